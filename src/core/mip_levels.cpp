#include "core/mip_levels.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace nephele::core {

namespace {

// The weights of the source texels [first, first + count) under each of `to` destination texels
// along an axis of `from` texels: destination j covers [j r, (j + 1) r) with r = from / to.
struct AxisWeights {
  std::vector<int> first, count;
  std::vector<double> weights;  // count[j] entries for each j, in order, summing to 1 for each j
};

AxisWeights axis_weights(int from, int to) {
  AxisWeights a;
  const double r = double(from) / to;
  for (int j = 0; j < to; ++j) {
    const double begin = j * r, end = (j + 1) * r;
    const int lo = static_cast<int>(std::floor(begin)), hi = std::min(from, static_cast<int>(std::ceil(end)));
    a.first.push_back(lo);
    a.count.push_back(hi - lo);
    for (int i = lo; i < hi; ++i) a.weights.push_back((std::min(end, i + 1.0) - std::max(begin, double(i))) / r);
  }
  return a;
}

}  // namespace

std::vector<float> next_mip_level(const std::vector<float>& texels, int width, int height, int channels) {
  if (width < 1 || height < 1 || channels < 1 ||
      texels.size() != static_cast<size_t>(width) * static_cast<size_t>(height) * static_cast<size_t>(channels))
    throw std::invalid_argument("next_mip_level: the texels do not match width x height x channels");
  const int w = std::max(1, width / 2), h = std::max(1, height / 2);
  if (width % 2 == 0 && height % 2 == 0) {
    // Even sizes: each texel the mean of the 2 x 2 below it, summed in double as the general
    // path's weights of 1/2 (the same float), without its weight tables.
    std::vector<float> out(static_cast<size_t>(w) * h * channels);
    for (int y = 0; y < h; ++y) {
      const float* upper = &texels[static_cast<size_t>(2 * y) * width * channels];
      const float* lower = upper + static_cast<size_t>(width) * channels;
      float* target = &out[static_cast<size_t>(y) * w * channels];
      for (int x = 0; x < w; ++x)
        for (int c = 0; c < channels; ++c) {
          const size_t left = static_cast<size_t>(2 * x) * channels + c, right = left + channels;
          target[static_cast<size_t>(x) * channels + c] =
              static_cast<float>(0.5 * (0.5 * (double(upper[left]) + double(upper[right])) +
                                        0.5 * (double(lower[left]) + double(lower[right]))));
        }
    }
    return out;
  }
  const AxisWeights across = axis_weights(width, w), down = axis_weights(height, h);
  // Rows first (each source row reduced to w texels), then columns.
  std::vector<double> rows(static_cast<size_t>(w) * height * channels, 0.0);
  for (int y = 0; y < height; ++y) {
    size_t k = 0;
    for (int x = 0; x < w; ++x)
      for (int i = 0; i < across.count[x]; ++i, ++k) {
        const float* source = &texels[(static_cast<size_t>(y) * width + across.first[x] + i) * channels];
        double* target = &rows[(static_cast<size_t>(y) * w + x) * channels];
        for (int c = 0; c < channels; ++c) target[c] += across.weights[k] * source[c];
      }
  }
  std::vector<float> out(static_cast<size_t>(w) * h * channels);
  size_t k = 0;
  for (int y = 0; y < h; ++y) {
    std::vector<double> sum(static_cast<size_t>(w) * channels, 0.0);
    for (int i = 0; i < down.count[y]; ++i, ++k) {
      const double* source = &rows[static_cast<size_t>(down.first[y] + i) * w * channels];
      for (size_t n = 0; n < sum.size(); ++n) sum[n] += down.weights[k] * source[n];
    }
    std::copy(sum.begin(), sum.end(), out.begin() + static_cast<std::ptrdiff_t>(static_cast<size_t>(y) * w * channels));
  }
  return out;
}

std::vector<std::vector<float>> mip_levels(const std::vector<float>& level0, int width, int height, int channels,
                                           int levels) {
  std::vector<std::vector<float>> chain;
  chain.reserve(static_cast<size_t>(std::max(levels - 1, 0)));
  const std::vector<float>* previous = &level0;
  for (int level = 1; level < levels; ++level) {
    chain.push_back(next_mip_level(*previous, width, height, channels));
    width = std::max(1, width / 2);
    height = std::max(1, height / 2);
    previous = &chain.back();
  }
  return chain;
}

}  // namespace nephele::core
