#include "apps/cli/orbit_render.hpp"

#include <chrono>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <future>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include "core/file_names.hpp"
#include "apps/cli/commands.hpp"
#include "core/progress.hpp"
#include "core/time.hpp"
#include "cover/global_cover.hpp"
#include "gpu/egl_context.hpp"
#include "gpu/pass_timer.hpp"
#include "files/atomic_output.hpp"
#include "files/float_cache.hpp"
#include "files/image_files.hpp"
#include "io/cover_cache.hpp"
#include "io/elevation_files.hpp"
#include "io/planet_textures.hpp"
#include "io/render_files.hpp"
#include "io/surface_files.hpp"
#include "params/table.hpp"
#include "regional/scene.hpp"
#include "render/exposure.hpp"
#include "render/orbit_renderer.hpp"
#include "render/render_limits.hpp"
#include "render/scene_renderer.hpp"

namespace nephele::cli {

namespace s = params::scene;

void bind_orbit_options(Options& options, OrbitOptions& orbit) {
  orbit.lat = s::lat.default_number;
  orbit.lon = s::lon.default_number;
  orbit.altitude_km = s::altitude_km.default_number;
  orbit.planet_radius_km = s::planet_radius_km.default_number;
  orbit.cloud_base_km = s::cloud_base_km.default_number;
  orbit.cloud_thickness_km = s::cloud_thickness_km.default_number;
  orbit.cloud_detail = s::cloud_detail.default_number;
  orbit.cloud_tau_spread = s::cloud_tau_spread.default_number;
  options.bind(s::lat, &orbit.lat);
  options.bind(s::lon, &orbit.lon);
  options.bind(s::altitude_km, &orbit.altitude_km);
  options.bind(s::cover, &orbit.cover);
  options.bind(s::earth_texture, &orbit.earth_texture);
  options.bind(s::night_texture, &orbit.night_texture);
  options.bind(s::planet_radius_km, &orbit.planet_radius_km);
  options.bind(s::cloud_base_km, &orbit.cloud_base_km);
  options.bind(s::cloud_thickness_km, &orbit.cloud_thickness_km);
  options.bind(s::cloud_detail, &orbit.cloud_detail);
  options.bind(s::cloud_tau_spread, &orbit.cloud_tau_spread);
}

const std::vector<const params::Parameter*>& orbit_only_parameters() {
  static const std::vector<const params::Parameter*> list = {&s::lat,
                                                             &s::lon,
                                                             &s::altitude_km,
                                                             &s::cover,
                                                             &s::earth_texture,
                                                             &s::night_texture,
                                                             &s::planet_radius_km,
                                                             &s::cloud_base_km,
                                                             &s::cloud_thickness_km,
                                                             &s::cloud_detail,
                                                             &s::cloud_tau_spread};
  return list;
}

int run_orbit_render(const OrbitOptions& orbit) {
  // Everything is checked before the context is made: bad input exits 2 at once.
  if (!render::cloud_shell_fits(orbit.cloud_base_km * 1000.0, orbit.cloud_thickness_km * 1000.0)) {
    std::ostringstream top;
    top << orbit.cloud_base_km + orbit.cloud_thickness_km
        << " km; the cloud shell must end below the atmosphere's top at " << render::atmosphere_top_km() << " km";
    throw UsageError("--cloud-base-km + --cloud-thickness-km: " + top.str());
  }
  if (orbit.out.empty()) throw UsageError("--out: give an output file (.png or .exr)");
  const std::filesystem::path out(orbit.out);
  const std::string extension = core::lowercase_extension(out);
  if (extension != ".png" && extension != ".exr")
    throw UsageError("--out: '" + orbit.out + "' must end in .png or .exr");
  std::filesystem::path directory = out.parent_path();
  if (directory.empty()) directory = ".";
  if (std::filesystem::exists(directory) && !std::filesystem::is_directory(directory))
    throw UsageError("--out: '" + directory.string() + "' is not a directory");
  files::check_output_files(directory, {out.filename().string(), out.stem().string() + ".json"}, "--out");

  render::OrbitCamera camera;
  camera.latitude_deg = orbit.lat;
  camera.longitude_deg = orbit.lon;
  camera.altitude_m = orbit.altitude_km * 1000.0;
  camera.width = params::size_part(s::size.default_text, false);
  camera.height = params::size_part(s::size.default_text, true);
  if (!orbit.size.empty()) regional::parse_size(orbit.size, camera.width, camera.height, "--size");
  camera.heading_deg = orbit.heading.value_or(0.0);
  camera.pitch_deg = orbit.pitch.value_or(-90.0);
  const double radius_m = orbit.planet_radius_km * 1000.0;
  camera.fov_deg =
      orbit.fov ? *orbit.fov : render::framing_fov_deg(camera.altitude_m, radius_m, camera.width, camera.height);
  const std::string time_text = orbit.time.empty() ? std::string(s::time.default_text) : orbit.time;
  double unix_seconds = 0;
  try {
    unix_seconds = core::parse_utc_time(time_text);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--time: ") + e.what());
  }
  render::OrbitSettings settings;
  settings.planet_radius_m = radius_m;
  settings.cloud_base_m = orbit.cloud_base_km * 1000.0;
  settings.cloud_thickness_m = orbit.cloud_thickness_km * 1000.0;
  settings.cloud_detail = orbit.cloud_detail;
  settings.cloud_tau_spread = orbit.cloud_tau_spread;

  // Files named by options are read before the context: a missing one exits 2 quickly.
  std::optional<render::CoverCube> cover;
  if (!orbit.cover.empty()) {
    if (!std::filesystem::is_directory(orbit.cover))
      throw UsageError("--cover", orbit.cover, "a directory written by nephele generate", "is not a directory");
    cover = io::read_cover_cube(orbit.cover);
  }
  std::error_code no_file;
  // The planet's maps are decoded on threads of their own while the context is made and the
  // cover generated, which leave a core idle for much of their time (docs/orbit_view.md, "Cost").
  // A bad named map still exits 2 before any of it, by its header.
  io::check_planet_maps(orbit.earth_texture, orbit.night_texture);
  const std::filesystem::path cache_directory =
      orbit.no_cache ? std::filesystem::path() : files::default_cache_directory();
  std::future<io::PlanetTextures> planet_maps =
      std::async(std::launch::async, [&orbit, camera, radius_m, cache_directory] {
        io::PlanetTextures textures =
            io::read_planet_textures(orbit.earth_texture, orbit.night_texture, "--earth-texture", cache_directory);
        io::add_view_coast(textures, camera, radius_m, cache_directory);
        return textures;
      });

  // The default day map's water and relief and the generated cover's land/ocean mask (--surface
  // etopo5) all come from ETOPO5: held across both, the file is read once (io::whole_etopo5),
  // on a thread of its own while the maps are decoded and the context is made.
  const bool etopo5_needed = orbit.earth_texture.empty() && !cover && orbit.surface == "etopo5" &&
                             std::filesystem::is_regular_file(io::etopo5_default_path, no_file);
  std::future<std::shared_ptr<const regional::ElevationRaster>> etopo5_read = std::async(
      std::launch::async,
      [etopo5_needed] { return etopo5_needed ? io::whole_etopo5(io::etopo5_default_path, "--surface") : nullptr; });
  using Clock = std::chrono::steady_clock;
  const auto milliseconds_since = [](Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  };
  std::vector<std::pair<std::string, double>> timings;
  Clock::time_point start = Clock::now();
  gpu::EglContext context;
  timings.emplace_back("context", milliseconds_since(start));
  files::preload_image_codecs();  // for the PNG, on the core the render leaves free till then
  start = Clock::now();
  const std::shared_ptr<const regional::ElevationRaster> etopo5 = etopo5_read.get();
  timings.emplace_back("ETOPO5 (waited)", milliseconds_since(start));
  if (orbit.verbose) std::cerr << "renderer: " << context.info().renderer << "\n";
  render::check_render_fits(context, camera.width, camera.height, orbit.size.empty() ? "--size" : "--size");
  core::Progress progress("render", 3, core::Progress::for_stderr(orbit.quiet));
  std::string cover_source = orbit.cover;
  std::string cover_note;  // from the cache or made
  if (!cover) {
    progress.update(0, "global cover");
    std::string warning;
    const cover::CoverParameters parameters =
        render::view_cover_parameters(s::cover_size.default_int(), orbit.seed, orbit.flow, time_text,
                                      io::surface_from_option(orbit.surface, &warning));
    if (!warning.empty()) std::cerr << "warning: " << warning << "\n";
    timings.emplace_back("global cover", gpu::time_pass([&] {
                           render::GlobalCoverFaces faces =
                               io::cached_global_cover(parameters, cache_directory, &cover_note);
                           cover = render::CoverCube{faces.size, std::move(faces.texels),
                                                     std::move(faces.optical_thickness), std::move(faces.cloud_top)};
                         }));
    cover_source = "generated (seed " + std::to_string(orbit.seed) + ", " + std::to_string(parameters.size) +
                   " texels per face, flow " + orbit.flow + ", surface " +
                   (parameters.surface ? parameters.surface->source : std::string("none")) + ")";
  }
  start = Clock::now();
  const io::PlanetTextures textures = planet_maps.get();
  timings.emplace_back("maps (waited)", milliseconds_since(start));
  for (const auto& w : textures.warnings) std::cerr << "warning: " << w << "\n";
  progress.update(1, "orbit view");
  render::RenderResult result = render::render_orbit(camera, unix_seconds, textures.images, *cover, settings);
  progress.update(2, "writing files");
  io::OrbitRecord record;
  record.camera = camera;
  record.settings = settings;
  record.time = time_text;
  record.earth_texture = textures.day_source;
  record.night_texture = textures.night_source;
  record.water = textures.water_source;
  record.relief = textures.relief_source;
  record.cover = cover_source;
  record.exposure =
      orbit.exposure
          ? *orbit.exposure
          : render::highlight_exposure(result.radiance, orbit_default_exposure,
                                       render::sunlit_white_luminance(camera, unix_seconds, settings.planet_radius_m));
  record.metering = orbit.exposure ? "given" : "highlights";
  start = Clock::now();
  io::write_orbit_outputs(result, record, out);
  timings.emplace_back("files", milliseconds_since(start));
  progress.finish();
  if (orbit.verbose) {
    std::cerr << "earth texture: " << textures.day_source << "\nnight texture: " << textures.night_source
              << "\ncover: " << cover_source << "\n";
    if (!cover_note.empty()) std::cerr << cover_note << "\n";
    if (!textures.from_cache.empty()) {
      std::cerr << "maps from the cache:";
      for (const std::string& map : textures.from_cache) std::cerr << " " << map;
      std::cerr << "\n";
    }
    for (const auto& p : result.passes) std::cerr << "pass: " << p << "\n";
    for (const auto& [name, ms] : timings) std::cerr << "time " << name << ": " << ms << " ms\n";
    for (const auto& [name, ms] : result.timings_ms) std::cerr << "time " << name << ": " << ms << " ms\n";
  }
  std::cout << "wrote " << orbit.out << " (sun elevation " << result.sun_elevation_deg
            << " deg at the point below the camera)\n";
  return exit_ok;
}

int bench_orbit(const std::vector<std::string>& arguments) {
  int repeat = params::run::bench_render_repeat.default_int();
  Options options("bench orbit",
                  "Prints milliseconds per frame of the orbit view (render --view orbit's defaults) at\n"
                  "640x360 and 1280x720, with and without the sub-texel cloud (--cloud-detail 1 and 0):\n"
                  "the median of --repeat frames after one warm-up frame.",
                  params::bench_render);
  options.bind(params::run::bench_render_repeat, &repeat);
  if (!options.parse(arguments)) {
    std::cout << options.help();
    return exit_ok;
  }
  gpu::EglContext context;
  std::printf("device: %s (%s)\n", context.info().renderer.c_str(), context.info().version.c_str());
  io::PlanetTextures textures = io::read_planet_textures("");
  for (const auto& w : textures.warnings) std::cerr << "warning: " << w << "\n";
  const std::string time_text(s::time.default_text);
  std::string warning;
  const cover::CoverParameters parameters = render::view_cover_parameters(
      s::cover_size.default_int(), s::seed.default_uint32(), std::string(params::cover::flow.default_text), time_text,
      io::surface_from_option(std::string(params::cover::surface.default_text), &warning));
  if (!warning.empty()) std::cerr << "warning: " << warning << "\n";
  cover::GlobalCover generated(parameters);
  generated.run();
  render::OrbitRenderer renderer(
      textures.images, {parameters.size, generated.cover_field().read(), generated.optical_thickness_field().read(),
                        generated.cloud_top_field().read()});
  const double time = core::parse_utc_time(time_text);
  // The default, and the same without the sub-texel cloud (its cost).
  for (const auto& [width, height, detail] :
       {std::tuple{640, 360, 1.0}, std::tuple{1280, 720, 1.0}, std::tuple{640, 360, 0.0}, std::tuple{1280, 720, 0.0}}) {
    render::OrbitSettings settings = renderer.settings();
    settings.cloud_detail = detail;
    renderer.set_settings(settings);
    render::OrbitCamera camera;
    camera.latitude_deg = s::lat.default_number;
    camera.longitude_deg = s::lon.default_number;
    camera.altitude_m = s::altitude_km.default_number * 1000;
    camera.width = width;
    camera.height = height;
    camera.fov_deg = render::framing_fov_deg(camera.altitude_m, renderer.settings().planet_radius_m, width, height);
    renderer.render(camera, time);  // warm-up: compilation, first touch of the textures
    std::vector<double> ms;
    for (int k = 0; k < repeat; ++k) {
      const render::RenderResult r = renderer.render(camera, time);
      double total = 0;
      for (const auto& [name, t] : r.timings_ms) total += t;
      ms.push_back(total);
    }
    std::sort(ms.begin(), ms.end());
    std::printf("orbit %dx%d, cloud detail %g: %.1f ms per frame (median of %d)\n", width, height, detail,
                ms[ms.size() / 2], repeat);
    std::fflush(stdout);
  }
  return exit_ok;
}

}  // namespace nephele::cli
