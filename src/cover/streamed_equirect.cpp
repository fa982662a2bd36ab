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
  streamed_equirect(face_size, {FacePointers{faces[0], faces[1], faces[2], faces[3], faces[4], faces[5]}}, width,
                    height, take, band_rows);
}

void streamed_equirect(int face_size, const std::vector<FacePointers>& faces, int width, int height,
                       const TakeMapRows& take, int band_rows) {
  const std::vector<glm::vec2> rows = geodetic_row_directions(height);
  const size_t channels = faces.size();
  std::vector<float> plane, band;
  for (int y0 = 0; y0 < height; y0 += band_rows) {
    const int y1 = std::min(height, y0 + band_rows);
    const size_t pixels = static_cast<size_t>(y1 - y0) * width;
    band.assign(pixels * channels, 0.0f);
    plane.resize(pixels);
    for (size_t c = 0; c < channels; ++c) {
      equirect_region(face_size, faces[c].data(), width, rows, PixelTile{0, y0, width, y1 - y0}, plane.data());
      for (size_t k = 0; k < pixels; ++k) band[k * channels + c] = plane[k];
    }
    take(y0, y1 - y0, band);
  }
}

}  // namespace nephele::cover
