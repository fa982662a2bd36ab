// Probe of lib/cover_density.glsl (shared GLSL/C++ subset; tests/test_shader_probes.cpp).
#ifndef __cplusplus
#include "../lib/cover_density.glsl"
#endif
vec4 probe_cover_density(mat4 x) {
  int f = int(x[0].x);
  FbmParams params;  // members one by one: C++17 has no parenthesised aggregate initialisation
  params.frequency = x[2].x;
  params.octaves = int(x[2].y);
  params.lacunarity = x[2].z;
  params.gain = x[2].w;
  params.seed = uint(x[3].x);
  params.period = ivec3(0);
  if (f == 0) return vec4(cover_density(vec3(x[1]), params), 0.0f, 0.0f, 0.0f);
  if (f == 1) return vec4(cover_density_shifted(vec3(x[1]), params, vec3(x[3].y, x[3].z, x[3].w)), 0.0f, 0.0f, 0.0f);
  if (f == 3) return vec4(shaped_density(x[0].y, x[0].z, x[0].w, x[3].y, x[3].z), 0.0f, 0.0f, 0.0f);
  return vec4(cover_from_density(x[0].y, x[0].z, x[0].w), 0.0f, 0.0f, 0.0f);
}
