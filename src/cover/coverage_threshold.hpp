#pragma once
// Calibration of the density threshold so that a given fraction of the sphere is cloudy.
#include <vector>

namespace nephele::cover {

struct CoverageCalibration {
  float threshold = 0.0f;          // texels with density > threshold are cloudy
  float density_min = 0.0f;
  float density_max = 0.0f;
  double achieved_fraction = 0.0;  // solid-angle fraction of texels with density > threshold
  double max_texel_fraction = 0.0; // the largest single texel's share of the sphere
};

// `densities`: a cube map, 6 faces of size x size texels in GL order.
// Chooses the threshold whose cloudy fraction (weighted by texel solid angle) is nearest to
// `target` (0..1), so |achieved - target| <= one texel's share of the sphere when densities are
// distinct. Runs in linear time: a weighted histogram finds the bin, a sort finishes inside it.
CoverageCalibration calibrate_coverage(const std::vector<float>& densities, int size, double target);

// Solid-angle fraction of the sphere where cover > 0.
double cloudy_fraction(const std::vector<float>& cover, int size);

}  // namespace nephele::cover
