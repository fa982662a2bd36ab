#include "cover/streamed_equirect.hpp"

#include <algorithm>

#include "core/parallel_rows.hpp"
#include "cover/equirect.hpp"
#include "shader_math/shader_math.hpp"

namespace nephele::cover {

void equirect_region(int face_size, const float* const faces[6], int width, const std::vector<glm::vec2>& rows,
                     const PixelTile& region, float* out) {
  const int first_row[6] = {};
  glsl::CubeSource source{face_size};
  source.face_rows = faces;
  source.first_row = first_row;
  // Each thread a share of the region's rows.
  core::parallel_rows(region.height, [&](int r0, int r1) {
    for (int r = r0; r < r1; ++r) {
      const glm::vec2 row = rows[static_cast<size_t>(region.y + r)];
      for (int c = 0; c < region.width; ++c)
        out[static_cast<size_t>(r) * region.width + c] =
            glsl::sample_cube_bilinear(glsl::equirect_direction(region.x + c, width, row), source).x;
    }
  });
}

void streamed_equirect(int face_size, const float* const faces[6], int width, int height, const TakeMapRows& take,
                       int band_rows) {
  const std::vector<glm::vec2> rows = geodetic_row_directions(height);
  std::vector<float> band;
  for (int y0 = 0; y0 < height; y0 += band_rows) {
    const int y1 = std::min(height, y0 + band_rows);
    band.assign(static_cast<size_t>(y1 - y0) * width, 0.0f);
    equirect_region(face_size, faces, width, rows, PixelTile{0, y0, width, y1 - y0}, band.data());
    take(y0, y1 - y0, band);
  }
}

}  // namespace nephele::cover
