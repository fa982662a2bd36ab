// Bilinear sampling of a cube map by direction, seamless across face edges, written out
// instead of using the texture unit so that every driver and the C++ twin give the same
// result. The cube map is a CubeImage parameter (prelude.glsl; in C++ a CubeSource), read with
// imageLoad(source, ivec3(i, j, face)) and imageSize(source).x texels per face edge.
#ifndef NEPHELE_CUBE_SAMPLING_GLSL
#define NEPHELE_CUBE_SAMPLING_GLSL
#include "prelude.glsl"
#include "cube_faces.glsl"

// Texel (i, j) of `face`, where i or j may lie one texel outside the face: such a texel is
// replaced by the neighbour face's texel just across the edge. The texel grids of adjacent faces
// meet along the shared edge, so the point a quarter texel beyond the edge at the texel's
// along-edge centre falls inside exactly that texel. At a cube corner (i and j both outside)
// there is no fourth texel; one of the two other faces' corner texels stands in.
vec4 cube_texel_extended(int face, int i, int j, CubeImage source) {
  int size = imageSize(source).x;
  if (i >= 0 && i < size && j >= 0 && j < size) return imageLoad(source, ivec3(i, j, face));
  float beyond = 1.0f + 0.5f / float(size);
  float sc = i < 0 ? -beyond : (i >= size ? beyond : (2.0f * (float(i) + 0.5f)) / float(size) - 1.0f);
  float tc = j < 0 ? -beyond : (j >= size ? beyond : (2.0f * (float(j) + 0.5f)) / float(size) - 1.0f);
  vec3 r = cube_face_point(face, sc, tc);
  int other = cube_face_of(r);
  vec2 st = 0.5f * cube_face_coords(other, r) + 0.5f;
  int oi = clamp(int(floor(st.x * float(size))), 0, size - 1);
  int oj = clamp(int(floor(st.y * float(size))), 0, size - 1);
  return imageLoad(source, ivec3(oi, oj, other));
}

vec4 sample_cube_bilinear(vec3 direction, CubeImage source) {
  int size = imageSize(source).x;
  int face = cube_face_of(direction);
  vec2 st = 0.5f * cube_face_coords(face, direction) + 0.5f;
  float u = st.x * float(size) - 0.5f;
  float v = st.y * float(size) - 0.5f;
  float u0 = floor(u);
  float v0 = floor(v);
  float fu = u - u0;
  float fv = v - v0;
  int i = int(u0);
  int j = int(v0);
  vec4 a = cube_texel_extended(face, i, j, source);
  vec4 b = cube_texel_extended(face, i + 1, j, source);
  vec4 c = cube_texel_extended(face, i, j + 1, source);
  vec4 d = cube_texel_extended(face, i + 1, j + 1, source);
  return mix(mix(a, b, fu), mix(c, d, fu), fv);
}

#endif
