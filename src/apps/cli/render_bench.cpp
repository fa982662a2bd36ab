// nephele bench render: seconds per frame, and the image error against the number of steps.
#include <algorithm>
#include <cstdio>
#include <iostream>

#include "apps/cli/commands.hpp"
#include "params/table.hpp"
#include "apps/cli/options.hpp"
#include "gpu/egl_context.hpp"
#include "gpu/pass_timer.hpp"
#include "studies/render_error.hpp"
#include "studies/render_report.hpp"
#include "io/surface_files.hpp"
#include "io/weather_files.hpp"
#include "render/scene_renderer.hpp"

namespace nephele::cli {

int bench_render(const std::vector<std::string>& arguments) {
  regional::Scene scene;  // the built-in default: Gurten, global cover as the weather
  std::string size(params::run::bench_render_size.default_text);
  std::string sweep_size(params::run::bench_render_sweep_size.default_text);
  int repeat = params::run::bench_render_repeat.default_int();
  bool no_sweep = false;
  Options options("bench render",
                  "Prints seconds per frame of the default scene, then the image error (RMS of the display\n"
                  "values; relative RMS and max of the radiance) against the numbers of view and light steps,\n"
                  "frames and resolution, against " +
                      studies::RenderSweepOptions::full().reference_name() + ": the sweep of `nephele report`.",
                  params::bench_render);
  options.bind(params::run::bench_render_size, &size);
  options.bind(params::run::bench_render_sweep_size, &sweep_size);
  options.bind(params::run::bench_render_repeat, &repeat);
  options.bind(params::run::bench_render_no_sweep, &no_sweep);
  if (!options.parse(arguments)) {
    std::cout << options.help();
    return exit_ok;
  }
  regional::parse_size(size, scene.width, scene.height, "--size");
  regional::Scene check = scene;
  regional::parse_size(sweep_size, check.width, check.height, "--sweep-size");
  regional::validate_scene(scene, "--size");
  regional::validate_scene(check, "--sweep-size");
  gpu::EglContext context;
  std::printf("device: %s (%s)\n", context.info().renderer.c_str(), context.info().version.c_str());
  std::printf("scene: %s, %s, %dx%d, %d view x %d light x %d sky steps\n", scene.view.c_str(), scene.time.c_str(),
              scene.width, scene.height, scene.view_steps, scene.light_steps, scene.sky_steps);
  std::vector<double> frames;
  for (int r = 0; r < repeat; ++r) {
    const gpu::PassTimer timer;
    std::string warning;  // the default etopo5 missing: a cover without the mask, as render makes
    const render::SceneRender result =
        render::render_scene(scene, io::read_scene_weather(scene), io::scene_surface(scene, &warning, "--surface"));
    frames.push_back(timer.milliseconds() / 1000.0);
    if (r == 0)
      for (const auto& [name, ms] : result.render.timings_ms) std::printf("  pass %-14s %10.1f ms\n", name.c_str(), ms);
  }
  std::sort(frames.begin(), frames.end());
  std::printf("seconds per frame (whole scene, median of %d): %.2f\n", repeat, frames[frames.size() / 2]);
  if (no_sweep) return exit_ok;

  studies::RenderSweepOptions sweep = studies::RenderSweepOptions::full();
  regional::parse_size(sweep_size, sweep.width, sweep.height, "--sweep-size");
  std::printf(
      "\nimage error against steps, frames and resolution at %dx%d (reference %d view x %d light steps, %d "
      "frames)\n",
      sweep.width, sweep.height, sweep.reference_view, sweep.reference_light, sweep.reference_frames);
  std::printf("%s", studies::render_error_table_header().c_str());
  std::fflush(stdout);
  studies::render_error_sweep(scene, sweep, [](const studies::RenderErrorRow& row) {
    std::printf("%s", studies::render_error_table_line(row).c_str());
    std::fflush(stdout);
  });
  return exit_ok;
}

}  // namespace nephele::cli
