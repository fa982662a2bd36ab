// Probe of lib/portable_math.glsl (shared GLSL/C++ subset; tests/test_shader_probes.cpp).
// x[0].x picks the function, the other numbers are its arguments.
#ifndef __cplusplus
#include "../lib/portable_math.glsl"
#endif
vec4 probe_portable_math(mat4 x) {
  return vec4(portable_asin(x[0].y), 0.0f, 0.0f, 0.0f);
}
