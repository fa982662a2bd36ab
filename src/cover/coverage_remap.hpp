#pragma once
// Pass 4b and the calibration before it (docs/algorithm.md): the coverage thresholds from the
// densities of the whole cube map, handed over in parts (the whole map, or its tiles one by
// one: cube_tiles.hpp), then each part's cover. The sums are integers, so any cut into parts
// gives the thresholds and covers of the whole map to the bit.
#include <optional>
#include <utility>

#include "cover/cover_parameters.hpp"
#include "cover/coverage_threshold.hpp"
#include "cover/gpu_reductions.hpp"
#include "gpu/compute_program.hpp"

namespace nephele::cover {

// The maps the remap writes, of one region: the cover, the optical thickness, and the cloud-top
// height, which the density pass wrote and the remap clears where the texel stays clear.
struct CoverFields {
  const gpu::Texture& cover;
  const gpu::Texture& optical_thickness;
  const gpu::Texture& cloud_top;
};

class CoverageRemap {
 public:
  explicit CoverageRemap(const CoverParameters& parameters);
  // The reductions' buffers (the density pass reduces its range into them).
  const GpuCalibration& calibration() const { return calibration_; }
  // The threshold (--profile flat) or the band thresholds from every part's density; `range`
  // (smallest, largest) where the density passes reduced it, else found by a pass of its own.
  void calibrate(const DensityParts& parts, std::optional<std::pair<float, float>> range);
  // The remap of the parts, after calibrate: begin, each part's density into its fields (R32F
  // maps or tiles of the same region), and finish, which reads the achieved fractions back.
  // The optical thickness follows the rank of a texel's density among its band's cloudy texels,
  // from the calibration's coarse histograms (one more histogram for --profile flat).
  void begin_remap() const;
  // `contrast`: the density pass's cover contrast of the same region (cover_density.glsl).
  void remap(const gpu::Texture& density, const gpu::Texture& contrast, const CoverFields& fields,
             const CubeRegion& region) const;
  const CoverageCalibration& finish_remap();

  const CoverageCalibration& result() const { return result_; }
  // The latitude profile's calibration (absent with --profile flat).
  const std::optional<BandCalibration>& bands() const { return bands_; }

 private:
  CoverParameters parameters_;
  GpuCalibration calibration_;
  gpu::ComputeProgram remap_program_{"cover/cover_remap.comp"};
  CoverageCalibration result_;
  std::optional<BandCalibration> bands_;
  int tail_bands_ = 1;  // the densities' tails (GpuCalibration::set_band_tails): bands, range, scale
  float tail_min_ = 0.0f, tail_scale_ = 0.0f;
};

}  // namespace nephele::cover
