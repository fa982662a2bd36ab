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

class CoverageRemap {
 public:
  explicit CoverageRemap(const CoverParameters& parameters);
  // The reductions' buffers (the density pass reduces its range into them).
  const GpuCalibration& calibration() const { return calibration_; }
  // The threshold (--profile flat) or the band thresholds from every part's density; `range`
  // (smallest, largest) where the density passes reduced it, else found by a pass of its own.
  void calibrate(const DensityParts& parts, std::optional<std::pair<float, float>> range);
  // The remap of the parts, after calibrate: begin, each part's density into its cover (an
  // R32F map or tile of the same region), and finish, which reads the achieved fractions back.
  void begin_remap() const;
  void remap(const gpu::Texture& density, const gpu::Texture& cover, const CubeRegion& region) const;
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
};

}  // namespace nephele::cover
