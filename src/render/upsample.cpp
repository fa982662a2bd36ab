#include "render/upsample.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace nephele::render {

core::ImageData upsample_bilinear(const core::ImageData& image, int width, int height) {
  if (image.width < 1 || image.height < 1 || width < 1 || height < 1)
    throw std::invalid_argument("upsample_bilinear: empty image");
  core::ImageData out{width, height, image.channels, {}};
  out.pixels.resize(static_cast<size_t>(width) * height * image.channels);
  // Pixel centres line up: output pixel x covers the source coordinate (x + 1/2) w/W - 1/2.
  const auto source = [](int i, int from, int to, int& i0, int& i1, float& t) {
    const double s = std::clamp((i + 0.5) * from / to - 0.5, 0.0, from - 1.0);
    i0 = static_cast<int>(std::floor(s));
    i1 = std::min(i0 + 1, from - 1);
    t = static_cast<float>(s - i0);
  };
  for (int y = 0; y < height; ++y) {
    int y0, y1;
    float ty;
    source(y, image.height, height, y0, y1, ty);
    for (int x = 0; x < width; ++x) {
      int x0, x1;
      float tx;
      source(x, image.width, width, x0, x1, tx);
      const auto at = [&](int xi, int yi, int c) {
        return image.pixels[(static_cast<size_t>(yi) * image.width + xi) * image.channels + c];
      };
      for (int c = 0; c < image.channels; ++c) {
        const float top = at(x0, y0, c) + tx * (at(x1, y0, c) - at(x0, y0, c));
        const float bottom = at(x0, y1, c) + tx * (at(x1, y1, c) - at(x0, y1, c));
        out.pixels[(static_cast<size_t>(y) * width + x) * image.channels + c] = top + ty * (bottom - top);
      }
    }
  }
  return out;
}

}  // namespace nephele::render
