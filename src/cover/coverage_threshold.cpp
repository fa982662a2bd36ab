#include "cover/coverage_threshold.hpp"

#include <algorithm>
#include <cmath>
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
  std::sort(members.begin(), members.end(),
            [](const auto& a, const auto& b) { return a.first > b.first; });

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
