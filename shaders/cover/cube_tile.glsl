// Where a cover pass's images lie on the cube map (src/cover/cube_tiles.hpp): image row r of
// layer l is row r + u_tile_origin.x of face l + u_tile_origin.y. A whole cube map is origin
// (0, 0) with six layers (its faces, bound as a 2D array view); a tile is a few rows of one face,
// so that covers larger than the GPU's memory are computed piece by piece (docs/scale.md).
// Each texel's passes depend on its face position only, so a tile's texels are those of the
// whole map to the bit.
#ifndef NEPHELE_CUBE_TILE_GLSL
#define NEPHELE_CUBE_TILE_GLSL
#include "../lib/cube_faces.glsl"

uniform int u_face_size;      // texels per face edge (N)
uniform ivec2 u_tile_origin;  // (face row of image row 0, face of image layer 0)
// The image rows [x, y) a pass computes or reduces; the tile's other rows are the halo that the
// diagnosis's differences read across the tile's edge.
uniform ivec2 u_tile_rows;

// The face position (column, row, face) of an image texel.
ivec3 face_texel(ivec3 image_texel) {
  return ivec3(image_texel.x, image_texel.y + u_tile_origin.x, image_texel.z + u_tile_origin.y);
}

// The unit direction through an image texel's centre (the identity map's texel: the passes
// compute it where they need it rather than read a map of it, 16 bytes a texel).
vec3 image_texel_direction(ivec3 image_texel) {
  ivec3 at = face_texel(image_texel);
  return texel_direction(at.z, at.x, at.y, u_face_size);
}

#endif
