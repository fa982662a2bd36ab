#include "render/exposure.hpp"

#include <algorithm>
#include <cstddef>
#include <vector>

namespace nephele::render {

double highlight_exposure(const core::ImageData& radiance, double fallback, double sunlit_white) {
  std::vector<double> lit;
  if (radiance.channels >= 3) {
    for (std::size_t k = 0; k + 2 < radiance.pixels.size(); k += radiance.channels) {
      const double y = 0.2126 * radiance.pixels[k] + 0.7152 * radiance.pixels[k + 1] + 0.0722 * radiance.pixels[k + 2];
      if (y > kLitLuminance) lit.push_back(y);
    }
  }
  if (lit.empty()) return fallback;
  const std::size_t at = static_cast<std::size_t>(kHighlightPercentile * double(lit.size() - 1));
  std::nth_element(lit.begin(), lit.begin() + static_cast<std::ptrdiff_t>(at), lit.end());
  double exposure = kHighlightKey / lit[at];
  if (sunlit_white > 0.0) exposure = std::min(exposure, kHighlightKey / sunlit_white);
  return std::clamp(exposure, fallback / 4, fallback * 4);
}

}  // namespace nephele::render
