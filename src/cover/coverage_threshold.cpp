#include "cover/coverage_threshold.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "cover/solid_angle.hpp"

namespace nephele::cover {

CoverageCalibration calibrate_coverage(const std::vector<float>& densities, int size, double target) {
  const size_t per_face = static_cast<size_t>(size) * size;
  if (densities.size() != 6 * per_face) throw std::invalid_argument("calibrate_coverage: wrong size");
  const std::vector<double> weights = face_texel_solid_angles(size);
  const double sphere = 4.0 * M_PI;
  const auto weight_of = [&](size_t index) { return weights[index % per_face] / sphere; };

  CoverageCalibration result;
  const auto [lowest, highest] = std::minmax_element(densities.begin(), densities.end());
  result.density_min = *lowest;
  result.density_max = *highest;
  result.max_texel_fraction = *std::max_element(weights.begin(), weights.end()) / sphere;

  // Walk down from the densest texel, accumulating the cloudy fraction, until the target is
  // reached. First coarsely through histogram bins, then texel by texel in the bin that crosses.
  const int bins = 4096;
  const double span = static_cast<double>(result.density_max) - result.density_min;
  auto bin_of = [&](float d) {
    if (span <= 0.0) return 0;
    return std::min(bins - 1, static_cast<int>((d - result.density_min) / span * bins));
  };
  std::vector<double> bin_weight(bins, 0.0);
  for (size_t k = 0; k < densities.size(); ++k) bin_weight[bin_of(densities[k])] += weight_of(k);

  double above = 0.0;  // fraction strictly in bins above `bin`
  int bin = bins - 1;
  while (bin > 0 && above + bin_weight[bin] < target) above += bin_weight[bin--];

  std::vector<std::pair<float, double>> members;  // (density, weight) of texels in the bin
  for (size_t k = 0; k < densities.size(); ++k)
    if (bin_of(densities[k]) == bin) members.emplace_back(densities[k], weight_of(k));
  std::sort(members.begin(), members.end(), [](const auto& a, const auto& b) { return a.first > b.first; });

  // Candidate cut after `count` members: cloudy fraction above + their weights. Choose the
  // count whose fraction is nearest to the target.
  double best_error = std::abs(above - target);
  size_t best_count = 0;
  double cumulative = above;
  for (size_t count = 1; count <= members.size(); ++count) {
    cumulative += members[count - 1].second;
    const double error = std::abs(cumulative - target);
    if (error < best_error) {
      best_error = error;
      best_count = count;
    }
  }
  // The cloudy set is every texel in higher bins plus the first best_count members; the
  // threshold is the largest density outside it, so that density > threshold <=> cloudy.
  float threshold = std::nextafter(result.density_min, -INFINITY);
  if (best_count < members.size()) {
    threshold = members[best_count].first;
  } else {
    for (float d : densities)
      if (bin_of(d) < bin) threshold = std::max(threshold, d);
  }
  result.threshold = threshold;
  double achieved = 0.0;
  for (size_t k = 0; k < densities.size(); ++k)
    if (densities[k] > threshold) achieved += weight_of(k);
  result.achieved_fraction = achieved;
  return result;
}

double cloudy_fraction(const std::vector<float>& cover, int size) {
  const size_t per_face = static_cast<size_t>(size) * size;
  const std::vector<double> weights = face_texel_solid_angles(size);
  double cloudy = 0.0;
  for (size_t k = 0; k < cover.size(); ++k)
    if (cover[k] > 0.0f) cloudy += weights[k % per_face];
  return cloudy / (4.0 * M_PI);
}

}  // namespace nephele::cover

namespace nephele::cover {

float band_bin_scale(float density_min, float density_max) {
  const double span = static_cast<double>(density_max) - density_min;
  const double scale = span > 0.0 ? band_bins / span : 0.0;
  return std::isfinite(scale) && scale < std::numeric_limits<float>::max() ? static_cast<float>(scale) : 0.0f;
}

std::vector<BandCrossing> band_crossings(const std::vector<double>& coarse, const std::vector<double>& targets,
                                         float density_min, float scale) {
  const size_t bands = targets.size();
  if (coarse.size() != bands * band_bins) throw std::invalid_argument("band_crossings: wrong histogram size");
  std::vector<BandCrossing> out(bands);
  for (size_t b = 0; b < bands; ++b) {
    const double* h = &coarse[b * band_bins];
    BandCrossing& c = out[b];
    for (int k = 0; k < band_bins; ++k) c.total += h[k];
    c.needed = targets[b] * c.total;
    // Down from the densest bin while the cloudy weight stays below the need, as
    // calibrate_coverage walks its bins.
    int bin = band_bins - 1;
    while (bin > 0 && c.above + h[bin] < c.needed) c.above += h[bin--];
    c.bin = bin;
    c.low = scale > 0.0f ? static_cast<float>(density_min + bin / static_cast<double>(scale)) : density_min;
  }
  return out;
}

std::vector<float> band_thresholds(const std::vector<BandCrossing>& crossings, const std::vector<double>& fine,
                                   float density_min, float density_max, float scale) {
  const int bands = static_cast<int>(crossings.size());
  // Nothing cloudy: a threshold one span above the largest density, so that the float blend of
  // equal neighbours (whose weights sum to 1 only within rounding) stays above every density.
  const float none_cloudy = density_max + std::max(density_max - density_min, 1.0f);
  const float all_cloudy = std::nextafter(density_min, -INFINITY);
  std::vector<float> thresholds(static_cast<size_t>(bands), 0.0f);
  std::vector<int> filled;
  for (int b = 0; b < bands; ++b) {
    const BandCrossing& c = crossings[b];
    if (c.total <= 0.0) continue;
    filled.push_back(b);
    float& t = thresholds[b];
    if (c.needed <= 0.0) {
      t = none_cloudy;
    } else if (c.needed >= c.total) {
      t = all_cloudy;
    } else if (scale <= 0.0f) {
      // One density everywhere: all or nothing, whichever is nearer the target.
      t = c.needed >= 0.5 * c.total ? all_cloudy : none_cloudy;
    } else {
      const double* h = &fine[static_cast<size_t>(b) * band_bins];
      double above = c.above;
      int bin = band_bins - 1;
      while (bin > 0 && above + h[bin] < c.needed) above += h[bin--];
      // The cloudy share q of the crossing fine bin lies at its top, its texels taken as spread
      // evenly over the bin's width.
      const double q = h[bin] > 0.0 ? std::clamp((c.needed - above) / h[bin], 0.0, 1.0) : 0.0;
      const double width = 1.0 / (static_cast<double>(scale) * band_bins);
      t = static_cast<float>(c.low + (bin + 1.0 - q) * width);
    }
  }
  if (filled.empty()) return thresholds;
  // Bands without texels: linear between the nearest filled bands (constant beyond the ends).
  for (int b = 0; b < bands; ++b) {
    if (crossings[b].total > 0.0) continue;
    const auto next = std::lower_bound(filled.begin(), filled.end(), b);
    if (next == filled.begin())
      thresholds[b] = thresholds[*next];
    else if (next == filled.end())
      thresholds[b] = thresholds[filled.back()];
    else {
      const int lo = *(next - 1), hi = *next;
      thresholds[b] = thresholds[lo] + (thresholds[hi] - thresholds[lo]) * static_cast<float>(b - lo) / (hi - lo);
    }
  }
  return thresholds;
}

float smooth_band_threshold(const std::vector<float>& thresholds, const glsl::vec3& direction) {
  const int bands = static_cast<int>(thresholds.size());
  const float c = glsl::band_coordinate(direction, bands);
  const glsl::ivec4 k = glsl::band_neighbours(c, bands);
  const glsl::vec4 values(thresholds[k.x], thresholds[k.y], thresholds[k.z], thresholds[k.w]);
  return glsl::dot(glsl::catmull_rom_weights(glsl::band_fraction(c, bands)), values);
}

namespace {

// Calls visit(index, face texel weight (fraction of the sphere), direction, band) for every texel.
template <class Visit>
void for_each_band_texel(int size, int bands, Visit&& visit) {
  const size_t per_face = static_cast<size_t>(size) * size;
  const std::vector<double> weights = face_texel_solid_angles(size);
  for (int face = 0; face < 6; ++face)
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i) {
        const size_t in_face = static_cast<size_t>(j) * size + i;
        const glsl::vec3 direction = glsl::texel_direction(face, i, j, size);
        const int band = glsl::band_of(glsl::band_coordinate(direction, bands), bands);
        visit(face * per_face + in_face, weights[in_face] / (4.0 * M_PI), direction, band);
      }
}

}  // namespace

void measure_band_coverage(const std::vector<float>& densities, int size, BandCalibration& c) {
  const int bands = static_cast<int>(c.thresholds.size());
  std::vector<double> cloudy(static_cast<size_t>(bands), 0.0);
  c.band_weight.assign(static_cast<size_t>(bands), 0.0);
  for_each_band_texel(size, bands, [&](size_t k, double weight, const glsl::vec3& direction, int band) {
    c.band_weight[band] += weight;
    if (densities[k] > smooth_band_threshold(c.thresholds, direction)) cloudy[band] += weight;
  });
  c.achieved.assign(static_cast<size_t>(bands), 0.0);
  c.achieved_fraction = 0.0;
  for (int b = 0; b < bands; ++b) {
    c.achieved[b] = c.band_weight[b] > 0.0 ? cloudy[b] / c.band_weight[b] : 0.0;
    c.achieved_fraction += cloudy[b];
  }
}

BandCalibration calibrate_band_coverage(const std::vector<float>& densities, int size,
                                        const std::vector<double>& targets) {
  if (densities.size() != 6 * static_cast<size_t>(size) * size)
    throw std::invalid_argument("calibrate_band_coverage: wrong size");
  const int bands = static_cast<int>(targets.size());
  BandCalibration c;
  c.targets = targets;
  const auto [lowest, highest] = std::minmax_element(densities.begin(), densities.end());
  c.density_min = *lowest;
  c.density_max = *highest;
  const float scale = band_bin_scale(c.density_min, c.density_max);
  // The bins as the GPU computes them (coverage_histogram.comp, stages 6 and 7), in float.
  auto coarse_bin = [&](float d) { return std::min(band_bins - 1, static_cast<int>((d - c.density_min) * scale)); };
  std::vector<double> coarse(static_cast<size_t>(bands) * band_bins, 0.0), fine(coarse.size(), 0.0);
  for_each_band_texel(size, bands, [&](size_t k, double weight, const glsl::vec3&, int band) {
    coarse[static_cast<size_t>(band) * band_bins + coarse_bin(densities[k])] += weight;
  });
  const std::vector<BandCrossing> crossings = band_crossings(coarse, targets, c.density_min, scale);
  const float fine_scale = scale * static_cast<float>(band_bins);
  for_each_band_texel(size, bands, [&](size_t k, double weight, const glsl::vec3&, int band) {
    const float d = densities[k];
    if (coarse_bin(d) != crossings[band].bin) return;
    const int bin = std::clamp(static_cast<int>((d - crossings[band].low) * fine_scale), 0, band_bins - 1);
    fine[static_cast<size_t>(band) * band_bins + bin] += weight;
  });
  c.thresholds = band_thresholds(crossings, fine, c.density_min, c.density_max, scale);
  measure_band_coverage(densities, size, c);
  return c;
}

std::vector<float> band_tails(const std::vector<double>& histogram, int bands) {
  if (bands < 1 || histogram.size() != static_cast<size_t>(bands) * band_bins)
    throw std::invalid_argument("band_tails: the histogram is not bands x band_bins weights");
  std::vector<float> tails(static_cast<size_t>(bands) * (band_bins + 1));
  for (int b = 0; b < bands; ++b) {
    const double* weights = histogram.data() + static_cast<size_t>(b) * band_bins;
    float* tail = tails.data() + static_cast<size_t>(b) * (band_bins + 1);
    double total = 0.0;
    for (int k = 0; k < band_bins; ++k) total += weights[k];
    double above = 0.0;  // summed from the densest bin down, so that the last values are exact
    tail[band_bins] = 0.0f;
    for (int k = band_bins - 1; k >= 0; --k) {
      above += weights[k];
      tail[k] = total > 0.0 ? static_cast<float>(above / total) : static_cast<float>(band_bins - k) / band_bins;
    }
  }
  return tails;
}

}  // namespace nephele::cover
