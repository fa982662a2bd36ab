#pragma once
// Calibration of the density threshold so that a given fraction of the sphere is cloudy.
#include <vector>

#include "shader_math/shader_math.hpp"

namespace nephele::cover {

struct CoverageCalibration {
  float threshold = 0.0f;  // texels with density > threshold are cloudy
  float density_min = 0.0f;
  float density_max = 0.0f;
  double achieved_fraction = 0.0;   // solid-angle fraction of texels with density > threshold
  double max_texel_fraction = 0.0;  // the largest single texel's share of the sphere
};

// `densities`: a cube map, 6 faces of size x size texels in GL order.
// Chooses the threshold whose cloudy fraction (weighted by texel solid angle) is nearest to
// `target` (0..1), so |achieved - target| <= one texel's share of the sphere when densities are
// distinct. Runs in linear time: a weighted histogram finds the bin, a sort finishes inside it.
CoverageCalibration calibrate_coverage(const std::vector<float>& densities, int size, double target);

// The latitude profile's calibration (docs/climate.md): a threshold per latitude band
// (latitude_bands.glsl), each reaching its band's target fraction, found from two levels of
// solid-angle weighted histograms per band: band_bins bins over [min, max], then band_bins fine
// bins inside the bin where the band's cloudy fraction crosses its target, the threshold placed
// inside the crossing fine bin as if its texels were spread evenly over it. The remap pass then
// blends the thresholds smoothly between band centres (smooth_band_threshold).
constexpr int band_bins = 256;

struct BandCalibration {
  float density_min = 0.0f, density_max = 0.0f;
  std::vector<double> targets;      // per band, the fraction of the band's solid angle
  std::vector<float> thresholds;    // per band (at its centre)
  std::vector<double> achieved;     // per band: cloudy fraction at the smooth threshold
  std::vector<double> band_weight;  // per band: its texels' share of the sphere
  double achieved_fraction = 0.0;   // the sphere's cloudy fraction at the smooth threshold
  // The coarse level: bands x band_bins weights (fractions of the sphere) over [min, max] at
  // bin_scale bins per unit density (band_bin_scale), for the densities' tails (band_tails).
  std::vector<double> histogram;
  float bin_scale = 0.0f;
};

// Per band, the share of its weight in the bins at and above each bin: band_bins + 1 values a
// band, from 1 at bin 0 down to 0 past the last bin (a band without weight: 1 - k / band_bins),
// for the remap's ranks of cloudy texels (shaders/cover/band_tails.glsl). `histogram` holds
// bands x band_bins weights.
std::vector<float> band_tails(const std::vector<double>& histogram, int bands);

// Bins per unit density of the coarse level: band_bins / (max - min) in float, 0 when all
// densities are equal (or nearly) so that every texel falls in bin 0.
float band_bin_scale(float density_min, float density_max);

// Where each band's cumulative weight, summed from the densest bin down, reaches its target:
// the coarse bin, its lower edge, and the weights above it and of the whole band. `coarse`
// holds bands x band_bins weights (any unit, the same as the fine level's).
struct BandCrossing {
  int bin = 0;
  float low = 0.0f;     // lower edge of the bin: min + bin / scale, rounded to float
  double above = 0.0;   // weight in the band's bins above `bin`
  double total = 0.0;   // the band's weight
  double needed = 0.0;  // target x total
};
std::vector<BandCrossing> band_crossings(const std::vector<double>& coarse, const std::vector<double>& targets,
                                         float density_min, float scale);
// The thresholds from the crossings and the fine level (bands x band_bins weights). Bands
// without texels (small maps) take the threshold interpolated linearly between the nearest
// bands with texels.
std::vector<float> band_thresholds(const std::vector<BandCrossing>& crossings, const std::vector<double>& fine,
                                   float density_min, float density_max, float scale);

// The threshold at a unit direction: the band thresholds blended by Catmull-Rom between band
// centres (band_thresholds.glsl; the C++ twin of the remap pass's).
float smooth_band_threshold(const std::vector<float>& thresholds, const glsl::vec3& direction);

// The CPU reference of GpuCalibration::run_bands: the same histograms with the solid angles of
// face_texel_solid_angles, the same thresholds, and the achieved fractions at the smooth
// threshold.
BandCalibration calibrate_band_coverage(const std::vector<float>& densities, int size,
                                        const std::vector<double>& targets);
// The achieved fractions of a calibration (its thresholds, its targets) measured on the CPU.
void measure_band_coverage(const std::vector<float>& densities, int size, BandCalibration& calibration);

// Solid-angle fraction of the sphere where cover > 0.
double cloudy_fraction(const std::vector<float>& cover, int size);

}  // namespace nephele::cover
