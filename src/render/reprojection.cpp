#include "render/reprojection.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "render/upsample.hpp"

namespace nephele::render {

namespace {

bool marched(int x, int y, int stride, glm::ivec2 phase) { return x % stride == phase.x && y % stride == phase.y; }

}  // namespace

glm::ivec2 march_phase(long frame, int stride) {
  if (stride <= 1) return {0, 0};
  const int n = stride * stride;
  const long k = ((frame % n) + n) % n;
  if (stride == 2) {
    static const glm::ivec2 order[4] = {{0, 0}, {1, 1}, {1, 0}, {0, 1}};
    return order[k];
  }
  // Larger strides: a step coprime to n through the blocks' pixels.
  long step = n / 2 + 1;
  while (std::gcd(step, static_cast<long>(n)) != 1) ++step;
  const long i = (k * step) % n;
  return {static_cast<int>(i % stride), static_cast<int>(i / stride)};
}

namespace {

glm::dvec3 direction_in(const CameraFrame& b, int width, int height, double x, double y) {
  const double u = (x + 0.5) / width, v = (y + 0.5) / height;
  const double aspect = double(height) / width;
  const double sx = (2 * u - 1) * b.tan_half_fov, sy = (1 - 2 * v) * aspect * b.tan_half_fov;
  return glm::normalize(b.forward + sx * b.right + sy * b.up);
}

}  // namespace

glm::dvec3 pixel_direction(const Camera& camera, double x, double y) {
  return direction_in(camera_frame(camera), camera.width, camera.height, x, y);
}

long fill_unmarched(core::ImageData& image, const Camera& camera, int stride, glm::ivec2 phase,
                    const FrameHistory* history) {
  if (stride <= 1) return 0;
  if (image.channels != 4 || image.width != camera.width || image.height != camera.height || camera.panorama)
    throw std::logic_error("fill_unmarched: an RGBA image of a perspective camera's size");
  const int w = image.width, h = image.height;
  const core::ImageData* previous = history != nullptr && history->radiance.width == w &&
                                            history->radiance.height == h && history->radiance.channels == 4 &&
                                            !history->camera.panorama
                                        ? &history->radiance
                                        : nullptr;
  const CameraFrame now = camera_frame(camera);
  CameraFrame before{};
  if (previous != nullptr) before = camera_frame(history->camera);
  const double before_aspect = double(h) / w;
  auto at = [&](int x, int y, int c) { return image.pixels[(static_cast<std::size_t>(y) * w + x) * 4 + c]; };
  long reprojected = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (marched(x, y, stride, phase)) continue;
      float* out = &image.pixels[(static_cast<std::size_t>(y) * w + x) * 4];
      if (previous != nullptr) {
        const glm::dvec3 d = direction_in(now, w, h, x, y);
        const double z = glm::dot(d, before.forward);
        if (z > 0) {
          // The previous camera's pixel coordinates of d (inverse of pixel_direction).
          const double sx = glm::dot(d, before.right) / z / before.tan_half_fov;
          const double sy = glm::dot(d, before.up) / z / (before_aspect * before.tan_half_fov);
          // Within the previous image (up to half a pixel beyond its edge centres, clamped).
          const double px = std::clamp((sx + 1) / 2 * w - 0.5, -1.0, double(w)),
                       py = std::clamp((1 - sy) / 2 * h - 0.5, -1.0, double(h));
          if (px >= -0.5 && py >= -0.5 && px <= w - 0.5 && py <= h - 0.5) {
            sample_bilinear(*previous, px, py, out);
            ++reprojected;
            continue;
          }
        }
      }
      // The nearest marched pixel of this frame (the block's lattice pixel, kept inside).
      int mx = x - ((x - phase.x) % stride + stride) % stride, my = y - ((y - phase.y) % stride + stride) % stride;
      if (x - mx > stride / 2 && mx + stride < w) mx += stride;
      if (y - my > stride / 2 && my + stride < h) my += stride;
      if (mx < 0) mx += stride;
      if (my < 0) my += stride;
      mx = std::min(mx, w - 1);
      my = std::min(my, h - 1);
      for (int c = 0; c < 4; ++c) out[c] = at(mx, my, c);
    }
  return reprojected;
}

}  // namespace nephele::render
