// Probe of lib/cube_faces.glsl (shared GLSL/C++ subset; tests/test_shader_probes.cpp).
#ifndef __cplusplus
#include "../lib/cube_faces.glsl"
#endif
vec4 probe_cube_faces(mat4 x) {
  int f = int(x[0].x);
  int face = int(x[0].y);
  if (f == 0) return vec4(cube_face_point(face, x[0].z, x[0].w), 0.0f);
  if (f == 1) return vec4(texel_direction(face, int(x[0].z), int(x[0].w), int(x[1].x)), 0.0f);
  if (f == 2) return vec4(float(cube_face_of(vec3(x[1]))), 0.0f, 0.0f, 0.0f);
  return vec4(cube_face_coords(face, vec3(x[1])), 0.0f, 0.0f);
}
