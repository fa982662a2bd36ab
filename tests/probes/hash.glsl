// Probe of lib/hash.glsl (shared GLSL/C++ subset; tests/test_shader_probes.cpp). Integers pass
// as floats below 2^24 (exact); results are compared as floats of 24-bit parts.
#ifndef __cplusplus
#include "../lib/hash.glsl"
#endif
vec4 probe_hash(mat4 x) {
  int f = int(x[0].x);
  uvec3 v = uvec3(vec3(x[1]));
  if (f == 0) return vec4(vec3(pcg3d(v) >> 8u), 0.0f);
  if (f == 1) return vec4(hash_to_unit3(v * 2654435761u), 0.0f);
  return vec4(vec3(noise_key(v.x, v.y) >> 8u), 0.0f);
}
