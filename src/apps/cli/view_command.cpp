// nephele view [COVER_DIR] [--scene FILE]: the window (src/apps/viewer, docs/viewer.md).
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <map>

#include "apps/cli/commands.hpp"
#include "apps/cli/options.hpp"
#include "apps/cli/scene_options.hpp"
#include "apps/viewer/viewer.hpp"
#include "cover/integrators.hpp"
#include "io/noise_cache.hpp"
#include "params/table.hpp"

namespace nephele::cli {

int run_view(const std::vector<std::string>& arguments) {
  namespace c = params::cover;
  std::string record, integrator(c::integrator.default_text);
  int cover_size = params::scene::cover_size.default_int(), iterations = c::iterations.default_int(), frames = 0;
  int month = c::month.default_int();
  float coverage = c::coverage.default_float(), step = c::step.default_float();
  bool no_cache = false;
  Options options("view [COVER_DIR]",
                  "Opens a window on the ground view of the clouds, with panels for the parameters below\n"
                  "(their ranges and help come from the same table). COVER_DIR: a cover written by\n"
                  "nephele generate; without it the cover is made from the cover parameters. Without a\n"
                  "display: xvfb-run -a nephele view ..., or render headless with nephele render.\n\n" +
                      std::string(viewer::key_help()),
                  params::viewer);
  const SceneOptions scene_options(options);
  options.bind(params::scene::cover_size, &cover_size);
  options.bind(c::coverage, &coverage);
  options.bind(c::month, &month);
  options.bind(c::iterations, &iterations);
  options.bind(c::step, &step);
  options.bind(c::integrator, &integrator);
  options.bind(params::run::view_record, &record);
  options.bind(params::run::view_frames, &frames);
  options.bind(params::run::no_cache, &no_cache);
  std::vector<std::string> rest = arguments;
  const std::string cover_dir = take_leading_operand(rest);
  if (!options.parse(rest)) {
    std::cout << options.help();
    return exit_ok;
  }
  regional::KeyOptions typed;
  regional::Scene scene = scene_options.scene(typed);
  const std::string& scene_file = scene_options.scene_file();
  if (options.given(params::scene::cover_size)) scene.cover_size = cover_size;
  regional::validate_scene(scene, scene_file.empty() ? "flags" : scene_file, typed);

  viewer::ViewerOptions view_options;
  view_options.scene = scene;
  view_options.cover_dir = cover_dir;
  view_options.record_dir = record;
  view_options.frames = frames;
  view_options.cache_directory = no_cache ? std::filesystem::path() : io::default_cache_directory();
  viewer::Viewer window(view_options);
  viewer::ViewState& state = window.state();
  state.coverage = coverage;
  state.month = month;
  state.iterations = iterations;
  state.step = step;
  state.integrator = integrator;
  window.run();
  return exit_ok;
}

}  // namespace nephele::cli

namespace nephele::cli {

int bench_view(const std::vector<std::string>& arguments) {
  std::string size(params::run::bench_view_size.default_text);
  int repeat = params::run::bench_view_repeat.default_int();
  Options options("bench view",
                  "Prints the milliseconds of each pass of nephele view's frames for the default scene:\n"
                  "the first frame after a change (the preview) and the refinement frames after it, the\n"
                  "median over --repeat changes of the heading. Needs a display (xvfb-run -a).",
                  params::bench_view);
  options.bind(params::run::bench_view_size, &size);
  options.bind(params::run::bench_view_repeat, &repeat);
  if (!options.parse(arguments)) {
    std::cout << options.help();
    return exit_ok;
  }
  viewer::ViewerOptions view_options;
  regional::parse_size(size, view_options.scene.width, view_options.scene.height, "--size");
  regional::validate_scene(view_options.scene, "--size");
  view_options.cache_directory = io::default_cache_directory();
  viewer::Viewer window(view_options);
  std::printf("device: %s (%s)\n", window.window().info().renderer.c_str(), window.window().info().version.c_str());
  const regional::Scene& scene = view_options.scene;
  std::printf("scene: %s, %s, window %dx%d, %d view x %d light steps\n", scene.view.c_str(), scene.time.c_str(),
              scene.width, scene.height, scene.view_steps, scene.light_steps);
  // The first change also makes the cover and the noise volume: refined once before timing.
  while (!window.refined()) window.frame();
  const std::size_t levels = viewer::refinement_levels().size();
  // Per refinement level: the passes' times and the frame's, over the changes.
  std::vector<std::map<std::string, std::vector<double>>> times(levels);
  std::vector<std::string> order;
  for (int r = 0; r < repeat; ++r) {
    window.state().camera.heading_deg += 1.0;
    for (std::size_t level = 0; level < levels; ++level) {
      window.frame();
      for (const auto& [name, ms] : window.last_render().timings_ms) {
        times[level][name].push_back(ms);
        if (std::find(order.begin(), order.end(), name) == order.end()) order.push_back(name);
      }
      times[level]["frame"].push_back(window.frame_ms());
    }
  }
  order.push_back("frame");
  std::printf("milliseconds per pass, median of %d changes\n%-16s", repeat, "pass");
  for (std::size_t level = 0; level < levels; ++level) {
    const viewer::RefinementLevel l = viewer::refinement_levels()[level];
    const int d = l.divisor;
    std::string label = std::to_string((scene.width + d - 1) / d) + "x" + std::to_string((scene.height + d - 1) / d);
    if (l.bands > 1) label = "band " + std::to_string(l.band + 1) + "/" + std::to_string(l.bands);
    std::printf(" %11s", label.c_str());
  }
  std::printf("\n");
  for (const std::string& name : order) {
    std::printf("%-16s", name.c_str());
    for (std::size_t level = 0; level < levels; ++level) {
      auto values = times[level][name];
      if (values.empty()) {
        std::printf(" %11s", "-");
        continue;
      }
      std::sort(values.begin(), values.end());
      std::printf(" %11.1f", values[values.size() / 2]);
    }
    std::printf("\n");
  }
  return exit_ok;
}

}  // namespace nephele::cli
