#include "apps/viewer/view_source.hpp"

#include <algorithm>
#include <iostream>
#include <sstream>

#include "apps/viewer/modeller.hpp"
#include "gpu/pass_timer.hpp"
#include "io/elevation_files.hpp"
#include "io/export_presets.hpp"
#include "io/cover_cache.hpp"
#include "io/noise_cache.hpp"
#include "io/planet_textures.hpp"
#include "core/time.hpp"
#include "io/weather_files.hpp"

namespace nephele::viewer {
namespace {

std::string cover_key(const cover::CoverParameters& p) {
  std::ostringstream key;
  key.precision(17);
  cover::visit_numeric_parameters(
      p, [&](const params::Parameter& parameter, auto value) { key << parameter.key << '=' << value << ' '; });
  key << cover::integrator_name(p.integrator) << ' ' << cover::flow_name(p.flow) << ' '
      << (p.surface ? p.surface->source : std::string("none"));
  // The steady cover is the same at every time: moving the sun does not make it again.
  if (p.flow == cover::Flow::moving) key << ' ' << p.time;
  return key.str();
}

}  // namespace

GroundSource::GroundSource(const std::filesystem::path& cover_dir, const std::filesystem::path& cache_directory)
    : cache_directory_(cache_directory) {
  if (!cover_dir.empty()) {
    io::CoverFaces faces = io::read_cover_faces(cover_dir);
    cover_ = {faces.size, std::move(faces.texels), std::move(faces.optical_thickness), std::move(faces.cloud_top)};
    cover_from_files_ = true;
  }
}

render::RenderResult GroundSource::render(const ViewState& state, int width, int height, int first_row, int row_count,
                                          bool coarse) {
  const regional::Scene scene = scene_of(state, width, height);
  std::vector<std::pair<std::string, double>> setup_ms;
  if (state.weather != station_files_) {
    stations_ = io::read_scene_weather(scene);
    station_files_ = state.weather;
  }
  if (stations_.empty() && !cover_from_files_) {
    const cover::CoverParameters parameters = cover_of(state);
    const std::string key = cover_key(parameters);
    if (key != cover_key_) {
      setup_ms.emplace_back("global_cover",
                            gpu::time_pass([&] { cover_ = io::cached_global_cover(parameters, cache_directory_); }));
      cover_key_ = key;
    }
  }
  // The weather field is centred on the camera: prepared again for every render (a CPU
  // resampling of the cover or the stations, no GPU pass).
  render::PreparedScene prepared;
  setup_ms.emplace_back("weather_field",
                        gpu::time_pass([&] { prepared = render::prepare_scene(scene, stations_, cover_); }));
  std::ostringstream terrain_key;
  terrain_key.precision(17);
  // Not the height: the ground is the same at any height (io::load_terrain), and climbing
  // does not make it again.
  terrain_key << scene.terrain << ' ' << scene.land_cover << ' ' << scene.terrain_detail << ' '
              << prepared.partial.camera.latitude_deg << ' ' << prepared.partial.camera.longitude_deg;
  if (terrain_key.str() != terrain_key_) {
    std::string warning;
    setup_ms.emplace_back("terrain", gpu::time_pass([&] {
                            terrain_ = io::load_terrain(scene.terrain, prepared.partial.camera.latitude_deg,
                                                        prepared.partial.camera.longitude_deg,
                                                        prepared.partial.camera.height_m, &warning, "--terrain",
                                                        {scene.land_cover, "--land-cover", scene.terrain_detail});
                          }));
    // Said once per place, not once per frame.
    if (!warning.empty()) std::cerr << "warning: " << warning << "\n";
    terrain_key_ = terrain_key.str();
  }
  prepared.terrain = terrain_;
  render::RenderSettings settings = render::render_settings(scene);
  settings.first_row = first_row;
  settings.row_count = row_count;
  if (coarse) {
    settings.view_steps = std::min(settings.view_steps, preview_steps.view);
    settings.light_steps = std::min(settings.light_steps, preview_steps.light);
  }
  settings.shadow_cache = shadow_maps_;  // the bands of a frame share its maps
  if (row_count == 0 && settings.resolution_divisor == 1) {
    settings.march_stride = march_stride_;
    settings.march_phase = march_phase_;
  }
  if (render::needs_noise_volume(prepared.partial.layers, prepared.field) &&
      (!noise_ || noise_->seed() != settings.seed || noise_->size() != settings.noise_size))
    setup_ms.emplace_back("noise_volume", gpu::time_pass([&] {
                            noise_ = io::cached_noise_volume(settings.noise_size, settings.seed, cache_directory_);
                          }));
  render::SceneRender out = render::render_prepared(prepared, settings, noise_.get());
  out.render.timings_ms.insert(out.render.timings_ms.begin(), setup_ms.begin(), setup_ms.end());
  return out.render;
}

OrbitSource::OrbitSource(const std::filesystem::path& cover_dir, const std::filesystem::path& cache_directory)
    : cover_dir_(cover_dir), cache_directory_(cache_directory) {}
OrbitSource::~OrbitSource() = default;

render::RenderResult OrbitSource::render(const ViewState& state, int width, int height, int first_row, int row_count,
                                         bool) {
  std::vector<std::pair<std::string, double>> setup_ms;
  // The cover: the files once, or made again when the panels change its parameters.
  const std::string key = cover_dir_.empty() ? cover_key(cover_of(state)) : cover_dir_.string();
  if (!renderer_ || key != cover_key_) {
    render::CoverCube cube;
    setup_ms.emplace_back("global_cover", gpu::time_pass([&] {
                            if (!cover_dir_.empty()) {
                              cube = io::read_cover_cube(cover_dir_);
                            } else {
                              render::GlobalCoverFaces faces =
                                  io::cached_global_cover(cover_of(state), cache_directory_);
                              cube = {faces.size, std::move(faces.texels), std::move(faces.optical_thickness),
                                      std::move(faces.cloud_top)};
                            }
                          }));
    if (renderer_) {
      renderer_->set_cover(cube);
    } else {
      const io::PlanetTextures textures = io::read_planet_textures("", "", "--earth-texture", cache_directory_);
      for (const auto& warning : textures.warnings) std::cerr << "warning: " << warning << "\n";
      setup_ms.emplace_back("planet_textures", gpu::time_pass([&] {
                              renderer_ = std::make_unique<render::OrbitRenderer>(textures.images, cube);
                            }));
      sea_colour_ = textures.images.sea_colour;
      if (sea_colour_)
        if (const std::optional<std::string> warning = io::missing_shorelines_warning()) {
          std::cerr << "warning: " << *warning << "\n";
          sea_colour_ = false;
        }
      water_width_ = textures.images.water.width;
    }
    cover_key_ = key;
  }
  // Position, heading, pitch and fov through the table; the orbit view's range starts at 1 m
  // above its sphere.
  render::OrbitCamera camera;
  render::Camera view = state.camera;
  params::copy_bound_fields(render::field_bindings(view), render::field_bindings(camera));
  camera.altitude_m = std::clamp(state.camera.height_m, 1.0, params::scene::altitude_km.max * 1000.0);
  camera.width = width;
  camera.height = height;
  update_coast(camera, setup_ms);
  render::RenderResult result = renderer_->render(camera, core::parse_utc_time(state.time), first_row, row_count);
  result.timings_ms.insert(result.timings_ms.begin(), setup_ms.begin(), setup_ms.end());
  return result;
}

namespace {

// Whether `have` holds all of `want` (longitudes compared a turn either way) with texels at most
// twice as coarse.
bool window_serves(const io::GeoWindow& have, const io::GeoWindow& want) {
  if (want.south_deg < have.south_deg || want.north_deg > have.north_deg) return false;
  bool inside = false;
  for (double turn : {-360.0, 0.0, 360.0})
    inside = inside || (want.west_deg + turn >= have.west_deg && want.east_deg + turn <= have.east_deg);
  const double have_texel = (have.north_deg - have.south_deg) / have.height;
  const double want_texel = (want.north_deg - want.south_deg) / want.height;
  return inside && have_texel <= 2.0 * want_texel;
}

}  // namespace

void OrbitSource::update_coast(const render::OrbitCamera& camera,
                               std::vector<std::pair<std::string, double>>& setup_ms) {
  if (!sea_colour_) return;
  const std::optional<io::GeoWindow> wanted =
      io::view_coast_window(camera, renderer_->settings().planet_radius_m, water_width_);
  if (!wanted) {
    // High up the water map serves; a window kept from below would only cost its reads. Kept
    // while the nearest pixels are finer than the water map's whole texel, so that the quarter-size
    // preview of a view that wants a window does not drop it and make it again for the full size.
    if (coast_window_ && !io::coast_pixels_finer(camera, renderer_->settings().planet_radius_m, water_width_, 1.0)) {
      renderer_->set_coast({}, 0.0, 0.0, 0.0, 0.0);
      coast_window_.reset();
    }
    return;
  }
  if (coast_window_ && window_serves(*coast_window_, *wanted)) return;
  // A margin of a quarter of the window's size each way, so that a moving camera keeps it a while,
  // and texels twice as fine as this frame wants (within the 2048 a side), so that the window the
  // half-size preview makes serves the full size that follows it.
  io::GeoWindow finer = *wanted;
  finer.width *= 2, finer.height *= 2;
  const io::GeoWindow window = io::widened_coast_window(finer, 0.25);
  try {
    setup_ms.emplace_back(
        "coast_window", gpu::time_pass([&] {
          const core::ImageData water = io::read_gshhg_water(io::gshhg_shorelines_default_path, window);
          renderer_->set_coast(water, window.south_deg, window.north_deg, window.west_deg, window.east_deg);
        }));
    coast_window_ = window;
  } catch (const std::exception& e) {
    // A damaged shorelines file: the water map alone from now on, as without the file.
    std::cerr << "warning: " << e.what() << ": coasts and lakes as sharp as ETOPO5's water map\n";
    sea_colour_ = false;
  }
}

ViewSwitch::ViewSwitch(const std::filesystem::path& cover_dir, const std::filesystem::path& cache_directory)
    : ground_(cover_dir, cache_directory), orbit_(cover_dir, cache_directory) {}

render::RenderResult ViewSwitch::render(const ViewState& state, int width, int height, int first_row, int row_count,
                                        bool coarse) {
  const double share = orbit_share(state);
  if (share >= 1.0) return orbit_.render(state, width, height, first_row, row_count, coarse);
  render::RenderResult ground = ground_.render(state, width, height, first_row, row_count, coarse);
  if (share <= 0.0) return ground;
  // The fade band: both renderers, their linear radiance (and opacity) mixed by the share.
  const render::RenderResult orbit = orbit_.render(state, width, height, first_row, row_count, coarse);
  const int first = row_count > 0 ? first_row : 0, rows = row_count > 0 ? row_count : height;
  const std::size_t row_floats = static_cast<std::size_t>(width) * 4;
  for (std::size_t k = first * row_floats; k < (first + rows) * row_floats; ++k)
    ground.radiance.pixels[k] =
        static_cast<float>((1.0 - share) * ground.radiance.pixels[k] + share * orbit.radiance.pixels[k]);
  for (const std::string& pass : orbit.passes) ground.passes.push_back("orbit " + pass);
  for (const auto& [pass, ms] : orbit.timings_ms) ground.timings_ms.emplace_back("orbit " + pass, ms);
  return ground;
}

ModelSource::ModelSource(int size) : size_(size) {}
ModelSource::~ModelSource() = default;

render::RenderResult ModelSource::render(const ViewState& state, int width, int height, int first_row, int row_count,
                                         bool /*coarse*/) {
  render::RenderResult result;
  if (!volume_) {
    volume_ = std::make_unique<model::DensityVolume>(size_);
    preview_ = std::make_unique<render::PreviewRenderer>();
  }
  // What differs from the volume's model: nothing, one primitive (the edit), or more.
  const model::CloudModel& shown = volume_->model();
  const model::CloudModel& wanted = state.model;
  int changed = -1, count = 0;
  const bool same_frame = !shown.primitives.empty() && model::same_but_primitives(shown, wanted);
  if (same_frame)
    for (std::size_t i = 0; i < wanted.primitives.size(); ++i)
      if (shown.primitives[i] != wanted.primitives[i]) {
        changed = int(i);
        ++count;
      }
  if (!same_frame || count > 1) {
    volume_->compute(wanted);
    result.timings_ms.emplace_back("volume", volume_->stats().ms);
  } else if (count == 1) {
    volume_->edit(changed, wanted.primitives[std::size_t(changed)]);
    result.timings_ms.emplace_back("volume_edit", volume_->stats().ms);
  }
  render::PreviewSettings settings = preview_settings(state, width, height);
  settings.first_row = first_row;
  settings.row_count = row_count;
  result.timings_ms.emplace_back("preview",
                                 gpu::time_pass([&] { result.radiance = preview_->render(*volume_, settings); }));
  result.passes = {"model_preview"};
  return result;
}

std::unique_ptr<ViewSource> make_view_source(const std::filesystem::path& cover_dir,
                                             const std::filesystem::path& cache_directory) {
  return std::make_unique<ViewSwitch>(cover_dir, cache_directory);
}

}  // namespace nephele::viewer
