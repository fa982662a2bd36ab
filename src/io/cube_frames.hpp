#pragma once
// A cover's cube map re-addressed for another engine: its world axes (a signed permutation of
// nephele's, a rotation or a reflection) and its own face rules (docs/export.md, "Axes of the
// engines"). Directions through texel centres map onto texel centres, so these are exact
// copies of texels, never resampling.
#include <array>
#include <functional>
#include <vector>

#include "io/export_presets.hpp"

namespace nephele::io {

using Direction = std::array<double, 3>;

// Unit direction through the centre of texel (i, j) of GL face `face` (OpenGL 4.6 core,
// section 8.13, table 8.19; rows from t = 0).
Direction gl_texel_direction(int face, int i, int j, int size);

// The cover in direction d (nephele axes: +X to 0 N 0 E, +Y to 0 N 90 E, +Z north): the texel
// of the GL face table that d passes through.
float cover_texel(const CoverFaces& faces, const Direction& d);

// nephele's axis k is sign[k] times the engine's axis axis[k].
struct AxisMap {
  std::array<int, 3> axis{0, 1, 2};
  std::array<int, 3> sign{1, 1, 1};
  Direction to_nephele(const Direction& engine) const;
  int determinant() const;  // +1: a rotation; -1: a reflection (a left-handed engine)
};

// The six faces (GL order +X .. -Z, GL face table) of an engine whose direction e is nephele's
// map.to_nephele(e): what the engine's cube sampler must find for the cover to appear in place.
std::vector<float> faces_for_axes(const CoverFaces& faces, const AxisMap& map);

// width x height pixels, pixel (i, j) the cover in direction direction(i, j) (nephele axes).
std::vector<float> cover_by_direction(const CoverFaces& faces, int width, int height,
                                      const std::function<Direction(int, int)>& direction);

// Faces of size n (6 n^2 texels, in order) laid out `columns` wide, row-major (face k at
// column k % columns, row k / columns).
std::vector<float> face_layout(const std::vector<float>& faces, int n, int columns);

}  // namespace nephele::io
