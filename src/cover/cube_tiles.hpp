#pragma once
// Parts of the cover's cube map that the passes compute on their own (docs/scale.md): a tile is
// a strip of rows of one face. Every pass but the calibration works texel by texel (the warp
// evaluates the flow where its trajectory goes, from the procedural curl or the spline of the
// curl grid, never from the curl map), so a tile's texels are the whole map's to the bit; the
// calibration adds integer histograms over all tiles, whose sums do not depend on the order.
// The warp diagnosis's differences read one row beyond the tile: its halo.
#include <cstdint>
#include <string>

namespace nephele::gpu {
class ComputeProgram;
}

namespace nephele::cover {

// Rows of the cube map held by a pass's images (cube_tile.glsl): image row r of layer l is
// row first_row + r of face face + l. The owned rows [owned_begin, owned_end) (image rows) are
// the region's own; the others, one on each side that is not a face edge, are halo.
struct CubeRegion {
  int face_size = 0;
  int face = 0;       // the face of layer 0
  int layers = 6;     // 6: the whole cube map; 1: rows of one face
  int first_row = 0;  // the face row of image row 0
  int rows = 0;       // image rows (owned and halo)
  int owned_begin = 0, owned_end = 0;

  static CubeRegion whole(int face_size);
  bool whole_cube() const { return layers == 6; }
  int owned_rows() const { return owned_end - owned_begin; }
  std::int64_t image_texels() const { return std::int64_t(face_size) * rows * layers; }
  std::int64_t owned_texels() const { return std::int64_t(face_size) * owned_rows() * layers; }
};

// A cube map of N texels per face edge cut into `count` tiles, count a multiple of 6: each face
// in count / 6 strips of rows, as equal as whole rows allow; tile t is strip t mod (count / 6)
// of face t / (count / 6).
struct CubeTiling {
  int face_size = 0;
  int count = 6;

  int strips_per_face() const { return count / 6; }
  // Tile `index` with its halo; throws std::out_of_range outside [0, count).
  CubeRegion tile(int index) const;
};

// The largest tile count generate accepts: one row per strip.
inline std::int64_t max_tile_count(int face_size) { return 6 * std::int64_t(face_size); }
// Why `count` cannot tile a face of `face_size` (empty when it can).
std::string tile_count_problem(int face_size, std::int64_t count);

// Sets the region's uniforms of cube_tile.glsl on `program`.
void set_region(const gpu::ComputeProgram& program, const CubeRegion& region);

}  // namespace nephele::cover
