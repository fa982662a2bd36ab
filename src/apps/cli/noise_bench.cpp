// nephele bench noise: million points per second of the tileable noise generator on a cubic
// grid (as FastNoise's benchmarks count them), and the seconds of the presets.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "apps/cli/commands.hpp"
#include "params/table.hpp"
#include "apps/cli/noise_options.hpp"
#include "apps/cli/options.hpp"
#include "gpu/pass_timer.hpp"
#include "io/noise_files.hpp"
#include "noise/noise_texture.hpp"
#include "studies/benchmarks.hpp"

namespace nephele::cli {
int bench_noise(const std::vector<std::string>& arguments) {
  int size = params::run::bench_noise_size.default_int();
  int repeat = params::run::bench_noise_repeat.default_int();
  Options options("bench noise",
                  "Prints million points per second of 3D Worley F1, Perlin and 4-octave Perlin fBm on a size^3\n"
                  "grid (medians of the repeats; 'device' by GL_TIME_ELAPSED queries around the dispatches,\n"
                  "n/a where the driver gives none (llvmpipe); 'GPU mem' wall clock until the values are in\n"
                  "GPU memory; 'host' until they are in a host array), and the seconds of the shape and\n"
                  "erosion presets. On a GPU use --size 512.",
                  params::bench_noise);
  options.bind(params::run::bench_noise_size, &size);
  options.bind(params::run::bench_noise_repeat, &repeat);
  if (!options.parse(arguments)) {
    std::cout << options.help();
    return exit_ok;
  }
  gpu::EglContext context;
  std::printf("device: %s (%s)\n", context.info().renderer.c_str(), context.info().version.c_str());
  noise::TextureGenerator generator;
  const double points = static_cast<double>(size) * size * size;
  std::printf("%d^3 grid, tileable, median of %d runs   Mpt/s device  Mpt/s GPU mem  Mpt/s host  first run ms\n", size,
              repeat);
  for (const studies::NoiseBenchCase& c : studies::noise_bench_cases(size)) {
    try {
      noise::validate(c.spec);
    } catch (const noise::SpecError&) {
      std::printf("  %-42s (not possible at this size)\n", c.name);
      continue;
    }
    const studies::NoiseRun run = studies::measure_noise(generator, c.spec, repeat);
    if (run.device_ms > 0)
      std::printf("  %-42s %7.1f", c.name, points / (run.device_ms * 1e3));
    else
      std::printf("  %-42s %7s", c.name, "n/a");
    std::printf(" %14.1f %11.1f %13.0f\n", points / (run.compute_ms * 1e3), points / (run.total_ms * 1e3),
                run.first_ms);
    std::fflush(stdout);
  }

  const std::filesystem::path directory =
      std::filesystem::temp_directory_path() / ("nephele-bench-noise-" + std::to_string(::getpid()));
  std::filesystem::create_directories(directory);
  std::printf("presets, median of %d runs                  generate s   first run s   + write PNG s\n", repeat);
  for (const std::string name : {"shape", "erosion"}) {
    const noise::TextureSpec spec = noise::preset(name, 1);
    const studies::NoiseRun run = studies::measure_noise(generator, spec, repeat);
    const noise::Volume volume = generator.generate(spec);
    const double write_s = gpu::time_pass([&] {
                             io::write_noise_files(directory / (name + ".png"), spec, volume, 8, name, json::Value());
                           }) /
                           1e3;
    std::printf(
        "  %-42s %10.3f %13.3f %15.3f\n",
        (name + " " + std::to_string(spec.width) + "^3 " + std::to_string(spec.channels.size()) + " channels").c_str(),
        run.total_ms / 1e3, run.first_ms / 1e3, write_s);
    std::fflush(stdout);
  }
  std::error_code ignored;
  std::filesystem::remove_all(directory, ignored);
  std::printf(
      "reference (docs/noise.md): FastNoise2 2 threads: cellular F1 ~64, Perlin ~391 Mpt/s;\n"
      "TileableVolumeNoise: shape + erosion 24 s on two cores.\n");
  return exit_ok;
}

}  // namespace nephele::cli
