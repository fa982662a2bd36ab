#include "io/cube_frames.hpp"

#include <algorithm>
#include <cmath>

namespace nephele::io {

Direction gl_texel_direction(int face, int i, int j, int size) {
  const double sc = 2 * (i + 0.5) / size - 1, tc = 2 * (j + 0.5) / size - 1;
  Direction d;
  switch (face) {  // the inverse of table 8.19 on the face plane |ma| = 1
    case 0: d = {1, -tc, -sc}; break;
    case 1: d = {-1, -tc, sc}; break;
    case 2: d = {sc, 1, tc}; break;
    case 3: d = {sc, -1, -tc}; break;
    case 4: d = {sc, -tc, 1}; break;
    default: d = {-sc, -tc, -1}; break;
  }
  const double l = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  return {d[0] / l, d[1] / l, d[2] / l};
}

float cover_texel(const CoverFaces& faces, const Direction& d) {
  const double ax = std::abs(d[0]), ay = std::abs(d[1]), az = std::abs(d[2]);
  int face;
  double sc, tc, ma;
  if (ax >= ay && ax >= az) {
    face = d[0] > 0 ? 0 : 1, ma = ax, sc = d[0] > 0 ? -d[2] : d[2], tc = -d[1];
  } else if (ay >= az) {
    face = d[1] > 0 ? 2 : 3, ma = ay, sc = d[0], tc = d[1] > 0 ? d[2] : -d[2];
  } else {
    face = d[2] > 0 ? 4 : 5, ma = az, sc = d[2] > 0 ? d[0] : -d[0], tc = -d[1];
  }
  const int n = faces.size;
  const int i = std::clamp(int(std::floor((sc / ma + 1) / 2 * n)), 0, n - 1);
  const int j = std::clamp(int(std::floor((tc / ma + 1) / 2 * n)), 0, n - 1);
  return faces.texels[(std::size_t(face) * n + j) * n + i];
}

Direction AxisMap::to_nephele(const Direction& e) const {
  return {sign[0] * e[axis[0]], sign[1] * e[axis[1]], sign[2] * e[axis[2]]};
}

int AxisMap::determinant() const {
  // The permutation's parity times the signs.
  const int inversions = (axis[0] > axis[1]) + (axis[0] > axis[2]) + (axis[1] > axis[2]);
  return (inversions % 2 ? -1 : 1) * sign[0] * sign[1] * sign[2];
}

std::vector<float> faces_for_axes(const CoverFaces& faces, const AxisMap& map) {
  const int n = faces.size;
  std::vector<float> out(std::size_t(6) * n * n);
  for (int f = 0; f < 6; ++f)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        out[(std::size_t(f) * n + j) * n + i] = cover_texel(faces, map.to_nephele(gl_texel_direction(f, i, j, n)));
  return out;
}

std::vector<float> cover_by_direction(const CoverFaces& faces, int width, int height,
                                      const std::function<Direction(int, int)>& direction) {
  std::vector<float> out(std::size_t(width) * height);
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) out[std::size_t(j) * width + i] = cover_texel(faces, direction(i, j));
  return out;
}

std::vector<float> face_layout(const std::vector<float>& faces, int n, int columns) {
  const int width = columns * n;
  std::vector<float> out(std::size_t(6) * n * n);
  for (int f = 0; f < 6; ++f)
    for (int j = 0; j < n; ++j)
      std::copy_n(
          faces.begin() + std::ptrdiff_t((std::size_t(f) * n + j) * n), n,
          out.begin() + std::ptrdiff_t((std::size_t(f / columns) * n + j) * width + std::size_t(f % columns) * n));
  return out;
}

}  // namespace nephele::io
