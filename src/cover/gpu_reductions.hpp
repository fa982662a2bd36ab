#pragma once
// Reductions of the cover's cube maps on the GPU that leave only scalars to read back: the
// coverage threshold (a solid-angle weighted two-level histogram) and the warp diagnostics.
// The CPU versions (coverage_threshold.hpp, stability.hpp) are their reference; the tests
// compare the two. docs/performance.md gives the algorithm and its bounds.
#include <cstdint>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include "cover/coverage_threshold.hpp"
#include "cover/cube_tiles.hpp"
#include "cover/integrators.hpp"
#include "cover/stability.hpp"
#include "gpu/compute_program.hpp"
#include "gpu/textures.hpp"

namespace nephele::cover {

// Texels per invocation of the reduction passes, a strip down a column: at least 32, so that
// an invocation's atomics and partial record are shared by many texels (on llvmpipe, 1024 per
// face: 8 texels 1.6 times slower than 32), and enough that 6 N^2 texels make at most 2^20
// partial records (4096 per face: strips of 96). The density and remap passes, which reduce
// as they write, walk the same strips.
int reduction_strip(int size);
// The diagnosis's strips, four times as long: its texels read nine map values and work in
// double, and on llvmpipe fewer, longer strips (fewer partial records to store and fold) made
// the pass about 17 % faster at 1024 per face. 4096 per face still has 2^18 strips for a GPU.
int diagnosis_strip(int size);
// The density pass's strips: reduction_strip, at most 96 texels. Each texel runs the noise's
// loops (a Worley search per octave, two cloud layers), and llvmpipe ends an invocation's loops
// silently after 65535 iterations in all (integrators.hpp, shader_loop_budget): at 16384 per
// face the 1536-texel strips lost the second half of every strip (density 0, cloud fraction
// 0.588 instead of 0.67). At 4096 and below the strip is reduction_strip's, as before.
int density_strip(int size);

// Texel solid angles of one face as integers: units of 2^-scale_bits of the sphere, one entry
// per texel of the octant 0 <= a <= b < ceil(N/2) (index b (b + 1)/2 + a; the other texels
// by the face's symmetries). The scale puts the largest texel below 2^31 units, so a sum over
// 6 N^2 texels (N <= 16384) stays below 2^63.
struct TexelWeightUnits {
  int size = 0;
  int scale_bits = 0;
  std::vector<std::uint32_t> octant;
  double largest_fraction = 0.0;               // the largest texel's share of the sphere (exact, in double)
  double fraction(std::uint64_t units) const;  // units as a fraction of the sphere
  // Largest error of a sum over the whole cube map against the exact solid angles: each
  // entry is rounded to the nearest unit, half a unit per texel.
  double sum_error_bound() const;
};
TexelWeightUnits texel_weight_units(int size);

// The weight table uploaded once (a buffer texture, R32UI) and bound to the texture unit
// texel_weights.glsl reads.
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
  unsigned texture_ = 0;  // a buffer texture of buffer_ (texel_weights.glsl)
};

// One part of a density map (R32F) that the reductions read: a whole cube map, or a tile of it
// (cube_tiles.hpp) whose owned rows they count.
struct DensityPart {
  const gpu::Texture& density;
  CubeRegion region;
};
// The parts of a density map, each handed to `use` in turn: a reduction binds and reads one part
// at a time, so that tiles may come from files one by one. The sums are the same in any order.
using DensityParts = std::function<void(const std::function<void(const DensityPart&)>& use)>;
// A whole cube map as its one part.
DensityParts whole_cube(const gpu::Texture& density);

// Bytes of GPU memory the calibration and the diagnosis allocate for a cube face size: two
// weight tables, the listed texels, the histograms and the diagnosis's partial records.
double reduction_gpu_bytes(int size);

// Texels listed at most by the GPU calibration; a crossing bin with more texels is refined
// into 4096 fine bins, and a crossing fine bin with more (flat fields) is cut at its edges.
constexpr int calibration_member_capacity = 1 << 16;

// The threshold of calibrate_coverage computed on the GPU from `density` (an R32F cube map).
// Stages: the density range; a solid-angle weighted histogram of 4096 bins (64-bit sums of
// texel weight units) that finds the bin where the cloudy fraction crosses the target; the
// texels of that bin listed, sorted and cut on the host as the CPU does (a second histogram
// level of 4096 fine bins first where the bin holds more than calibration_member_capacity).
// Read back: two words, one or two histograms of 4096 sums, the listed texels.
// Bound: the threshold is the CPU's, and the cloudy fraction within
// TexelWeightUnits::sum_error_bound() of the CPU's, unless two cuts are that near to being
// equally far from the target (either may be taken) or the crossing fine bin holds more than
// calibration_member_capacity texels; then all or none of that bin is cloudy, whichever is
// nearer the target, which is never further from it than the CPU's cut (whose fraction error
// is at most one texel's share of the sphere, or the bin's share for equal densities).
class GpuCalibration {
 public:
  explicit GpuCalibration(int size);
  ~GpuCalibration();
  GpuCalibration(const GpuCalibration&) = delete;
  GpuCalibration& operator=(const GpuCalibration&) = delete;
  // The density range: found by a pass of its own (stage 0), or, with range_from_density_pass,
  // the one cover_density.comp reduced into the buffer bind_density_range bound before it.
  CoverageCalibration run(const gpu::Texture& density, double target, bool range_from_density_pass = false) const;
  // The same over the parts of a density map; `range`: its smallest and largest density where
  // known (the density passes reduced them), else found by a pass over the parts.
  CoverageCalibration run(const DensityParts& parts, double target,
                          std::optional<std::pair<float, float>> range = std::nullopt) const;
  // cover::calibrate_band_coverage on the GPU (stages 0, 6, 7 of coverage_histogram.comp; one
  // target per band): read back are two words and two tables of bands x band_bins 64-bit sums.
  // The thresholds stay in a buffer for the remap pass (bind_band_thresholds).
  // Bound: the histograms are the CPU's up to the texels whose centre the GPU's and the CPU's
  // float latitude put in different bands (within a few ulp of a band edge) and the rounding
  // of the solid angles to units (TexelWeightUnits::sum_error_bound per band); so are the
  // thresholds, which move with the histograms continuously within one fine bin.
  BandCalibration run_bands(const gpu::Texture& density, const std::vector<double>& targets,
                            bool range_from_density_pass = false) const;
  BandCalibration run_bands(const DensityParts& parts, const std::vector<double>& targets,
                            std::optional<std::pair<float, float>> range = std::nullopt) const;
  // Stage 6 alone: bands x band_bins weights (fractions of the sphere) over [density_min, ...)
  // at `scale` bins per unit density (run_bands keeps its own in BandCalibration::histogram).
  std::vector<double> coarse_histogram(const DensityParts& parts, int bands, float density_min, float scale) const;
  // The achieved fractions at the smooth threshold of `calibration` (stage 8), in place.
  void measure_bands(const gpu::Texture& density, BandCalibration& calibration) const;
  // The same measured by the remap pass (cover_remap.comp) as it writes the cover: bind before
  // that pass (binding 9 cleared, and the weights), read after it.
  void bind_band_cloudy() const;
  void read_band_cloudy(BandCalibration& calibration) const;
  // Resets the density range to empty and binds it (binding 8 of cover_density.comp).
  void bind_density_range() const;
  // The range the density passes reduced since bind_density_range (smallest, largest).
  std::pair<float, float> read_density_range() const;
  // Binds the thresholds of the last run_bands (binding 6 of band_thresholds.glsl).
  void bind_band_thresholds() const;
  // The densities' tails per band (band_tails) for the remap's ranks: kept, then bound
  // (binding 10 of band_tails.glsl).
  void set_band_tails(const std::vector<float>& tails) const;
  void bind_band_tails() const;
  const GpuTexelWeights& weights() const { return weights_; }

 private:
  std::pair<float, float> density_range(const DensityParts& parts) const;  // stage 0
  // Dispatches the program's current stage over every part's owned rows.
  void dispatch_parts(const DensityParts& parts) const;
  void set_achieved(const std::vector<std::uint64_t>& cloudy, BandCalibration& calibration) const;
  std::vector<std::uint64_t> band_histogram(const DensityParts& parts, int stage, int bands, float density_min,
                                            float scale) const;
  int size_;
  GpuTexelWeights weights_;
  gpu::ComputeProgram program_{"cover/coverage_histogram.comp"};
  unsigned band_thresholds_ = 0;  // a float per band
  unsigned band_crossing_ = 0;    // (bin, lower edge bits) per band
  unsigned density_range_ = 0;    // sortable bits of the smallest and largest density
  unsigned band_cloudy_ = 0;      // a 64-bit sum of units per band (the remap's measurement)
  unsigned band_tails_ = 0;       // band_bins + 1 floats per band (band_tails)
};

// cover::diagnose_warp on the GPU: the curl and warp maps stay there, 7 integers and 6 doubles
// come back. The same figures as the CPU up to the texel directions, which the GPU rounds
// to float on its own (a few units in the last place; see tests/test_gpu_reductions.cpp for
// the resulting tolerances), and fractions summed in texel weight units.
// The diagnosis's sums over a part of the cube map (cube_tiles.hpp), which `add` combines over
// the parts: the integer figures exactly, the extremes exactly, the double sums to rounding.
struct DiagnosisSums {
  std::uint64_t folded_units = 0, beyond_units = 0;  // texel weight units
  std::uint64_t capped_texels = 0, off_sphere_texels = 0;
  double max_attempts = 0.0;
  double max_rate = 0.0;  // largest spectral radius of the velocity gradient
  double jacobian_min = 1.0e300, jacobian_max = -1.0e300;
  double error_sum = 0.0, weight_sum = 0.0;  // sums of w (J - 1)^2 and w over texels with neighbours
  double attempts_sum = 0.0;
  void add(const DiagnosisSums& other);
};
// The figures from the sums over every texel of a cube map of `size` texels per face.
WarpDiagnostics diagnostics_from_sums(const DiagnosisSums& sums, const TexelWeightUnits& units, Integrator integrator,
                                      double step, bool moving);

class GpuDiagnosis {
 public:
  explicit GpuDiagnosis(int size);
  // `moving`: the moving flow's warp (its warnings do not offer the adaptive integrator).
  WarpDiagnostics run(const gpu::Texture& curl, const gpu::Texture& warp, Integrator integrator, double step,
                      bool moving = false) const;
  // The sums over the owned rows of `region`, whose rows the maps hold (the halo included).
  DiagnosisSums sums(const gpu::Texture& curl, const gpu::Texture& warp, const CubeRegion& region,
                     Integrator integrator, double step) const;
  const TexelWeightUnits& units() const { return weights_.units(); }

 private:
  int size_;
  GpuTexelWeights weights_;
  gpu::ComputeProgram program_{"cover/warp_diagnostics.comp"};
};

}  // namespace nephele::cover
