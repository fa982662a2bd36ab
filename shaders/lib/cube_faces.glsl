// Cube map face conventions of OpenGL 4.6 core, section 8.13, table 8.19.
// Face index 0..5 = +X, -X, +Y, -Y, +Z, -Z. World axes are Earth-centred, Earth-fixed:
// +Z north pole, +X latitude 0 longitude 0, +Y latitude 0 longitude 90 E.
#ifndef NEPHELE_CUBE_FACES_GLSL
#define NEPHELE_CUBE_FACES_GLSL
#include "prelude.glsl"

// Point on the face plane |major axis| = 1 for face coordinates sc, tc in [-1, 1]
// (values outside extend the plane beyond the face). Inverse of table 8.19.
vec3 cube_face_point(int face, float sc, float tc) {
  if (face == 0) return vec3(1.0f, -tc, -sc);
  if (face == 1) return vec3(-1.0f, -tc, sc);
  if (face == 2) return vec3(sc, 1.0f, tc);
  if (face == 3) return vec3(sc, -1.0f, -tc);
  if (face == 4) return vec3(sc, -tc, 1.0f);
  return vec3(-sc, -tc, -1.0f);
}

// Unit direction through the centre of texel (i, j) of a size x size face:
// s = (i + 0.5) / size, t = (j + 0.5) / size, sc = 2 s - 1, tc = 2 t - 1.
vec3 texel_direction(int face, int i, int j, int size) {
  float sc = (2.0f * (float(i) + 0.5f)) / float(size) - 1.0f;
  float tc = (2.0f * (float(j) + 0.5f)) / float(size) - 1.0f;
  return normalize(cube_face_point(face, sc, tc));
}

// The face a direction selects: the axis of largest magnitude (ties go to X, then Y).
int cube_face_of(vec3 r) {
  vec3 a = abs(r);
  if (a.x >= a.y && a.x >= a.z) return r.x >= 0.0f ? 0 : 1;
  if (a.y >= a.z) return r.y >= 0.0f ? 2 : 3;
  return r.z >= 0.0f ? 4 : 5;
}

// Face coordinates (sc/|ma|, tc/|ma|) in [-1, 1] of direction r on the given face.
vec2 cube_face_coords(int face, vec3 r) {
  if (face == 0) return vec2(-r.z, -r.y) / abs(r.x);
  if (face == 1) return vec2(r.z, -r.y) / abs(r.x);
  if (face == 2) return vec2(r.x, r.z) / abs(r.y);
  if (face == 3) return vec2(r.x, -r.z) / abs(r.y);
  if (face == 4) return vec2(r.x, -r.y) / abs(r.z);
  return vec2(-r.x, -r.y) / abs(r.z);
}

#endif
