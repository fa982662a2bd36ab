// nephele model: the density volume of a cloud made of implicit primitives (Montenegro et
// al.; docs/model.md), written as raw float32, an EXR slice atlas and an OpenVDB grid.
// nephele bench model: its GPU times and brick occupancy.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

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
#include "params/table.hpp"

namespace nephele::cli {
namespace {

namespace cm = params::cloud_model;

// Host bytes of a run: the read-back volume, the atlas, the encoded files and the VDB tree
// (each about one volume), plus the texture itself on a software driver (host memory).
double host_bytes(int size, bool software) {
  return 4.0 * model::DensityVolume::device_bytes(size) + (software ? model::DensityVolume::device_bytes(size) : 0.0);
}

void check_fits(int size, const gpu::Context& context) {
  const double available = core::host_memory_available_bytes();
  const double needed = host_bytes(size, context.is_software());
  if (available > 0 && needed > available) {
    int largest = size;
    while (largest > 8 && host_bytes(largest, context.is_software()) > available) largest = largest * 7 / 8;
    std::ostringstream m;
    m << "--size: " << size << "^3 voxels need about " << std::ceil(needed / 1048576.0) << " MiB but "
      << std::floor(available / 1048576.0) << " MiB of memory are available; allowed up to about " << largest;
    throw UsageError(m.str());
  }
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// n primitives spread over a cumulus field in a fixed pattern (golden-angle spiral), so that
// the figures for 1, 5, 10 and 50 primitives describe comparable clouds.
model::CloudModel spiral_of_cumuli(int n, model::Blend blend) {
  model::CloudModel m;
  m.blend = blend;
  for (int i = 0; i < n; ++i) {
    model::Primitive p;
    const float r = 0.3f * std::sqrt((float(i) + 0.5f) / float(n)), angle = 2.39996323f * float(i);
    p.from = p.to = glsl::vec3(0.5f + r * std::cos(angle), 0.5f + r * std::sin(angle), 0.35f + 0.05f * float(i % 3));
    p.radius = 0.05f;
    p.influence = 0.08f;
    p.noise.seed = std::uint32_t(i + 1);
    m.primitives.push_back(p);
  }
  return m;
}

}  // namespace

int run_model(const std::vector<std::string>& arguments) {
  std::string example, scene_path, out(cm::out.default_text), blend(cm::blend.default_text);
  int size = cm::size.default_int();
  double scale = cm::scale.default_number, extent = cm::extent.default_number;
  bool quiet = false, verbose = false, no_preview = false;
  std::string preview_size(cm::preview.default_text);
  Options options("model",
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
  model::validate(m, example.empty() ? scene_path : "--example " + example);
  render::PreviewSettings preview;
  regional::parse_size(preview_size, preview.width, preview.height, "--preview");

  gpu::EglContext context;
  if (verbose) std::cerr << "renderer: " << context.info().renderer << " (" << context.info().version << ")\n";
  check_fits(size, context);
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
    std::fprintf(stderr, "volume: %d^3 in %.1f ms, %d of %d bricks (%.1f%%), %ld brick-primitive pairs\n", size, stats.ms,
                 stats.bricks_computed, stats.bricks, 100.0 * stats.occupancy(), stats.pairs);
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
  check_fits(size, context);
  std::printf("device: %s (%s)\n", context.info().renderer.c_str(), context.info().version.c_str());
  std::printf("volume %d^3, median of %d runs after a warming run\n\n", size, repeat);
  std::printf("%-10s  %-13s  %10s  %9s  %10s  %9s  %9s\n", "primitives", "noise", "full ms", "bricks", "edit ms",
              "bricks", "volumes/s");
  model::DensityVolume volume(size);
  for (int n : {1, 5, 10, 50})
    for (auto blend : {model::Blend::global, model::Blend::per_primitive}) {
      const model::CloudModel m = spiral_of_cumuli(n, blend);
      volume.compute(m);  // warming: compiles and allocates
      std::vector<double> full, edit;
      double full_occupancy = 0, edit_occupancy = 0;
      for (int r = 0; r < repeat; ++r) {
        volume.compute(m);
        full.push_back(volume.stats().ms);
        full_occupancy = volume.stats().occupancy();
        // Moves the first primitive by one brick's width and back: two edits, each timed.
        model::Primitive moved = m.primitives[0];
        moved.from += glsl::vec3(8.0f / float(size), 0.0f, 0.0f);
        moved.to = moved.from;
        volume.edit(0, moved);
        edit.push_back(volume.stats().ms);
        edit_occupancy = volume.stats().occupancy();
        volume.edit(0, m.primitives[0]);
        edit.push_back(volume.stats().ms);
      }
      const double ms = median(full);
      std::printf("%-10d  %-13s  %10.1f  %8.1f%%  %10.1f  %8.1f%%  %9.1f\n", n,
                  blend == model::Blend::global ? "global (5)" : "per-prim (6)", ms, 100.0 * full_occupancy,
                  median(edit), 100.0 * edit_occupancy, 1000.0 / ms);
      std::fflush(stdout);
    }
  return exit_ok;
}

}  // namespace nephele::cli
