// nephele report: error of each warp approximation against its run time (docs/numerics.md), and
// the image error of the ray marcher against the number of view and light steps (docs/rendering.md).
#include <filesystem>
#include <iostream>
#include <sstream>

#include "apps/cli/commands.hpp"
#include "core/progress.hpp"
#include "params/table.hpp"
#include "apps/cli/cover_options.hpp"
#include "cover/cover_limits.hpp"
#include "render/render_limits.hpp"
#include "files/atomic_output.hpp"
#include "gpu/egl_context.hpp"
#include "studies/moving_precision.hpp"
#include "studies/noise_grid_precision.hpp"
#include "studies/work_precision.hpp"
#include "regional/scene.hpp"
#include "studies/render_error.hpp"
#include "studies/render_report.hpp"

namespace nephele::cli {

int run_report(const std::vector<std::string>& all_arguments) {
  // `nephele report render`: only the render sweep.
  // `nephele report moving`: only the moving flow's sweep.
  const bool render_only = !all_arguments.empty() && all_arguments[0] == "render";
  const bool moving_only = !all_arguments.empty() && all_arguments[0] == "moving";
  const std::vector<std::string> arguments(all_arguments.begin() + (render_only || moving_only ? 1 : 0),
                                           all_arguments.end());
  cover::CoverParameters parameters;
  parameters.flow = cover::Flow::steady;  // the sweeps below are of the steady warp and its reference
  std::string out(params::run::report_out.default_text), sizes, steps, tolerances, render_size;
  bool quick = false, no_render = false, quiet = false;
  int samples = 0, repeat = 0;  // 0: the mode's default
  float budget_ms = 0.0f;
  Options options("report",
                  "Sweeps integrator x steps x curl mode x size, times the curl and warp passes and compares\n"
                  "the warped points with a reference solution at sample points. Writes error_vs_runtime.csv,\n"
                  "error_vs_runtime.svg (work-precision diagram), stability.csv and summary.md into --out.\n"
                  "The moving flow's back-trajectories (one frame; RK4 steps, spline grids and windows) against\n"
                  "the CPU's procedural flow go into moving_error.csv and moving_error_vs_runtime.svg, the noise\n"
                  "grid's density and cover against every octave at every texel into noise_grid_error.csv and\n"
                  "noise_grid_error_vs_runtime.svg.\n"
                  "The flow time T = iterations * step stays fixed; fixed-step schemes use h = T / steps.\n"
                  "Then renders the default scene with view steps 8..96 x light steps 2..12, over 2 and 4\n"
                  "frames and at 1/2 and 1/4 resolution, against " +
                      studies::RenderSweepOptions::full().reference_name() + "\n(quick: 8,16,48 x 2,12 against " +
                      studies::RenderSweepOptions::quick().reference_name() +
                      ")\ninto render_error.csv, render_error_vs_runtime.svg and a section of summary.md; the error\n"
                      "is the RMS of the display values in [0, 1]. Then renders each quality of render --quality\n"
                      "at 1280x720 against " +
                      studies::RenderSweepOptions::qualities(false).reference_name() +
                      " (quick: 64x36) into render_quality.csv and a section of summary.md.\n"
                      "`nephele report render [options]` runs only the render sweep, `nephele report moving\n"
                      "[options]` only the moving flow's.",
                  params::report);
  options.bind(params::run::report_out, &out);
  options.bind(params::run::report_quick, &quick);
  options.bind(params::run::quiet, &quiet);
  options.bind(params::run::report_sizes, &sizes);
  options.bind(params::run::report_steps, &steps);
  options.bind(params::run::report_tolerances, &tolerances);
  options.bind(params::run::report_samples, &samples);
  options.bind(params::run::report_repeat, &repeat);
  options.bind(params::run::report_render_size, &render_size);
  options.bind(params::run::report_no_render, &no_render);
  options.bind(params::run::report_budget_ms, &budget_ms);
  add_cover_options(options, parameters, params::report);
  WarpOptions warp_options;
  ProfileOption profile_option;
  profile_option.add(options);
  warp_options.add(options, parameters, false);
  if (!options.parse(arguments)) {
    std::cout << options.help();
    return exit_ok;
  }
  warp_options.apply(parameters);
  profile_option.apply(parameters);
  validate_cover_parameters(parameters);
  studies::SweepOptions sweep =
      quick ? studies::SweepOptions::quick(parameters) : studies::SweepOptions::full(parameters);
  if (!sizes.empty()) sweep.sizes = parse_number_list<int>("--sizes", sizes, 1, 16384, true);
  if (!steps.empty()) sweep.steps = parse_number_list<int>("--steps", steps, 1, 100000, true);
  if (!tolerances.empty()) sweep.tolerances = parse_number_list<float>("--tolerances", tolerances, 1e-7, 1.0, false);
  if (samples > 0) sweep.sample_grid = samples;
  if (repeat > 0) sweep.repeat = repeat;
  if (budget_ms > 0) sweep.budget_ms = budget_ms;
  studies::RenderSweepOptions render_sweep =
      quick ? studies::RenderSweepOptions::quick() : studies::RenderSweepOptions::full();
  const regional::Scene render_scene;  // the built-in default: Gurten, global cover as the weather
  if (!render_size.empty()) regional::parse_size(render_size, render_sweep.width, render_sweep.height, "--render-size");
  regional::Scene check = render_scene;
  check.width = render_sweep.width;
  check.height = render_sweep.height;
  regional::validate_scene(check, "--render-size", {{"size", "--render-size"}});
  const std::filesystem::path directory(out);
  files::check_output_directory(directory, "--out");

  gpu::EglContext context;
  if (render_only && no_render) throw UsageError("report render: --no-render leaves nothing to do");
  if (moving_only) no_render = true;
  const bool steady_sweep = !render_only && !moving_only;
  if (steady_sweep)
    for (int size : sweep.sizes) cover::check_cover_fits(context, size, "--sizes");
  if (!no_render) render::check_render_fits(context, render_sweep.width, render_sweep.height, "--render-size");
  if (!no_render)
    render::check_render_fits(context, studies::RenderSweepOptions::qualities(quick).width,
                              studies::RenderSweepOptions::qualities(quick).height, "the qualities' sweep");
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error) throw UsageError("--out: cannot create directory '" + out + "': " + error.message());

  // Opened before the sweep, so that an interrupt at any time removes its temporary directory.
  files::OutputSet outputs(directory, files::OutputSet::Scope::directory);
  std::cout << "device: " << context.info().renderer << " (" << context.info().version << ")\n" << std::flush;
  studies::SweepResult result;
  if (steady_sweep) {
    core::Progress sweep_progress("report", sweep.planned_runs(), core::Progress::for_stderr(quiet));
    result = studies::run_sweep(
        sweep, [](const std::string& line) { std::cout << line << "\n"
                                                       << std::flush; },
        [&](int done) { sweep_progress.update(done, "warp runs"); });
    sweep_progress.finish();
  }
  result.device = context.info().renderer + " (" + context.info().version + ")";
  // The moving flow (the default cover): its back-trajectories against their CPU reference.
  cover::CoverParameters moving_base = parameters;
  moving_base.flow = cover::Flow::moving;
  moving_base.integrator = cover::Integrator::rk4;
  const studies::MovingPrecisionOptions moving_sweep =
      quick ? studies::MovingPrecisionOptions::quick(moving_base) : studies::MovingPrecisionOptions::full(moving_base);
  std::vector<studies::MovingPrecisionRow> moving_rows;
  if (!render_only) {
    std::cout << "moving flow: one frame at " << moving_sweep.base.time << ", " << moving_sweep.size
              << " per face, against the CPU's procedural flow at " << moving_sweep.reference_factor
              << " times the steps\n"
              << std::flush;
    moving_rows = studies::moving_precision_sweep(moving_sweep, [](const studies::MovingPrecisionRow& row) {
      std::cout << studies::moving_precision_line(row) << "\n" << std::flush;
    });
  }
  // The noise grid of the moving flow's covers finer than their warp grid.
  const studies::NoiseGridOptions noise_grid_sweep =
      quick ? studies::NoiseGridOptions::quick(moving_sweep.base) : studies::NoiseGridOptions::full(moving_sweep.base);
  std::vector<studies::NoiseGridRow> noise_grid_rows;
  if (!render_only) {
    std::cout << "noise grid: one frame at " << noise_grid_sweep.base.time << ", " << noise_grid_sweep.size
              << " per face, warp grid " << noise_grid_sweep.warp_grid << "\n"
              << std::flush;
    noise_grid_rows = studies::noise_grid_sweep(noise_grid_sweep, [](const studies::NoiseGridRow& row) {
      std::cout << studies::noise_grid_line(row) << "\n" << std::flush;
    });
  }

  std::vector<studies::RenderErrorRow> render_rows, quality_rows;
  studies::ReferenceCheck reference_check;
  const studies::RenderSweepOptions quality_sweep = studies::RenderSweepOptions::qualities(quick);
  // One render sweep with its table on stdout and its progress on stderr.
  const auto render_sweep_rows = [&](const studies::RenderSweepOptions& o, const std::string& what,
                                     studies::ReferenceCheck* check) {
    std::cout << what << ": default scene at " << o.width << "x" << o.height << ", reference " << o.reference_name()
              << "\n"
              << studies::render_error_table_header() << std::flush;
    core::Progress progress("report", static_cast<double>(o.variants().size()), core::Progress::for_stderr(quiet));
    progress.update(0, "rendering the reference of the " + what);
    int done = 0;
    auto rows = studies::render_error_sweep(
        render_scene, o,
        [&](const studies::RenderErrorRow& row) {
          std::cout << studies::render_error_table_line(row) << std::flush;
          progress.update(++done, what);
        },
        check);
    progress.finish();
    return rows;
  };
  if (!no_render) {
    render_rows = render_sweep_rows(render_sweep, "render sweep", &reference_check);
    std::cout << "reference check: " << reference_check.half_steps.view_steps << " view x "
              << reference_check.half_steps.light_steps << " light steps against the reference: display rms "
              << reference_check.half_steps.display_rms << "; " << reference_check.limited
              << " reference pixels left out (llvmpipe's loop limit)\n";
    // The qualities of `render --quality`, at the size their targets are set for.
    quality_rows = render_sweep_rows(quality_sweep, "render qualities", nullptr);
  }
  const studies::RenderStepChoice render_choice =
      studies::choose_render_steps(render_rows, render_scene.view_steps, render_scene.light_steps);

  std::string summary;
  if (steady_sweep) {
    outputs.write("error_vs_runtime.csv", studies::error_csv(result.rows));
    outputs.write("stability.csv", studies::stability_csv(result.rows));
    outputs.write("error_vs_runtime.svg",
                  studies::work_precision_svg(result.rows, "Warp error against run time, " + result.device,
                                              result.cpu_device ? "CPU time of the curl + warp passes, all threads (ms)"
                                                                : "time of the curl + warp passes (ms)"));
    summary = studies::summary_markdown(result, sweep) + "\n";
  }
  if (!render_only) {
    outputs.write("moving_error.csv", studies::moving_precision_csv(moving_rows));
    outputs.write("moving_error_vs_runtime.svg",
                  studies::moving_precision_svg(moving_rows, "The moving flow's back-trajectories, " + result.device));
    summary += studies::moving_precision_markdown(moving_rows, moving_sweep) + "\n";
    outputs.write("noise_grid_error.csv", studies::noise_grid_csv(noise_grid_rows));
    outputs.write(
        "noise_grid_error_vs_runtime.svg",
        studies::noise_grid_svg(noise_grid_rows, "The noise grid's error against run time, " + result.device));
    summary += studies::noise_grid_markdown(noise_grid_rows, noise_grid_sweep) + "\n";
  }
  if (moving_only) {
  } else if (no_render) {
    summary += "## Render: image error against run time\n\nNot run (--no-render).\n";
  } else {
    outputs.write("render_error.csv", studies::render_error_csv(render_rows, render_sweep));
    outputs.write(
        "render_error_vs_runtime.svg",
        studies::render_error_svg(render_rows,
                                  "Image error against run time, default scene, " + std::to_string(render_sweep.width) +
                                      " x " + std::to_string(render_sweep.height) + " pixels",
                                  "reference " + std::to_string(render_sweep.reference_view) + " view x " +
                                      std::to_string(render_sweep.reference_light) + " light steps, " +
                                      std::to_string(render_sweep.reference_frames) + " frames; " + result.device,
                                  render_scene.view_steps, render_scene.light_steps));
    summary += studies::render_summary_markdown(render_rows, render_sweep, render_choice, render_scene.view_steps,
                                                render_scene.light_steps, reference_check);
    outputs.write("render_quality.csv", studies::render_quality_csv(quality_rows, quality_sweep));
    summary += "\n" + studies::render_quality_markdown(quality_rows, quality_sweep);
  }
  outputs.write("summary.md", summary);
  outputs.commit();
  for (const auto& c : result.comparisons)
    if (c.has_baseline)
      std::cout << "size " << c.size << ": at the default's error (" << c.baseline.warp_err_rms << " rad rms) "
                << (c.has_equal_error ? std::to_string(c.speedup) + "x faster" : std::string("no faster run"))
                << "; at its time (" << c.baseline.time_ms << " ms) "
                << (c.has_equal_time ? std::to_string(c.error_ratio) + "x less error" : std::string("no run")) << "\n";
  if (render_choice.has_default)
    std::cout << "render: defaults " << studies::render_variant_name(render_choice.default_row) << ": display rms "
              << render_choice.default_row.display_rms << "; within " << render_choice.factor
              << "x its error the cheapest is " << studies::render_variant_name(render_choice.cheapest) << " ("
              << render_choice.cheapest.time_ms << " ms); within its time the most accurate is "
              << studies::render_variant_name(render_choice.most_accurate) << " (display rms "
              << render_choice.most_accurate.display_rms << ")\n";
  std::cout << "wrote " << directory.string()
            << "/: " << (steady_sweep ? "error_vs_runtime.csv, error_vs_runtime.svg, stability.csv, " : "")
            << (render_only ? ""
                            : "moving_error.csv, moving_error_vs_runtime.svg, noise_grid_error.csv, "
                              "noise_grid_error_vs_runtime.svg, ")
            << (no_render ? "" : "render_error.csv, render_error_vs_runtime.svg, render_quality.csv, ")
            << "summary.md\n";
  return exit_ok;
}

}  // namespace nephele::cli
