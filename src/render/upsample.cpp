#include "render/upsample.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace nephele::render {

namespace {

// The source cell of output pixel (x, y) of a width x height image upsampled from `image`: its
// 2 x 2 source pixels from (x0, y0) (clamped at the edges) and the bilinear weights (tx, ty).
struct SourceCell {
  int x0, y0;
  double sx, sy, tx, ty;
};

SourceCell source_cell(int x, int y, int source_width, int source_height, int width, int height) {
  SourceCell c;
  c.sx = std::clamp((x + 0.5) * source_width / width - 0.5, 0.0, source_width - 1.0);
  c.sy = std::clamp((y + 0.5) * source_height / height - 0.5, 0.0, source_height - 1.0);
  c.x0 = static_cast<int>(std::floor(c.sx));
  c.y0 = static_cast<int>(std::floor(c.sy));
  c.tx = c.sx - c.x0;
  c.ty = c.sy - c.y0;
  return c;
}

}  // namespace

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
  // Pixel centres line up: output pixel x covers the source coordinate (x + 1/2) w/W - 1/2
  // (source_cell, which upsample_guided and guide_pixels take too).
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const SourceCell c = source_cell(x, y, image.width, image.height, width, height);
      sample_bilinear(image, c.sx, c.sy, &out.pixels[(static_cast<size_t>(y) * width + x) * image.channels]);
    }
  return out;
}

double guided_likeness(float a, float b) {
  const bool sky_a = !(a > 0.0f), sky_b = !(b > 0.0f);
  if (sky_a || sky_b) return sky_a == sky_b ? 1.0 : 0.0;
  constexpr double sigma = 0.3;
  const double l = std::log(static_cast<double>(a) / b) / sigma;
  return std::exp(-0.5 * l * l);
}

std::vector<glm::ivec2> guide_pixels(const core::ImageData& guide, int width, int height) {
  if (guide.width < 1 || guide.height < 1 || guide.channels != 1)
    throw std::invalid_argument("guide_pixels: the guide must be a one-channel image");
  // Cell (i, j) spans source pixels i, i + 1 and j, j + 1: 1 where they are not all alike.
  std::vector<unsigned char> edge(static_cast<std::size_t>(guide.width) * guide.height, 0);
  const auto at = [&](int i, int j) {
    return guide
        .pixels[static_cast<std::size_t>(std::min(j, guide.height - 1)) * guide.width + std::min(i, guide.width - 1)];
  };
  for (int j = 0; j < guide.height; ++j)
    for (int i = 0; i < guide.width; ++i) {
      const float corners[4] = {at(i, j), at(i + 1, j), at(i, j + 1), at(i + 1, j + 1)};
      for (int a = 0; a < 4 && !edge[static_cast<std::size_t>(j) * guide.width + i]; ++a)
        for (int b = a + 1; b < 4; ++b)
          if (guided_likeness(corners[a], corners[b]) < 0.5) {
            edge[static_cast<std::size_t>(j) * guide.width + i] = 1;
            break;
          }
    }
  std::vector<glm::ivec2> pixels;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const SourceCell c = source_cell(x, y, guide.width, guide.height, width, height);
      if (edge[static_cast<std::size_t>(c.y0) * guide.width + c.x0]) pixels.emplace_back(x, y);
    }
  return pixels;
}

core::ImageData upsample_guided(const core::ImageData& image, const core::ImageData& guide,
                                const core::ImageData& upsampled_guide) {
  if (image.width < 1 || image.height < 1 || upsampled_guide.width < 1 || upsampled_guide.height < 1)
    throw std::invalid_argument("upsample_guided: empty image");
  if (guide.width != image.width || guide.height != image.height || guide.channels != 1 ||
      upsampled_guide.channels != 1)
    throw std::invalid_argument("upsample_guided: the guides must be one channel, the first at the image's size");
  const int width = upsampled_guide.width, height = upsampled_guide.height, channels = image.channels;
  core::ImageData out{width, height, channels, {}};
  out.pixels.resize(static_cast<size_t>(width) * height * channels);
  // Below this sum of weights none of the 2 x 2 is alike: a pixel across an edge from all four.
  constexpr double alike = 1e-3;
  const auto source = [&](int xi, int yi) {
    return &image.pixels[(static_cast<size_t>(yi) * image.width + xi) * channels];
  };
  std::vector<double> sum(channels);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      float* target = &out.pixels[(static_cast<size_t>(y) * width + x) * channels];
      const float g = upsampled_guide.pixels[static_cast<size_t>(y) * width + x];
      // The source coordinate of this pixel's centre, as upsample_bilinear takes it.
      const SourceCell cell = source_cell(x, y, image.width, image.height, width, height);
      const double sx = cell.sx, sy = cell.sy, tx = cell.tx, ty = cell.ty;
      const int x0 = cell.x0, y0 = cell.y0;
      if (std::isnan(g)) {
        sample_bilinear(image, sx, sy, target);
        continue;
      }
      std::fill(sum.begin(), sum.end(), 0.0);
      double total = 0;
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) {
          const int xi = std::min(x0 + i, image.width - 1), yi = std::min(y0 + j, image.height - 1);
          const double w = (i ? tx : 1 - tx) * (j ? ty : 1 - ty) *
                           guided_likeness(g, guide.pixels[static_cast<size_t>(yi) * image.width + xi]);
          if (w <= 0) continue;
          const float* v = source(xi, yi);
          for (int c = 0; c < channels; ++c) sum[c] += w * v[c];
          total += w;
        }
      if (total >= alike) {
        for (int c = 0; c < channels; ++c) target[c] = static_cast<float>(sum[c] / total);
        continue;
      }
      // Nearest-depth: the most alike of the 4 x 4, the nearer on ties.
      double best = 0, best_distance = 0;
      int bx = -1, by = -1;
      for (int yi = std::max(0, y0 - 1); yi <= std::min(image.height - 1, y0 + 2); ++yi)
        for (int xi = std::max(0, x0 - 1); xi <= std::min(image.width - 1, x0 + 2); ++xi) {
          const double likeness = guided_likeness(g, guide.pixels[static_cast<size_t>(yi) * image.width + xi]);
          const double distance = (xi - sx) * (xi - sx) + (yi - sy) * (yi - sy);
          if (likeness > best || (likeness == best && likeness > 0 && distance < best_distance)) {
            best = likeness;
            best_distance = distance;
            bx = xi;
            by = yi;
          }
        }
      if (best >= alike) {
        std::copy(source(bx, by), source(bx, by) + channels, target);
      } else {
        sample_bilinear(image, sx, sy, target);
      }
    }
  return out;
}

}  // namespace nephele::render
