#include "apps/viewer/view_source.hpp"

#include <iostream>
#include <sstream>

#include "gpu/pass_timer.hpp"
#include "io/elevation_files.hpp"
#include "io/export_presets.hpp"
#include "io/noise_cache.hpp"
#include "io/weather_files.hpp"

namespace nephele::viewer {
namespace {

std::string cover_key(const cover::CoverParameters& p) {
  std::ostringstream key;
  key.precision(17);
  cover::visit_numeric_parameters(p, [&](const params::Parameter& parameter, auto value) {
    key << parameter.key << '=' << value << ' ';
  });
  key << cover::integrator_name(p.integrator);
  return key.str();
}

}  // namespace

GroundSource::GroundSource(const std::filesystem::path& cover_dir, const std::filesystem::path& cache_directory)
    : cache_directory_(cache_directory) {
  if (!cover_dir.empty()) {
    const io::CoverFaces faces = io::read_cover_faces(cover_dir);
    cover_ = {faces.size, faces.texels};
    cover_from_files_ = true;
  }
}

render::RenderResult GroundSource::render(const ViewState& state, int width, int height, int first_row,
                                          int row_count) {
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
      setup_ms.emplace_back("global_cover", gpu::time_pass([&] { cover_ = render::make_global_cover(parameters); }));
      cover_key_ = key;
    }
  }
  // The weather field is centred on the camera: prepared again for every render (a CPU
  // resampling of the cover or the stations, no GPU pass).
  render::PreparedScene prepared;
  setup_ms.emplace_back("weather_field", gpu::time_pass([&] { prepared = render::prepare_scene(scene, stations_, cover_); }));
  std::ostringstream terrain_key;
  terrain_key.precision(17);
  terrain_key << scene.terrain << ' ' << prepared.partial.camera.latitude_deg << ' ' << prepared.partial.camera.longitude_deg
              << ' ' << prepared.partial.camera.height_m;
  if (terrain_key.str() != terrain_key_) {
    std::string warning;
    setup_ms.emplace_back("terrain", gpu::time_pass([&] {
                            terrain_ = io::load_terrain(scene.terrain, prepared.partial.camera.latitude_deg,
                                                        prepared.partial.camera.longitude_deg,
                                                        prepared.partial.camera.height_m, &warning);
                          }));
    // Said once per place, not once per frame.
    if (!warning.empty()) std::cerr << "warning: " << warning << "\n";
    terrain_key_ = terrain_key.str();
  }
  prepared.terrain = terrain_;
  render::RenderSettings settings = render::render_settings(scene);
  settings.first_row = first_row;
  settings.row_count = row_count;
  if (render::needs_noise_volume(prepared.partial.layers, prepared.field) &&
      (!noise_ || noise_->seed() != settings.seed || noise_->size() != settings.noise_size))
    setup_ms.emplace_back("noise_volume", gpu::time_pass([&] {
                            noise_ = io::cached_noise_volume(settings.noise_size, settings.seed, cache_directory_);
                          }));
  render::SceneRender out = render::render_prepared(prepared, settings, noise_.get());
  out.render.timings_ms.insert(out.render.timings_ms.begin(), setup_ms.begin(), setup_ms.end());
  return out.render;
}

std::unique_ptr<ViewSource> make_view_source(const std::filesystem::path& cover_dir,
                                             const std::filesystem::path& cache_directory) {
  return std::make_unique<GroundSource>(cover_dir, cache_directory);
}

}  // namespace nephele::viewer
