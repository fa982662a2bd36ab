// nephele view [COVER_DIR] [--scene FILE]: the window (src/apps/viewer, docs/viewer.md).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>

#include "apps/cli/commands.hpp"
#include "apps/cli/options.hpp"
#include "apps/cli/scene_options.hpp"
#include "apps/viewer/viewer.hpp"
#include "cover/integrators.hpp"
#include "io/cloud_model_files.hpp"
#include "files/float_cache.hpp"
#include "io/noise_cache.hpp"
#include "io/surface_files.hpp"
#include "model/bricks.hpp"
#include "params/table.hpp"

namespace nephele::cli {
namespace {

// The scene's checks, where the viewpoint may also be `orbit`: the viewer's own (the orbit
// renderer above render --view orbit's default point, src/apps/viewer/view_state.cpp), which
// the regional scenes do not know.
void validate_view_scene(const regional::Scene& scene, const std::string& source, const regional::KeyOptions& typed) {
  regional::Scene checked = scene;
  if (checked.view == "orbit") checked.view = params::scene::view.default_text;
  regional::validate_scene(checked, source, typed);
}

// --model FILE|EXAMPLE: a built-in example when no file of that name exists (saved as
// EXAMPLE.cloud.json in the working directory), else the model file (saved over itself).
void load_view_model(const std::string& name, viewer::ViewerOptions& options) {
  const auto& examples = model::example_names();
  const bool example = std::find(examples.begin(), examples.end(), name) != examples.end();
  if (example && !std::filesystem::exists(name)) {
    options.model = model::example(name);
    options.model_file = name + ".cloud.json";
  } else {
    options.model = io::read_cloud_model(name, "--model");
    options.model_file = name;
  }
}

}  // namespace

int run_view(const std::vector<std::string>& arguments) {
  namespace c = params::cover;
  std::string record, integrator(c::integrator.default_text);
  int cover_size = params::scene::cover_size.default_int(), iterations = c::iterations.default_int(), frames = 0;
  int month = c::month.default_int();
  float coverage = c::coverage.default_float(), step = c::step.default_float();
  bool no_cache = false;
  double time_step = params::run::time_step.default_number;
  std::string model_name;
  int model_size = params::cloud_model::view_model_size.default_int();
  Options options("view [COVER_DIR]",
                  "Opens a window on the ground view of the clouds, with panels for the parameters below\n"
                  "(their ranges and help come from the same table). COVER_DIR: a cover written by\n"
                  "nephele generate; without it the cover is made from the cover parameters. With --model,\n"
                  "the modeller: a cloud model's volume and preview, its primitives selected, dragged,\n"
                  "resized and edited in the panels, the volume and the image updated as they change\n"
                  "(docs/viewer.md). Without a display: xvfb-run -a nephele view ..., or render headless\n"
                  "with nephele render.\n\n" +
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
  options.bind(params::run::time_step, &time_step);
  options.bind(params::run::no_cache, &no_cache);
  options.bind(params::cloud_model::view_model, &model_name);
  options.bind(params::cloud_model::view_model_size, &model_size);
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
  validate_view_scene(scene, scene_file.empty() ? "flags" : scene_file, typed);
  if (cover_dir.empty()) {
    // The land/ocean mask read (and checked) once here; the viewer's covers take it from
    // io::surface_from_option's store.
    std::string warning;
    io::scene_surface(scene, &warning,
                      typed.count("surface") || scene_file.empty() ? "--surface" : scene_file + ": 'surface'");
    if (!warning.empty()) {
      std::cerr << "warning: " << warning << "\n";
      scene.cover_surface = "none";
    }
  }

  viewer::ViewerOptions view_options;
  view_options.scene = scene;
  view_options.cover_dir = cover_dir;
  view_options.record_dir = record;
  view_options.frames = frames;
  view_options.cache_directory = no_cache ? std::filesystem::path() : files::default_cache_directory();
  if (!model_name.empty()) {
    if (!cover_dir.empty() || !scene_file.empty())
      throw UsageError("--model: shows a cloud model alone; COVER_DIR and --scene belong to the ground view");
    load_view_model(model_name, view_options);
    view_options.model_size = model_size;
  } else if (options.given(params::cloud_model::view_model_size)) {
    throw UsageError("--model-size: the size of the modeller's volume, given with --model");
  }
  viewer::Viewer window(view_options);
  viewer::ViewState& state = window.state();
  state.coverage = coverage;
  state.month = month;
  state.iterations = iterations;
  state.step = step;
  state.integrator = integrator;
  state.time_step_hours = time_step;
  window.run();
  return exit_ok;
}

}  // namespace nephele::cli

namespace nephele::cli {

int bench_view(const std::vector<std::string>& arguments) {
  std::string size(params::run::bench_view_size.default_text), model_name, viewpoint(params::scene::view.default_text);
  int repeat = params::run::bench_view_repeat.default_int(),
      model_size = params::cloud_model::view_model_size.default_int();
  Options options("bench view",
                  "Prints the milliseconds of each pass of nephele view's frames for the default scene:\n"
                  "the first frame after a change (the preview) and the refinement frames after it, the\n"
                  "median over --repeat changes of the heading (--view orbit: of the orbit view). With --model, the "
                  "modeller's frames after moving\n"
                  "one primitive by one brick (8 voxels of the --model-size volume): the edit of the volume,\n"
                  "then the preview. Needs a display (xvfb-run -a).",
                  params::bench_view);
  options.bind(params::cloud_model::view_model, &model_name);
  options.bind(params::cloud_model::view_model_size, &model_size);
  options.bind(params::run::bench_view_size, &size);
  options.bind(params::run::bench_view_repeat, &repeat);
  options.bind(params::scene::view, &viewpoint);
  if (!options.parse(arguments)) {
    std::cout << options.help();
    return exit_ok;
  }
  viewer::ViewerOptions view_options;
  regional::parse_size(size, view_options.scene.width, view_options.scene.height, "--size");
  view_options.scene.view = viewpoint;  // orbit: the frames of the orbit renderer, from 2000 km
  validate_view_scene(view_options.scene, "bench view", {{"size", "--size"}, {"view", "--view"}});
  view_options.cache_directory = files::default_cache_directory();
  if (!model_name.empty()) {
    load_view_model(model_name, view_options);
    view_options.model_size = model_size;
  }
  viewer::Viewer window(view_options);
  std::printf("device: %s (%s)\n", window.window().info().renderer.c_str(), window.window().info().version.c_str());
  const regional::Scene& scene = view_options.scene;
  if (view_options.model)
    std::printf("model: %s, %zu primitives, volume %d^3, window %dx%d, %d view x %d light steps\n", model_name.c_str(),
                view_options.model->primitives.size(), view_options.model_size, scene.width, scene.height,
                window.state().view_steps, window.state().light_steps);
  else
    std::printf("scene: %s, %s, window %dx%d, %d view x %d light steps\n", scene.view.c_str(), scene.time.c_str(),
                scene.width, scene.height, scene.view_steps, scene.light_steps);
  // The first change also makes the cover and the noise volume: refined once before timing.
  while (!window.refined()) window.frame();
  const std::size_t levels = viewer::refinement_levels().size();
  // Per refinement level: the passes' times and the frame's, over the changes.
  std::vector<std::map<std::string, std::vector<double>>> times(levels);
  std::vector<std::string> order;
  for (int r = 0; r < repeat; ++r) {
    if (view_options.model) {
      // One primitive moved by one brick along x, back and forth: the edit a drag makes.
      model::Primitive& p = window.state().model.primitives[0];
      const float brick = float(model::brick_edge) / float(view_options.model_size) * (r % 2 ? -1.0f : 1.0f);
      p.from.x += brick;
      p.to.x += brick;
    } else {
      window.state().camera.heading_deg += 1.0;
    }
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
  if (!view_options.model) {
    // A drag: the heading turns by a degree every frame, so each frame is a moving preview
    // (a quarter of its pixels marched, the rest reprojected; docs/viewer.md).
    std::map<std::string, std::vector<double>> moving;
    for (int r = 0; r < std::max(repeat, 8); ++r) {
      window.state().camera.heading_deg += 1.0;
      window.frame();
      for (const auto& [name, ms] : window.last_render().timings_ms) moving[name].push_back(ms);
      moving["frame"].push_back(window.frame_ms());
    }
    auto median = [](std::vector<double> values) {
      std::sort(values.begin(), values.end());
      return values[values.size() / 2];
    };
    const double frame = median(moving["frame"]);
    std::printf("while turning a degree per frame (median of %zu frames): frame %.1f ms (%.1f fps)",
                moving["frame"].size(), frame, 1000.0 / frame);
    for (const char* pass : {"clouds", "reproject"})
      if (!moving[pass].empty()) std::printf(", %s %.1f ms", pass, median(moving[pass]));
    std::printf("\n");
  }
  return exit_ok;
}

}  // namespace nephele::cli
