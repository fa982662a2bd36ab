#pragma once
// The measurements behind `nephele bench`: each runs the real passes a number of times and
// returns medians; the command line only prints them (docs/performance.md).
#include <string>
#include <vector>

#include "cover/cover_parameters.hpp"
#include "model/cloud_model.hpp"
#include "model/density_volume.hpp"
#include "noise/noise_spec.hpp"
#include "noise/noise_texture.hpp"

namespace nephele::studies {

// The middle element (the upper one of an even count); `values` must not be empty.
double median(std::vector<double> values);

// --- bench cover
// The passes `bench cover` reports, in order (the equirect resampling last).
const std::vector<std::string>& cover_bench_passes();
struct CoverBenchRow {
  int size = 0;
  std::vector<double> device_ms;  // per pass of cover_bench_passes(): GL_TIME_ELAPSED, else wall clock
  bool wall_fallback = false;     // the driver gave no device time for some pass
  double wall_ms = 0, read_ms = 0, encode_ms = 0, megabytes = 0;  // medians
  // The first run's passes (wall clock), left out of the medians: the driver compiles the shaders
  // there, or reads them from its disk cache (llvmpipe: seconds when they are not cached).
  double first_ms = 0;
};
// Runs the cover of `parameters` at `size` once and then `repeat` times for the medians. Needs a
// current OpenGL 4.5 context.
CoverBenchRow bench_cover_size(cover::CoverParameters parameters, int size, int repeat);

// --- bench noise
struct NoiseRun {
  double first_ms = 0;    // first generate(): shader compilation (or cache lookup) included
  double compute_ms = 0;  // median: until the values are in GPU memory (wall clock)
  double device_ms = 0;   // median: the dispatches' GPU time (GL_TIME_ELAPSED; 0: none from the driver)
  double total_ms = 0;    // median: until they are interleaved in host memory
};
// Into one host array, as FastNoise's benchmarks fill a caller's array.
NoiseRun measure_noise(noise::TextureGenerator& generator, const noise::TextureSpec& spec, int repeat);
struct NoiseBenchCase {
  const char* name;
  noise::TextureSpec spec;
};
// Worley F1, Perlin and 4-octave fBm of both on a size^3 grid (FastNoise's figures count so).
std::vector<NoiseBenchCase> noise_bench_cases(int size);

// --- bench model
// n primitives spread over a cumulus field in a fixed pattern (golden-angle spiral), so that
// the figures for 1, 5, 10 and 50 primitives describe comparable clouds.
model::CloudModel spiral_of_cumuli(int n, model::Blend blend);
struct ModelBenchRow {
  int primitives = 0;
  model::Blend blend = model::Blend::per_primitive;
  double full_ms = 0, edit_ms = 0;                // medians
  double full_occupancy = 0, edit_occupancy = 0;  // fraction of bricks computed
};
// A full volume and one-primitive edits (the first primitive moved by a brick and back) of
// spiral_of_cumuli(primitives, blend), in `volume` (shared by the cases). Needs a current
// OpenGL 4.5 context.
ModelBenchRow bench_model_case(model::DensityVolume& volume, int primitives, model::Blend blend, int repeat);

}  // namespace nephele::studies
