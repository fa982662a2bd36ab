// Probe of lib/cube_bspline.glsl (shared GLSL/C++ subset; tests/test_library_probes.cpp).
// x[0] = (function, f or the cube's size), x[1] = a direction. The functions (x[0].x):
const int PROBE_BSPLINE_WEIGHTS = 0;  // the four weights at fraction x[0].y
const int PROBE_TAPS_00 = 1;          // (d00, g.x) of cube_bspline_taps(x[1], x[0].y)
const int PROBE_TAPS_10 = 2;          // (d10, g.y)
const int PROBE_TAPS_01 = 3;          // (d01, 0)
const int PROBE_TAPS_11 = 4;          // (d11, 0)
const int PROBE_COMBINE = 5;          // cube_bspline_combine(taps of x[1] on x[0].y, x[2], x[3], 1 - x[2], 1 - x[3])
#ifndef __cplusplus
#include "../lib/cube_bspline.glsl"
#endif
vec4 probe_cube_bspline(mat4 x) {
  int function = int(x[0].x);
  if (function == PROBE_BSPLINE_WEIGHTS) return bspline_weights(x[0].y);
  CubeBsplineTaps taps = cube_bspline_taps(vec3(x[1]), x[0].y);
  if (function == PROBE_TAPS_00) return vec4(taps.d00, taps.g.x);
  if (function == PROBE_TAPS_10) return vec4(taps.d10, taps.g.y);
  if (function == PROBE_TAPS_01) return vec4(taps.d01, 0.0f);
  if (function == PROBE_COMBINE) return cube_bspline_combine(taps, x[2], x[3], 1.0f - x[2], 1.0f - x[3]);
  return vec4(taps.d11, 0.0f);  // PROBE_TAPS_11
}
