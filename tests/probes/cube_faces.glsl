// Probe of lib/cube_faces.glsl (shared GLSL/C++ subset; tests/test_library_probes.cpp).
// x[0] = (function, face, a, b), x[1] = (a direction or the face's size). The functions (x[0].x):
const int PROBE_CUBE_FACE_POINT = 0;  // cube_face_point(face, a, b)
const int PROBE_TEXEL_DIRECTION = 1;  // texel_direction(face, i a, j b, size x[1].x)
const int PROBE_CUBE_FACE_OF = 2;
const int PROBE_CUBE_FACE_COORDS = 3;  // cube_face_coords(face, x[1])
#ifndef __cplusplus
#include "../lib/cube_faces.glsl"
#endif
vec4 probe_cube_faces(mat4 x) {
  int f = int(x[0].x);
  int face = int(x[0].y);
  if (f == PROBE_CUBE_FACE_POINT) return vec4(cube_face_point(face, x[0].z, x[0].w), 0.0f);
  if (f == PROBE_TEXEL_DIRECTION) return vec4(texel_direction(face, int(x[0].z), int(x[0].w), int(x[1].x)), 0.0f);
  if (f == PROBE_CUBE_FACE_OF) return vec4(float(cube_face_of(vec3(x[1]))), 0.0f, 0.0f, 0.0f);
  return vec4(cube_face_coords(face, vec3(x[1])), 0.0f, 0.0f);  // PROBE_CUBE_FACE_COORDS
}
