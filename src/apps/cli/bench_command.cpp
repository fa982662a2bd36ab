// nephele bench cover: time of each pass of the global cover for several sizes.
#include <algorithm>
#include <cstdio>
#include <iostream>

#include "apps/cli/commands.hpp"
#include "params/table.hpp"
#include "apps/cli/noise_options.hpp"
#include "apps/cli/cover_options.hpp"
#include "apps/cli/device_limits.hpp"
#include "core/integer_text.hpp"
#include "cover/global_cover.hpp"
#include "cover/equirect.hpp"
#include "gpu/pass_timer.hpp"

namespace nephele::cli {
namespace {

// Strict integers: parse_number took "1.5" (then truncated to 1), "0x10" and " 16".
std::vector<int> parse_sizes(const std::string& text) {
  const std::string allowed = "give a comma-separated list of integers in 1..16384, e.g. 256,512";
  std::vector<int> sizes;
  size_t start = 0;
  while (true) {
    const size_t comma = text.find(',', start);
    const std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const auto value = core::parse_integer(item);
    if (!value) throw UsageError("--sizes: '" + item + "' is not an integer (" + allowed + ")");
    if (*value < 1 || *value > 16384)
      throw UsageError("--sizes: " + item + " is out of range (" + allowed + ")");
    sizes.push_back(static_cast<int>(*value));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return sizes;
}

int bench_cover(const std::vector<std::string>& arguments) {
  cover::CoverParameters parameters;
  std::string sizes_text(params::run::bench_cover_sizes.default_text);
  int repeat = params::run::bench_cover_repeat.default_int();
  Options options("bench cover",
                  "Prints the time of each pass of the global cover (median of the repeats) for\n"
                  "each size, on the current OpenGL device.", params::bench_cover);
  options.bind(params::run::bench_cover_sizes, &sizes_text);
  options.bind(params::run::bench_cover_repeat, &repeat);
  add_cover_options(options, parameters, params::bench_cover);
  if (!options.parse(arguments)) {
    std::cout << options.help();
    return exit_ok;
  }
  validate_cover_parameters(parameters);
  const std::vector<int> sizes = parse_sizes(sizes_text);
  gpu::EglContext context;
  for (int s : sizes) check_cover_fits(context, s);
  std::printf("device: %s (%s)\n", context.info().renderer.c_str(), context.info().version.c_str());
  std::printf("K = %d steps, potential %d octaves, density %d octaves; milliseconds, median of %d\n",
              parameters.iterations, parameters.potential.octaves, parameters.density.octaves, repeat);
  const char* passes[] = {"identity", "curl", "warp", "density", "calibrate", "coverage", "equirect"};
  std::printf("%6s", "size");
  for (const char* p : passes) std::printf(" %10s", p);
  std::printf(" %10s %12s\n", "total", "Mtexel/s");
  for (int size : sizes) {
    parameters.size = size;
    std::vector<std::vector<double>> runs(std::size(passes));
    for (int r = 0; r < repeat; ++r) {
      cover::GlobalCover cover(parameters);
      cover.run();
      for (const auto& t : cover.timings())
        for (size_t k = 0; k < std::size(passes); ++k)
          if (t.pass == passes[k]) runs[k].push_back(t.milliseconds);
      runs.back().push_back(gpu::time_pass([&] { cover::equirect_from_cube(cover.cover_field(), 4 * size, 2 * size); }));
    }
    double total = 0;
    std::printf("%6d", size);
    for (auto& r : runs) {
      std::sort(r.begin(), r.end());
      const double median = r[r.size() / 2];
      total += median;
      std::printf(" %10.1f", median);
    }
    std::printf(" %10.1f %12.2f\n", total, 6.0 * size * size / (total * 1e3));
    std::fflush(stdout);
  }
  return exit_ok;
}

}  // namespace

int run_bench(const std::vector<std::string>& arguments) {
  if (arguments.empty() || arguments[0] == "--help" || arguments[0] == "-h") {
    std::cout << "usage: nephele bench cover [options]\n\nbenchmarks:\n"
                 "  cover   time of each global cover pass for sizes 256, 512, 1024\n"
                 "  render  seconds per frame of the default scene, image error against steps\n"
                 "  noise   million points per second of 3D Worley and Perlin, seconds of the noise presets\n"
                 "  model   milliseconds per cloud model volume (1 to 50 primitives), whole and after one edit\n";
    return arguments.empty() ? exit_usage : exit_ok;
  }
  const std::vector<std::string> rest(arguments.begin() + 1, arguments.end());
  if (arguments[0] == "cover") return bench_cover(rest);
  if (arguments[0] == "render") return bench_render(rest);
  if (arguments[0] == "noise") return bench_noise(rest);
  if (arguments[0] == "model") return bench_model(rest);
  throw UsageError("nephele bench: unknown benchmark '" + arguments[0] + "' (allowed: cover, render, noise, model)");
}

}  // namespace nephele::cli
