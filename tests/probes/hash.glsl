// Probe of lib/hash.glsl (shared GLSL/C++ subset; tests/test_library_probes.cpp). Integers pass
// as floats below 2^24 (exact); results are compared as floats of 24-bit parts. x[1] = the
// integers. The functions (x[0].x):
const int PROBE_PCG3D = 0;
const int PROBE_HASH_TO_UNIT3 = 1;  // hash_to_unit3 of x[1] times 2654435761
const int PROBE_NOISE_KEY = 2;  // noise_key(x[1].x, x[1].y)
#ifndef __cplusplus
#include "../lib/hash.glsl"
#endif
vec4 probe_hash(mat4 x) {
  int f = int(x[0].x);
  uvec3 v = uvec3(vec3(x[1]));
  if (f == PROBE_PCG3D) return vec4(vec3(pcg3d(v) >> 8u), 0.0f);
  if (f == PROBE_HASH_TO_UNIT3) return vec4(hash_to_unit3(v * 2654435761u), 0.0f);
  return vec4(vec3(noise_key(v.x, v.y) >> 8u), 0.0f);  // PROBE_NOISE_KEY
}
