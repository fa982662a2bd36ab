// nephele render: cloud layers seen from the ground, from weather files or the global cover.
#include <filesystem>
#include <iostream>
#include <algorithm>
#include <cstdio>
#include <sstream>

#include "apps/cli/commands.hpp"
#include "apps/cli/device_limits.hpp"
#include "apps/cli/options.hpp"
#include "gpu/egl_context.hpp"
#include "regional/scene.hpp"
#include "regional/weather.hpp"
#include "io/render_files.hpp"
#include "render/scene_renderer.hpp"

namespace nephele::cli {
namespace {

void parse_position(const std::string& text, regional::Scene& scene) {
  double lat = 0, lon = 0, height = 0;
  int consumed = 0;
  if (std::sscanf(text.c_str(), "%lf,%lf,%lf%n", &lat, &lon, &height, &consumed) != 3 ||
      consumed != static_cast<int>(text.size()))
    throw UsageError("--at: '" + text + "' is not LAT,LON,HEIGHT (degrees, degrees, metres)");
  scene.latitude_deg = lat;
  scene.longitude_deg = lon;
  scene.height_m = height;
  scene.view.clear();
}

}  // namespace

int run_render(const std::vector<std::string>& arguments) {
  regional::Scene scene;
  std::string view, at, size, time, scene_file, out;
  float heading = 1000, pitch = static_cast<float>(scene.pitch_deg), fov = static_cast<float>(scene.fov_deg);
  float exposure = static_cast<float>(scene.exposure);
  bool panorama = false, verbose = false;
  std::vector<std::string> weather;
  Options options("render",
                  "Renders the cloud layers, sky and ground from a viewpoint near the ground. Without\n"
                  "weather files the global cover is the weather. --out FILE.png is tone-mapped sRGB,\n"
                  "FILE.exr linear radiance; with --scene, --out is a directory for the scene's outputs.");
  options.add_string("--view", &view, "viewpoint: gurten (towards Solothurn) or bantiger (towards Fribourg)");
  options.add_string("--at", &at, "camera position LAT,LON,HEIGHT (WGS84 degrees, metres) instead of --view");
  options.add_float("--heading", &heading, -360, 360, "view heading, degrees clockwise from north (default: towards the view's city)");
  options.add_float("--pitch", &pitch, -90, 90, "view pitch, degrees above the horizon");
  options.add_float("--fov", &fov, 1, 179, "horizontal field of view, degrees");
  options.add_string("--time", &time, "date and time, ISO 8601 UTC (default " + scene.time + ")");
  options.add_string("--size", &size, "image size WIDTHxHEIGHT (default 1280x720; panorama 2048x1024)");
  options.add_flag("--panorama", &panorama, "render the full 360 x 180 view sphere (equirectangular)");
  options.add_string_list("--weather", &weather, "Open-Meteo or meteoblue JSON of a station");
  options.add_int("--view-steps", &scene.view_steps, 1, 4096, "samples per layer along each view ray");
  options.add_int("--light-steps", &scene.light_steps, 0, 256, "samples towards the sun per cloud sample");
  options.add_float("--exposure", &exposure, 1e-6, 1e6, "exposure before tone mapping (PNG)");
  options.add_uint32("--seed", &scene.seed, "seed of the global cover and the cloud noise");
  options.add_string("--scene", &scene_file, "scene file (JSON, see scenes/); flags override it");
  options.add_string("--out", &out, "output file (.png or .exr), or a directory with --scene");
  options.add_flag("--verbose", &verbose, "list the passes that ran and their times");
  if (!options.parse(arguments)) {
    std::cout << options.help();
    return exit_ok;
  }
  // The keys set by options: their errors name the option the user typed, not a scene key.
  regional::KeyOptions typed;
  try {
    if (!scene_file.empty()) scene = regional::read_scene_file(scene_file);
    if (!view.empty()) {
      scene.view = view;
      scene.latitude_deg.reset();
      typed["view"] = "--view";
    }
    if (!at.empty()) {
      parse_position(at, scene);
      typed["at"] = "--at";
    }
    if (heading != 1000) {
      scene.heading_deg = heading;
      typed["heading"] = "--heading";
    }
    if (arguments.end() != std::find(arguments.begin(), arguments.end(), "--pitch")) scene.pitch_deg = pitch;
    if (arguments.end() != std::find(arguments.begin(), arguments.end(), "--fov")) scene.fov_deg = fov;
    if (arguments.end() != std::find(arguments.begin(), arguments.end(), "--exposure")) scene.exposure = exposure;
    if (!time.empty()) {
      scene.time = time;
      typed["time"] = "--time";
    }
    if (panorama) {
      scene.panorama = true;
      if (size.empty()) {
        scene.width = 2048, scene.height = 1024;
        typed["size"] = "--panorama";
      }
    }
    if (!size.empty()) {
      regional::parse_size(size, scene.width, scene.height, "--size");
      typed["size"] = "--size";
    }
    if (!weather.empty()) {
      scene.weather = weather;
      typed["weather"] = "--weather";
    }
    regional::validate_scene(scene, scene_file.empty() ? "flags" : scene_file, typed);
  } catch (const regional::SceneError& e) {
    throw UsageError(e.what());
  }

  std::vector<std::string> outputs;
  if (!scene_file.empty() && (out.empty() || std::filesystem::is_directory(out) || std::filesystem::path(out).extension().empty())) {
    if (scene.outputs.empty()) throw UsageError(scene_file + ": 'outputs': give at least one file name, or --out FILE");
    const std::filesystem::path directory = out.empty() ? std::filesystem::path(".") : std::filesystem::path(out);
    for (const auto& name : scene.outputs) outputs.push_back((directory / name).string());
  } else {
    if (out.empty()) throw UsageError("--out: give an output file (.png or .exr)");
    const std::string extension = std::filesystem::path(out).extension().string();
    if (extension != ".png" && extension != ".exr")
      throw UsageError("--out: '" + out + "' must end in .png or .exr");
    outputs.push_back(out);
  }
  for (const auto& o : outputs) {
    const std::filesystem::path parent = std::filesystem::path(o).parent_path();
    if (!parent.empty() && std::filesystem::exists(parent) && !std::filesystem::is_directory(parent))
      throw UsageError("--out: '" + parent.string() + "' is not a directory");
  }

  gpu::EglContext context;
  if (verbose) std::cerr << "renderer: " << context.info().renderer << "\n";
  const std::string size_label = typed.count("size") ? typed.at("size")
                                 : scene_file.empty() ? std::string("--size")  // the default; --size changes it
                                                      : scene_file + ": 'size'";
  check_render_fits(context, scene.width, scene.height, size_label);
  render::SceneRender result;
  try {
    result = render::render_scene(scene);
  } catch (const regional::WeatherError& e) {
    throw UsageError(e.what());
  } catch (const regional::SceneError& e) {
    throw UsageError(e.what());
  }
  for (const auto& o : outputs) {
    const std::filesystem::path parent = std::filesystem::path(o).parent_path();
    if (!parent.empty()) std::filesystem::create_directories(parent);
  }
  io::write_scene_outputs(result, scene, outputs);
  if (result.render.loop_limited_pixels > 0 && context.info().renderer.find("llvmpipe") != std::string::npos)
    std::cerr << "warning: " << result.render.loop_limited_pixels
              << " pixels need 65535 or more shader loop iterations, where llvmpipe stops every loop; they are "
                 "cut short: lower --view-steps (now "
              << scene.view_steps << ") or --light-steps (now " << scene.light_steps << ")\n";
  if (verbose) {
    for (const auto& p : result.passes) std::cerr << "pass: " << p << "\n";
    for (const auto& [name, ms] : result.render.timings_ms) std::cerr << "time " << name << ": " << ms << " ms\n";
    for (const auto& l : result.layers)
      std::cerr << "layer " << regional::cloud_type_name(l.type) << " " << l.base_m << "-" << l.top_m << " m: " << l.reason << "\n";
  }
  std::cout << "wrote";
  for (const auto& o : outputs) std::cout << " " << o;
  std::cout << " (sun elevation " << result.render.sun_elevation_deg << " deg)\n";
  return exit_ok;
}

}  // namespace nephele::cli
