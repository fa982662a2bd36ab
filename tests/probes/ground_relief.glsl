// Probe of lib/ground_relief.glsl (shared GLSL/C++ subset; tests/test_library_probes.cpp).
// x[0] = (function, slope east, slope north, 0), x[1] = up, x[2] = sun.
const int PROBE_GROUND_RELIEF = 0;
#ifndef __cplusplus
#include "../lib/ground_relief.glsl"
#endif
vec4 probe_ground_relief(mat4 x) {
  vec2 slopes = vec2(x[0].y, x[0].z);
  return vec4(relief_normal(vec3(x[1]), slopes), relief_sun_cosine(vec3(x[1]), slopes, vec3(x[2])));
}
