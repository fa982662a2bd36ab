// Bilinear sampling of a cube map by direction, seamless across face edges, written out
// instead of using the texture unit so that every driver and the C++ twin give the same
// result. The cube map is a CubeImage parameter (prelude.glsl; in C++ a CubeSource), read with
// imageLoad(source, ivec3(i, j, face)) and imageSize(source).x texels per face edge.
#ifndef NEPHELE_CUBE_SAMPLING_GLSL
#define NEPHELE_CUBE_SAMPLING_GLSL
#include "prelude.glsl"
#include "cube_faces.glsl"

// Texel (i, j) of `face` of a cube map of `size` texels per face edge, where i or j may lie one
// texel outside the face: such a texel is replaced by the neighbour face's texel just across the
// edge. The texel grids of adjacent faces meet along the shared edge, so the point a quarter
// texel beyond the edge at the texel's along-edge centre falls inside exactly that texel. At a
// cube corner (i and j both outside) there is no fourth texel; one of the two other faces' corner
// texels stands in. Returns the texel read, (i, j, face).
ivec3 cube_texel_address(int face, int i, int j, int size) {
  if (i >= 0 && i < size && j >= 0 && j < size) return ivec3(i, j, face);
  float beyond = 1.0f + 0.5f / float(size);
  float sc = i < 0 ? -beyond : (i >= size ? beyond : (2.0f * (float(i) + 0.5f)) / float(size) - 1.0f);
  float tc = j < 0 ? -beyond : (j >= size ? beyond : (2.0f * (float(j) + 0.5f)) / float(size) - 1.0f);
  vec3 r = cube_face_point(face, sc, tc);
  int other = cube_face_of(r);
  vec2 st = 0.5f * cube_face_coords(other, r) + 0.5f;
  int oi = clamp(int(floor(st.x * float(size))), 0, size - 1);
  int oj = clamp(int(floor(st.y * float(size))), 0, size - 1);
  return ivec3(oi, oj, other);
}
vec4 cube_texel_extended(int face, int i, int j, CubeImage source) {
  return imageLoad(source, cube_texel_address(face, i, j, imageSize(source).x));
}

// The four texels of a bilinear sample of a cube map of `size` texels per face edge at
// `direction` and their weights: texels (i, j), (i + 1, j), (i, j + 1), (i + 1, j + 1) of the
// face (cube_texel_address), and the fractions along i and j. Found once where several maps of
// one size are sampled at one direction (the equirect export's channels): on a SIMD CPU driver
// the edge's branch runs for every texel (prelude.glsl, SKIPPABLE), so it is the sample's cost.
struct CubeFootprint {
  ivec3 texels[4];
  vec2 fraction;
};
CubeFootprint cube_footprint(vec3 direction, int size) {
  int face = cube_face_of(direction);
  vec2 st = 0.5f * cube_face_coords(face, direction) + 0.5f;
  float u = st.x * float(size) - 0.5f;
  float v = st.y * float(size) - 0.5f;
  float u0 = floor(u);
  float v0 = floor(v);
  int i = int(u0);
  int j = int(v0);
  CubeFootprint footprint;
  footprint.fraction = vec2(u - u0, v - v0);
  footprint.texels[0] = cube_texel_address(face, i, j, size);
  footprint.texels[1] = cube_texel_address(face, i + 1, j, size);
  footprint.texels[2] = cube_texel_address(face, i, j + 1, size);
  footprint.texels[3] = cube_texel_address(face, i + 1, j + 1, size);
  return footprint;
}
vec4 sample_cube_footprint(IN(CubeFootprint) footprint, CubeImage source) {
  vec4 a = imageLoad(source, footprint.texels[0]);
  vec4 b = imageLoad(source, footprint.texels[1]);
  vec4 c = imageLoad(source, footprint.texels[2]);
  vec4 d = imageLoad(source, footprint.texels[3]);
  return mix(mix(a, b, footprint.fraction.x), mix(c, d, footprint.fraction.x), footprint.fraction.y);
}

vec4 sample_cube_bilinear(vec3 direction, CubeImage source) {
  return sample_cube_footprint(cube_footprint(direction, imageSize(source).x), source);
}

#endif
