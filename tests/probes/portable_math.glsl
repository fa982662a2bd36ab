// Probe of lib/portable_math.glsl (shared GLSL/C++ subset; tests/test_library_probes.cpp).
// x[0].x picks the function, the other numbers are its arguments; the one function (x[0].x):
const int PROBE_PORTABLE_ASIN = 0;  // portable_asin(x[0].y)
#ifndef __cplusplus
#include "../lib/portable_math.glsl"
#endif
vec4 probe_portable_math(mat4 x) {
  return vec4(portable_asin(x[0].y), 0.0f, 0.0f, 0.0f);  // PROBE_PORTABLE_ASIN, whatever x[0].x
}
