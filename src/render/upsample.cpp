#include "render/upsample.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace nephele::render {

void sample_bilinear(const core::ImageData& image, double x, double y, float* out) {
  const auto axis = [](double s, int size, int& i0, int& i1, float& t) {
    s = std::clamp(s, 0.0, size - 1.0);
    i0 = static_cast<int>(std::floor(s));
    i1 = std::min(i0 + 1, size - 1);
    t = static_cast<float>(s - i0);
  };
  int x0, x1, y0, y1;
  float tx, ty;
  axis(x, image.width, x0, x1, tx);
  axis(y, image.height, y0, y1, ty);
  const auto at = [&](int xi, int yi, int c) {
    return image.pixels[(static_cast<size_t>(yi) * image.width + xi) * image.channels + c];
  };
  for (int c = 0; c < image.channels; ++c) {
    const float top = at(x0, y0, c) + tx * (at(x1, y0, c) - at(x0, y0, c));
    const float bottom = at(x0, y1, c) + tx * (at(x1, y1, c) - at(x0, y1, c));
    out[c] = top + ty * (bottom - top);
  }
}

core::ImageData upsample_bilinear(const core::ImageData& image, int width, int height) {
  if (image.width < 1 || image.height < 1 || width < 1 || height < 1)
    throw std::invalid_argument("upsample_bilinear: empty image");
  core::ImageData out{width, height, image.channels, {}};
  out.pixels.resize(static_cast<size_t>(width) * height * image.channels);
  // Pixel centres line up: output pixel x covers the source coordinate (x + 1/2) w/W - 1/2.
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      sample_bilinear(image, (x + 0.5) * image.width / width - 0.5, (y + 0.5) * image.height / height - 0.5,
                      &out.pixels[(static_cast<size_t>(y) * width + x) * image.channels]);
  return out;
}

}  // namespace nephele::render
