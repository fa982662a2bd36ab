#pragma once
// Reductions of the cover's cube maps on the GPU that leave only scalars to read back: the
// coverage threshold (a solid-angle weighted two-level histogram) and the warp diagnostics.
// The CPU versions (coverage_threshold.hpp, stability.hpp) are their reference; the tests
// compare the two. docs/performance.md gives the algorithm and its bounds.
#include <cstdint>
#include <vector>

#include "cover/coverage_threshold.hpp"
#include "cover/integrators.hpp"
#include "cover/stability.hpp"
#include "gpu/compute_program.hpp"
#include "gpu/textures.hpp"

namespace nephele::cover {

// Texel solid angles of one face as integers: units of 2^-scale_bits of the sphere, one entry
// per texel of the octant 0 <= a <= b < ceil(N/2) (index b (b + 1)/2 + a; the other texels
// by the face's symmetries). The scale puts the largest texel below 2^31 units, so a sum over
// 6 N^2 texels (N <= 16384) stays below 2^63.
struct TexelWeightUnits {
  int size = 0;
  int scale_bits = 0;
  std::vector<std::uint32_t> octant;
  double largest_fraction = 0.0;  // the largest texel's share of the sphere (exact, in double)
  double fraction(std::uint64_t units) const;  // units as a fraction of the sphere
  // Largest error of a sum over the whole cube map against the exact solid angles: each
  // entry is rounded to the nearest unit, half a unit per texel.
  double sum_error_bound() const;
};
TexelWeightUnits texel_weight_units(int size);

// The weight table uploaded once and bound to the binding texel_weights.glsl reads.
class GpuTexelWeights {
 public:
  explicit GpuTexelWeights(int size);
  ~GpuTexelWeights();
  GpuTexelWeights(const GpuTexelWeights&) = delete;
  GpuTexelWeights& operator=(const GpuTexelWeights&) = delete;
  const TexelWeightUnits& units() const { return units_; }
  void bind() const;

 private:
  TexelWeightUnits units_;
  unsigned buffer_ = 0;
};

// Texels listed at most by the last stage of the GPU calibration; a crossing fine bin with
// more texels (flat fields) is cut at its edges instead.
constexpr int calibration_member_capacity = 1 << 16;

// The threshold of calibrate_coverage computed on the GPU from `density` (an R32F cube map),
// reading back two histograms of 4096 64-bit sums and the texels of one fine bin. The
// threshold equals the CPU's whenever the fine bin that crosses the target holds at most
// calibration_member_capacity texels (always, unless about that many texels share nearly one
// density) and no two cuts are nearer the target than TexelWeightUnits::sum_error_bound();
// otherwise the cut is at an edge of that fine bin, of width (max - min) / 4096^2.
class GpuCalibration {
 public:
  explicit GpuCalibration(int size);
  CoverageCalibration run(const gpu::Texture& density, double target) const;
  const GpuTexelWeights& weights() const { return weights_; }

 private:
  int size_;
  GpuTexelWeights weights_;
  gpu::ComputeProgram program_{"cover/coverage_histogram.comp"};
};

// cover::diagnose_warp on the GPU: the curl and warp maps stay there, 7 integers and 6 doubles
// come back. The same figures as the CPU up to the texel directions, which the GPU rounds
// to float on its own (a few units in the last place; see tests/test_gpu_reductions.cpp for
// the resulting tolerances), and fractions summed in texel weight units.
class GpuDiagnosis {
 public:
  explicit GpuDiagnosis(int size);
  WarpDiagnostics run(const gpu::Texture& curl, const gpu::Texture& warp, Integrator integrator, double step) const;

 private:
  int size_;
  GpuTexelWeights weights_;
  gpu::ComputeProgram program_{"cover/warp_diagnostics.comp"};
};

}  // namespace nephele::cover
