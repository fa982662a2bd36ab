// nephele model: the density volume of a cloud made of implicit primitives (Montenegro et
// al.; docs/model.md), written as raw float32, an EXR slice atlas and an OpenVDB grid.
// nephele bench model: its GPU times and brick occupancy.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "files/atomic_output.hpp"
#include "io/cloud_model_files.hpp"
#include "apps/cli/commands.hpp"
#include "apps/cli/options.hpp"
#include "core/memory.hpp"
#include "core/progress.hpp"
#include "gpu/egl_context.hpp"
#include "gpu/pass_timer.hpp"
#include "io/model_files.hpp"
#include "regional/scene.hpp"
#include "render/model_preview.hpp"
#include "model/density_volume.hpp"
#include "model/model_limits.hpp"
#include "studies/benchmarks.hpp"
#include "params/table.hpp"

namespace nephele::cli {

namespace cm = params::cloud_model;

int run_model(const std::vector<std::string>& arguments) {
  std::string example, scene_path, out(cm::out.default_text), blend(cm::blend.default_text);
  int size = cm::size.default_int();
  double scale = cm::scale.default_number, extent = cm::extent.default_number;
  double base = cm::base.default_number, top = cm::top.default_number;
  bool quiet = false, verbose = false, no_preview = false;
  std::string preview_size(cm::preview.default_text);
  Options options(
      "model",
      "Builds the density volume of a cloud made of implicit primitives (points and segments with Wyvill\n"
      "fields, Lipus blending and turbulence per primitive; Montenegro et al., docs/model.md) from a built-in\n"
      "--example or a --scene file (scenes/*.cloud.json), and writes into --out: density.raw (float32),\n"
      "density.json, density_atlas.exr, model.cloud.json, preview.png and, with OpenVDB, density.vdb.",
      params::model);
  options.bind(cm::example, &example);
  options.bind(cm::scene_path, &scene_path);
  options.bind(cm::size, &size);
  options.bind(cm::out, &out);
  options.bind(cm::blend, &blend);
  options.bind(cm::scale, &scale);
  options.bind(cm::extent, &extent);
  options.bind(cm::base, &base);
  options.bind(cm::top, &top);
  options.bind(cm::preview, &preview_size);
  options.bind(cm::no_preview, &no_preview);
  options.bind(params::run::quiet, &quiet);
  options.bind(params::run::verbose, &verbose);
  if (!options.parse(arguments)) {
    std::cout << options.help();
    return exit_ok;
  }
  if (example.empty() == scene_path.empty())
    throw UsageError("--example, --scene: give exactly one (a built-in cloud or a cloud model file)");
  model::CloudModel m = example.empty() ? io::read_cloud_model(scene_path) : model::example(example);
  if (options.given(cm::blend)) m.blend = model::parse_blend(blend, "--blend");
  if (options.given(cm::scale)) m.scale = float(scale);
  if (options.given(cm::extent)) m.extent_m = extent;
  if (options.given(cm::base)) m.base = float(base);
  if (options.given(cm::top)) m.top = float(top);
  model::validate(m, example.empty() ? scene_path : "--example " + example);
  render::PreviewSettings preview;
  regional::parse_size(preview_size, preview.width, preview.height, "--preview");
  files::check_output_directory(out, "--out");

  gpu::EglContext context;
  if (verbose) std::cerr << "renderer: " << context.info().renderer << " (" << context.info().version << ")\n";
  model::check_model_fits(size, context);
  core::Progress progress("model", 3, core::Progress::for_stderr(quiet));
  progress.update(0, "volume");
  model::DensityVolume volume(size);
  volume.compute(m);
  const std::vector<float> values = volume.read();
  const model::PassStats stats = volume.stats();
  core::ImageData image;
  double preview_ms = 0;
  if (!no_preview) {
    progress.update(1, "preview");
    gpu::PassTimer timer;
    image = render::render_preview(volume, preview);
    preview_ms = timer.milliseconds();
  }
  progress.update(2, "files");
  json::Value run;
  run.set("renderer", context.info().renderer);
  run.set("volume_ms", stats.ms);
  run.set("bricks", stats.bricks);
  run.set("bricks_computed", stats.bricks_computed);
  run.set("brick_primitive_pairs", static_cast<long>(stats.pairs));
  if (!no_preview) run.set("preview_ms", preview_ms);
  const auto names = io::write_model_files(out, m, size, values, run, no_preview ? nullptr : &image);
  progress.finish();
  if (verbose) {
    std::fprintf(stderr, "volume: %d^3 in %.1f ms, %d of %d bricks (%.1f%%), %ld brick-primitive pairs\n", size,
                 stats.ms, stats.bricks_computed, stats.bricks, 100.0 * stats.occupancy(), stats.pairs);
    if (!no_preview) std::fprintf(stderr, "preview: %d x %d in %.1f ms\n", preview.width, preview.height, preview_ms);
  }
  for (const auto& name : names) std::cout << (std::filesystem::path(out) / name).string() << "\n";
  return exit_ok;
}

int bench_model(const std::vector<std::string>& arguments) {
  int size = cm::size.default_int(), repeat = params::run::bench_model_repeat.default_int();
  Options options("bench model",
                  "Times the density volume of 1, 5, 10 and 50 primitives, with turbulence after blending (global,\n"
                  "eq. 5) and per primitive (eq. 6), computed whole and after moving one primitive, with the share of\n"
                  "bricks each pass computed.",
                  params::bench_model);
  options.bind(cm::size, &size);
  options.bind(params::run::bench_model_repeat, &repeat);
  if (!options.parse(arguments)) {
    std::cout << options.help();
    return exit_ok;
  }
  gpu::EglContext context;
  model::check_model_fits(size, context);
  std::printf("device: %s (%s)\n", context.info().renderer.c_str(), context.info().version.c_str());
  std::printf("volume %d^3, median of %d runs after a warming run\n\n", size, repeat);
  std::printf("%-10s  %-13s  %10s  %9s  %10s  %9s  %9s\n", "primitives", "noise", "full ms", "bricks", "edit ms",
              "bricks", "volumes/s");
  model::DensityVolume volume(size);
  for (int n : {1, 5, 10, 50})
    for (auto blend : {model::Blend::global, model::Blend::per_primitive}) {
      const studies::ModelBenchRow row = studies::bench_model_case(volume, n, blend, repeat);
      std::printf("%-10d  %-13s  %10.1f  %8.1f%%  %10.1f  %8.1f%%  %9.1f\n", n,
                  blend == model::Blend::global ? "global (5)" : "per-prim (6)", row.full_ms,
                  100.0 * row.full_occupancy, row.edit_ms, 100.0 * row.edit_occupancy, 1000.0 / row.full_ms);
      std::fflush(stdout);
    }
  return exit_ok;
}

}  // namespace nephele::cli
