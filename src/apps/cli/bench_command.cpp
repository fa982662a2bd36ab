// nephele bench cover: time of each pass of the global cover for several sizes.
#include <cstdio>
#include <iostream>

#include "apps/cli/commands.hpp"
#include "cover/global_cover.hpp"
#include "apps/cli/orbit_render.hpp"
#include "params/table.hpp"
#include "apps/cli/noise_options.hpp"
#include "apps/cli/cover_options.hpp"
#include "cover/cover_limits.hpp"
#include "studies/benchmarks.hpp"

namespace nephele::cli {
int bench_cover(const std::vector<std::string>& arguments) {
  cover::CoverParameters parameters;
  std::string sizes_text(params::run::bench_cover_sizes.default_text);
  int repeat = params::run::bench_cover_repeat.default_int();
  Options options("bench cover",
                  "Prints the device time of each pass of the global cover (GL_TIME_ELAPSED queries, median\n"
                  "of the repeats) for each size, and separately the host's wall clock, read-back and image\n"
                  "encoding. On a GPU use sizes that fill it, e.g. --sizes 1024,4096.",
                  params::bench_cover);
  options.bind(params::run::bench_cover_sizes, &sizes_text);
  options.bind(params::run::bench_cover_repeat, &repeat);
  add_cover_options(options, parameters, params::bench_cover);
  ProfileOption profile_option;
  profile_option.add(options);
  std::string curl_mode(params::cover::curl_mode.default_text);
  options.bind(params::cover::curl_mode, &curl_mode);
  std::string flow(params::cover::flow.default_text);
  options.bind(params::cover::flow, &flow);
  options.bind(params::cover::time, &parameters.time);
  if (!options.parse(arguments)) {
    std::cout << options.help();
    return exit_ok;
  }
  profile_option.apply(parameters);
  const auto mode = cover::parse_curl_mode(curl_mode);
  if (!mode) throw UsageError(params::cover::curl_mode.option(), curl_mode, params::cover::curl_mode.range_text());
  parameters.curl_mode = *mode;
  apply_flow(flow, parameters);
  validate_cover_parameters(parameters);
  const std::vector<int> sizes = parse_number_list<int>("--sizes", sizes_text, 1, 16384, true);
  gpu::EglContext context;
  for (int s : sizes) cover::check_cover_fits(context, s, "--sizes", parameters.flow);
  std::printf("device: %s (%s)\n", context.info().renderer.c_str(), context.info().version.c_str());
  std::printf("flow: %s\n", cover::flow_name(parameters.flow));
  // The curl each size runs with (--curl-mode auto resolves per size: cover::resolved_curl).
  std::string curl;
  for (int size : sizes) {
    cover::CoverParameters at = parameters;
    at.size = size;
    at = cover::resolved_curl(at);
    curl += (curl.empty() ? "" : ", ") + std::to_string(size) + ": " + cover::curl_mode_name(at.curl_mode) +
            (at.curl_mode == cover::CurlMode::spline ? " of " + std::to_string(at.curl_size) + " nodes" : "");
  }
  std::printf("K = %d steps, curl %s (%s); potential %d octaves, density %d octaves; median of %d runs after a first\n",
              parameters.iterations, cover::curl_mode_name(parameters.curl_mode), curl.c_str(),
              parameters.potential.octaves, parameters.density.octaves, repeat);
  std::printf(
      "device ms: GPU time of each pass by GL_TIME_ELAPSED queries (equirect: its dispatches), or\n"
      "the wall clock between glFinish calls where the driver reports none (llvmpipe);\n"
      "host ms: wall clock of the whole cover, of reading the cube map back, and of encoding the six\n"
      "faces and the equirect map of the cover channel as float32 ZIP EXR in memory, in parallel\n"
      "(generate adds the optical thickness and cloud top, and writes each file as it encodes);\n"
      "first: the whole cover's first run, left out of the medians: the driver compiles the shaders\n"
      "there or reads them from its cache (llvmpipe: seconds when they are not cached)\n");
  const auto& passes = studies::cover_bench_passes();
  std::printf("%6s", "size");
  for (const auto& p : passes) std::printf(" %9s", p.c_str());
  std::printf(" %9s %10s | %9s %9s %9s %9s %8s\n", "device", "Mtexel/s", "first", "wall", "read", "encode", "MB/s");
  for (int size : sizes) {
    const studies::CoverBenchRow row = studies::bench_cover_size(parameters, size, repeat);
    double total = 0;
    std::printf("%6d", size);
    for (double ms : row.device_ms) {
      total += ms;
      std::printf(" %9.1f", ms);
    }
    const double texels = 6.0 * size * size;
    std::printf(" %9.1f %10.1f | %9.1f %9.1f %9.1f %9.1f %8.1f%s\n", total, texels / (total * 1e3), row.first_ms,
                row.wall_ms, row.read_ms, row.encode_ms, row.megabytes / (row.encode_ms / 1e3),
                row.wall_fallback ? "  (no device time from the driver: wall clock)" : "");
    std::fflush(stdout);
  }
  return exit_ok;
}

int run_bench(const std::vector<std::string>& arguments) {
  if (arguments.empty() || arguments[0] == "--help" || arguments[0] == "-h") {
    std::cout
        << "usage: nephele bench cover [options]\n\nbenchmarks:\n"
           "  cover   time of each global cover pass for sizes 256, 512, 1024\n"
           "  render  seconds per frame of the default scene, image error against steps\n"
           "  noise   million points per second of 3D Worley and Perlin, seconds of the noise presets\n"
           "  model   milliseconds per cloud model volume (1 to 50 primitives), whole and after one edit\n"
           "  orbit   milliseconds per frame of the orbit view at 640x360 and 1280x720\n"
           "  view    milliseconds per pass of nephele view's preview and refinement frames (needs a display)\n"
           "  export  error, size and encoding time of each texel format of the exports (bench export COVER_DIR)\n";
    return arguments.empty() ? exit_usage : exit_ok;
  }
  const std::vector<std::string> rest(arguments.begin() + 1, arguments.end());
  if (arguments[0] == "cover") return bench_cover(rest);
  if (arguments[0] == "render") return bench_render(rest);
  if (arguments[0] == "noise") return bench_noise(rest);
  if (arguments[0] == "model") return bench_model(rest);
  if (arguments[0] == "orbit") return bench_orbit(rest);
  if (arguments[0] == "view") return bench_view(rest);
  if (arguments[0] == "export") return bench_export(rest);
  throw UsageError("nephele bench: unknown benchmark '" + arguments[0] +
                   "' (allowed: cover, render, noise, model, orbit, view, export)");
}

}  // namespace nephele::cli
