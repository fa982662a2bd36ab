#include "files/mip_chain.hpp"

#include <algorithm>
#include <stdexcept>

namespace nephele::files {
namespace {

// One axis of the area-weighted box: output texel o of m covers [o n/m, (o + 1) n/m) of the n
// input texels; input texel k weighs the length of [k, k + 1) inside it, over n/m.
struct Tap {
  int first = 0;
  std::vector<double> weights;
};
std::vector<Tap> area_taps(int n, int m) {
  std::vector<Tap> taps(m);
  const double ratio = double(n) / double(m);
  for (int o = 0; o < m; ++o) {
    const double lo = o * ratio, hi = (o + 1) * ratio;
    Tap& tap = taps[o];
    tap.first = int(lo);
    for (int k = tap.first; k < n && k < hi; ++k)
      tap.weights.push_back((std::min(hi, double(k + 1)) - std::max(lo, double(k))) / ratio);
  }
  return taps;
}

// One image of w x h (c channels) reduced to the next level's size.
void reduce(const float* in, int w, int h, int c, int w2, int h2, float* out) {
  const std::vector<Tap> across = area_taps(w, w2), down = area_taps(h, h2);
  std::vector<double> row(std::size_t(w2) * c);
  for (int y = 0; y < h2; ++y) {
    std::vector<double> sum(std::size_t(w2) * c, 0.0);
    const Tap& ty = down[y];
    for (std::size_t a = 0; a < ty.weights.size(); ++a) {
      const float* source = in + std::size_t(ty.first + a) * w * c;
      for (int x = 0; x < w2; ++x) {
        const Tap& tx = across[x];
        for (int ch = 0; ch < c; ++ch) {
          double v = 0.0;
          for (std::size_t b = 0; b < tx.weights.size(); ++b) v += tx.weights[b] * source[(tx.first + b) * c + ch];
          sum[std::size_t(x) * c + ch] += ty.weights[a] * v;
        }
      }
    }
    for (std::size_t i = 0; i < sum.size(); ++i) out[std::size_t(y) * w2 * c + i] = float(sum[i]);
  }
}

}  // namespace

int full_mip_count(int width, int height) {
  int levels = 1;
  for (int edge = std::max(width, height); edge > 1; edge >>= 1) ++levels;
  return levels;
}

MipChain build_mip_chain(std::vector<float> base, int width, int height, int layers, int channels, int levels) {
  if (width < 1 || height < 1 || layers < 1 || channels < 1 ||
      base.size() != std::size_t(width) * std::size_t(height) * std::size_t(layers) * std::size_t(channels))
    throw std::invalid_argument("mip chain: the texels do not match the image size");
  MipChain chain{width, height, layers, channels, {}};
  const int count = levels > 0 ? std::min(levels, full_mip_count(width, height)) : full_mip_count(width, height);
  chain.levels.reserve(count);
  chain.levels.push_back(std::move(base));
  for (int k = 1; k < count; ++k) {
    const int w = chain.level_width(k - 1), h = chain.level_height(k - 1);
    const int w2 = chain.level_width(k), h2 = chain.level_height(k);
    std::vector<float> next(chain.image_floats(k) * layers);
    for (int layer = 0; layer < layers; ++layer)
      reduce(chain.image(k - 1, layer), w, h, channels, w2, h2, next.data() + chain.image_floats(k) * layer);
    chain.levels.push_back(std::move(next));
  }
  return chain;
}

}  // namespace nephele::files
