// nephele render: cloud layers seen from the ground, from weather files or the global cover.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <algorithm>
#include <sstream>

#include "core/file_names.hpp"
#include "apps/cli/commands.hpp"
#include "io/elevation_files.hpp"
#include "files/float_cache.hpp"
#include "io/cover_cache.hpp"
#include "io/noise_cache.hpp"
#include "render/cloud_renderer.hpp"
#include "cover/cover_limits.hpp"
#include "render/render_limits.hpp"
#include "apps/cli/options.hpp"
#include "apps/cli/scene_options.hpp"
#include "core/number_text.hpp"
#include "core/progress.hpp"
#include "params/table.hpp"
#include "params/values.hpp"
#include "gpu/egl_context.hpp"
#include "regional/scene.hpp"
#include "regional/weather.hpp"
#include "io/render_files.hpp"
#include "io/scene_files.hpp"
#include "io/surface_files.hpp"
#include "io/weather_files.hpp"
#include "render/scene_renderer.hpp"
#include "apps/cli/orbit_render.hpp"

namespace nephele::cli {
namespace {

// LAT,LON,HEIGHT, each a strict decimal; their ranges are checked with the scene's.
void parse_position(const std::string& text, regional::Scene& scene) {
  const std::string form = "LAT,LON,HEIGHT (degrees, degrees, metres)";
  const auto first = text.find(','), second = first == std::string::npos ? first : text.find(',', first + 1);
  if (second == std::string::npos || text.find(',', second + 1) != std::string::npos)
    throw UsageError("--at", text, form, "is not three numbers");
  auto number = [&](const std::string& part, const char* name) {
    const auto value = core::parse_decimal(part, core::NumberForm::real);
    if (!value) throw UsageError(std::string("--at (") + name + ")", part, form, params::number_problem(part, false));
    if (!std::isfinite(*value)) throw UsageError(std::string("--at (") + name + ")", part, form, "is out of range");
    return *value;
  };
  scene.latitude_deg = number(text.substr(0, first), "latitude");
  scene.longitude_deg = number(text.substr(first + 1, second - first - 1), "longitude");
  scene.height_m = number(text.substr(second + 1), "height");
  scene.view.clear();
}

}  // namespace

int run_render(const std::vector<std::string>& arguments) {
  std::string at, out;
  bool panorama = false, verbose = false, quiet = false, no_cache = false;
  std::vector<std::string> weather;
  Options options("render",
                  "Renders the cloud layers, sky and ground from a viewpoint near the ground. Without\n"
                  "weather files the global cover is the weather. --out FILE.png is tone-mapped sRGB,\n"
                  "FILE.exr linear radiance; with --scene, --out is a directory for the scene's outputs.",
                  params::render);
  namespace s = params::scene;
  const SceneOptions scene_options(options);
  options.bind(s::at, &at);
  options.bind(s::panorama, &panorama);
  options.bind(s::weather, &weather);
  int frames = regional::Scene{}.frames;  // render's own: the viewer accumulates by reprojection
  options.bind(s::frames, &frames);
  int divisor = regional::Scene{}.resolution_divisor;  // render's own: the viewer refines in bands
  options.bind(s::resolution_divisor, &divisor);
  std::string terrain;
  options.bind(s::terrain, &terrain);
  std::string land_cover;
  options.bind(s::land_cover, &land_cover);
  double terrain_detail = regional::Scene{}.terrain_detail;
  options.bind(s::terrain_detail, &terrain_detail);
  double fog_top = regional::Scene{}.fog_top_m;
  options.bind(s::fog_top, &fog_top);
  double powder = regional::Scene{}.powder;
  options.bind(s::powder, &powder);
  options.bind(s::out, &out);
  options.bind(params::run::quiet, &quiet);
  options.bind(params::run::no_cache, &no_cache);
  options.bind(params::run::verbose, &verbose);
  OrbitOptions orbit;
  bind_orbit_options(options, orbit);
  if (!options.parse(arguments)) {
    std::cout << options.help();
    return exit_ok;
  }
  if (scene_options.view() == "orbit") {
    orbit.time = scene_options.time();
    orbit.size = scene_options.size();
    orbit.out = out;
    orbit.seed = scene_options.seed();
    if (!scene_options.flow().empty()) {
      if (!orbit.cover.empty())
        throw UsageError("--flow: the flow of a generated cover; --cover " + orbit.cover + " gives the cover");
      orbit.flow = scene_options.flow();
    }
    if (!scene_options.surface().empty()) {
      if (!orbit.cover.empty())
        throw UsageError("--surface: the land/ocean mask of a generated cover; --cover " + orbit.cover +
                         " gives the cover");
      orbit.surface = scene_options.surface();
    }
    // Without --exposure the frame is metered for its highlights (render::highlight_exposure).
    if (options.given(s::exposure)) orbit.exposure = scene_options.exposure();
    orbit.verbose = verbose;
    orbit.quiet = quiet;
    orbit.no_cache = no_cache;
    if (options.given(s::heading)) orbit.heading = scene_options.heading();
    if (options.given(s::pitch)) orbit.pitch = scene_options.pitch();
    if (options.given(s::fov)) orbit.fov = scene_options.fov();
    for (const auto* ground_only :
         {&s::at, &s::scene_path, &s::panorama, &s::weather, &s::terrain, &s::land_cover, &s::terrain_detail,
          &s::fog_top, &s::powder, &s::quality, &s::view_steps, &s::light_steps, &s::frames, &s::resolution_divisor})
      if (options.given(*ground_only))
        throw UsageError(ground_only->option() + ": not taken by --view orbit (it belongs to the ground views)");
    return run_orbit_render(orbit);
  }
  for (const auto* orbit_only : orbit_only_parameters())
    if (options.given(*orbit_only)) throw UsageError(orbit_only->option() + ": only taken with --view orbit");
  // The keys set by options: their errors name the option the user typed, not a scene key.
  regional::KeyOptions typed;
  regional::Scene scene = scene_options.scene(typed);
  const std::string& scene_file = scene_options.scene_file();
  if (!at.empty()) {
    parse_position(at, scene);
    typed["at"] = "--at";
  }
  if (options.given(s::frames)) regional::give_step(scene, s::frames, frames);
  if (options.given(s::resolution_divisor)) {
    regional::give_step(scene, s::resolution_divisor, divisor);
    typed["resolution_divisor"] = "--resolution-divisor";
  }
  if (options.given(s::terrain)) scene.terrain = terrain;
  if (options.given(s::land_cover)) scene.land_cover = land_cover;
  if (options.given(s::terrain_detail)) {
    scene.terrain_detail = terrain_detail;
    typed["terrain_detail"] = "--terrain-detail";
  }
  if (options.given(s::fog_top)) {
    scene.fog_top_m = fog_top;
    typed["fog_top"] = "--fog-top";
  }
  if (options.given(s::powder)) {
    scene.powder = powder;
    typed["powder"] = "--powder";
  }
  if (panorama) {
    if (!scene_options.size_given()) typed["size"] = "--panorama";
    regional::make_panorama(scene, scene_options.size_given());
  }
  if (!weather.empty()) {
    scene.weather = weather;
    typed["weather"] = "--weather";
  }
  regional::apply_render_quality(scene, scene_file.empty() ? "flags" : scene_file, typed);
  regional::validate_scene(scene, scene_file.empty() ? "flags" : scene_file, typed);

  // The outputs are names inside `directory`; with --scene and --out DIR the set owns DIR, else
  // it is only its own files in a directory shared with others.
  std::vector<std::string> outputs, shown;
  std::string outputs_field = "--out";  // where the names come from, for errors
  std::filesystem::path directory;
  files::OutputSet::Scope scope = files::OutputSet::Scope::files;
  if (!scene_file.empty() &&
      (out.empty() || std::filesystem::is_directory(out) || std::filesystem::path(out).extension().empty())) {
    if (scene.outputs.empty()) throw UsageError(scene_file + ": 'outputs': give at least one file name, or --out FILE");
    directory = out.empty() ? std::filesystem::path(".") : std::filesystem::path(out);
    if (!out.empty()) {
      scope = files::OutputSet::Scope::directory;
      files::check_output_directory(directory, "--out");
    }
    outputs = scene.outputs;
    outputs_field = scene_file + ": 'outputs'";
    for (const auto& name : outputs) shown.push_back((directory / name).string());
  } else {
    if (out.empty()) throw UsageError("--out: give an output file (.png or .exr)");
    const std::string extension = core::lowercase_extension(out);
    if (extension != ".png" && extension != ".exr") throw UsageError("--out: '" + out + "' must end in .png or .exr");
    directory = std::filesystem::path(out).parent_path();
    if (directory.empty()) directory = ".";
    outputs.push_back(std::filesystem::path(out).filename().string());
    shown.push_back(out);
  }
  for (const auto& o : outputs) {
    const std::filesystem::path parent = (directory / o).parent_path();
    if (!parent.empty() && std::filesystem::exists(parent) && !std::filesystem::is_directory(parent))
      throw UsageError("--out: '" + parent.string() + "' is not a directory");
  }
  // Checked before any work: a reserved name, or a directory where an output or the sidecar goes.
  std::vector<std::string> written = outputs;
  const std::filesystem::path first(outputs.front());
  written.push_back((first.parent_path() / (first.stem().string() + ".json")).string());
  files::check_output_files(directory, written, outputs_field);

  gpu::EglContext context;
  if (verbose) std::cerr << "renderer: " << context.info().renderer << "\n";
  const std::string size_label = typed.count("size")  ? typed.at("size")
                                 : scene_file.empty() ? std::string("--size")  // the default; --size changes it
                                                      : scene_file + ": 'size'";
  render::check_render_fits(context, scene.width, scene.height, size_label);
  // Weather (with the global cover when no files are given), the march, the files.
  core::Progress progress("render", 3, core::Progress::for_stderr(quiet));
  progress.update(0, "weather");
  std::string surface_warning;
  const auto surface = io::scene_surface(
      scene, &surface_warning, typed.count("surface") || scene_file.empty() ? "--surface" : scene_file + ": 'surface'");
  if (!surface_warning.empty()) {
    std::cerr << "warning: " << surface_warning << "\n";
    scene.cover_surface = "none";  // the render's sidecar records the cover it made
  }
  // Without weather files the global cover is the weather, from the disk cache where it is there.
  const std::filesystem::path cache_directory = no_cache ? std::filesystem::path() : files::default_cache_directory();
  const std::vector<regional::WeatherSeries> weather_series = io::read_scene_weather(scene);
  std::string cover_note;
  render::PreparedScene prepared =
      weather_series.empty()
          ? render::prepare_scene(
                scene, weather_series,
                io::cached_global_cover(render::scene_cover_parameters(scene, surface), cache_directory, &cover_note))
          : render::prepare_scene(scene, weather_series, surface);
  std::string terrain_warning;
  const std::string terrain_field =
      options.given(s::terrain) || scene_file.empty() ? s::terrain.option() : scene_file + ": 'terrain'";
  const render::Camera& camera = prepared.partial.camera;
  const std::string land_field =
      options.given(s::land_cover) || scene_file.empty() ? s::land_cover.option() : scene_file + ": 'land_cover'";
  prepared.terrain =
      io::load_terrain(scene.terrain, camera.latitude_deg, camera.longitude_deg, camera.height_m, &terrain_warning,
                       terrain_field, {scene.land_cover, land_field, scene.terrain_detail});
  if (!terrain_warning.empty()) std::cerr << "warning: " << terrain_warning << "\n";
  progress.update(1, "clouds");
  // The noise volume from the disk cache when a layer is marched (the same bits as making it).
  std::unique_ptr<render::NoiseVolume> noise;
  std::string noise_note;
  if (!cache_directory.empty() && render::needs_noise_volume(prepared.partial.layers, prepared.field)) {
    const render::RenderSettings settings = render::render_settings(scene);
    noise = io::cached_noise_volume(settings.noise_size, settings.seed, cache_directory, &noise_note);
  }
  const render::SceneRender result = render::render_prepared(prepared, scene, noise.get());
  progress.update(2, "writing files");
  io::write_scene_outputs(result, scene, directory, outputs, scope);
  progress.finish();
  if (result.render.loop_limited_pixels > 0 && context.info().renderer.find("llvmpipe") != std::string::npos)
    std::cerr << "warning: " << result.render.loop_limited_pixels
              << " pixels need 65535 or more shader loop iterations, where llvmpipe stops every loop; they are "
                 "cut short: lower --view-steps (now "
              << scene.view_steps << ") or --light-steps (now " << scene.light_steps << ")\n";
  if (verbose) {
    if (!cover_note.empty()) std::cerr << cover_note << "\n";
    if (!noise_note.empty()) std::cerr << noise_note << "\n";
    for (const auto& p : result.passes) std::cerr << "pass: " << p << "\n";
    for (const auto& [name, ms] : result.render.timings_ms) std::cerr << "time " << name << ": " << ms << " ms\n";
    for (const auto& l : result.layers)
      std::cerr << "layer " << regional::cloud_type_name(l.type) << " " << l.base_m << "-" << l.top_m
                << " m: " << l.reason << "\n";
  }
  std::cout << "wrote";
  for (const auto& o : shown) std::cout << " " << o;
  std::cout << " (sun elevation " << result.render.sun_elevation_deg << " deg)\n";
  return exit_ok;
}

}  // namespace nephele::cli
