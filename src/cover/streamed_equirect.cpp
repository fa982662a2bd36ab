#include "cover/streamed_equirect.hpp"

#include <algorithm>
#include <thread>

#include "cover/equirect.hpp"
#include "shader_math/shader_math.hpp"

namespace nephele::cover {

void streamed_equirect(int face_size, const float* const faces[6], int width, int height, const TakeMapRows& take,
                       int band_rows) {
  const std::vector<glm::vec2> rows = geodetic_row_directions(height);
  const int first_row[6] = {};
  glsl::CubeSource source{face_size};
  source.face_rows = faces;
  source.first_row = first_row;
  const int threads = static_cast<int>(std::max(1u, std::min(16u, std::thread::hardware_concurrency())));
  std::vector<float> band;
  for (int y0 = 0; y0 < height; y0 += band_rows) {
    const int y1 = std::min(height, y0 + band_rows);
    band.assign(static_cast<size_t>(y1 - y0) * width, 0.0f);
    // Each thread a share of the band's columns.
    const auto sample = [&](int x0, int x1) {
      for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x)
          band[static_cast<size_t>(y - y0) * width + x] =
              glsl::sample_cube_bilinear(glsl::equirect_direction(x, width, rows[static_cast<size_t>(y)]), source).x;
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(sample, t * width / threads, (t + 1) * width / threads);
    sample(0, width / threads);
    for (std::thread& thread : pool) thread.join();
    take(y0, y1 - y0, band);
  }
}

}  // namespace nephele::cover
