// Probe of lib/curl_spline.glsl (shared GLSL/C++ subset; tests/test_library_probes.cpp).
// The coefficient grid has SPLINE_PROBE_CELLS nodes per face edge inside the face (and
// SPLINE_MARGIN more on each side), vec4 per node, faces in GL order and rows from j = 0: in GLSL
// the 2D array image at the probe's data binding, in C++ a SplineSource over the same floats.
// x[0] = (function, a, b, c). The functions (x[0].x):
const int PROBE_CUBIC_BSPLINE_WEIGHTS = 0;  // cubic_bspline_weights(a)
const int PROBE_PREFILTER_CUBIC_BSPLINE = 1;  // prefilter_cubic_bspline(x[1], x[2], x[3])
const int PROBE_CURL_SPLINE_ROW = 2;  // curl_spline_row(face a, i b, j c, weights x[1])
const int PROBE_SAMPLE_CURL_SPLINE = 3;  // sample_curl_spline(x[1])
const int PROBE_SPLINE_VELOCITY = 4;  // spline_velocity(x[1])
const int PROBE_CURL_SPLINE_NODE = 5;  // curl_spline_node(face a, i b, j c, margin x[1].x, cells x[1].y)
const int PROBE_SPLINE_WARP_VELOCITY = 6;  // warp_velocity(x[1]) of the spline
const int PROBE_SAMPLE_CURL_SPLINE_NODE = 7;  // sample_curl_spline_node(x[1], node a)
const int PROBE_SAMPLE_CURL_SPLINE_IN_TIME = 8;  // sample_curl_spline_in_time(x[1], node a, turn b)
const int PROBE_SPLINE_VELOCITY_IN_TIME = 9;  // spline_velocity_in_time(x[1], node a, turn b)
const int PROBE_SAMPLE_CURL_SPLINE_NODE_TURNED = 10;  // sample_curl_spline_node_turned(x[1], node a, angle b)
const int PROBE_WARP_GRID_SAMPLE = 11;  // warp_grid_sample(x[1], layer a)
const int SPLINE_PROBE_CELLS = 4;
#ifndef __cplusplus
layout(rgba32f, binding = 2) uniform readonly image2DArray probe_spline;
#include "../lib/curl_spline.glsl"
#endif
vec4 probe_curl_spline(mat4 x, SplineImage spline) {
  int f = int(x[0].x);
  if (f == PROBE_CUBIC_BSPLINE_WEIGHTS) return cubic_bspline_weights(x[0].y);
  if (f == PROBE_PREFILTER_CUBIC_BSPLINE) return prefilter_cubic_bspline(x[1], x[2], x[3]);
  if (f == PROBE_CURL_SPLINE_ROW) return curl_spline_row(int(x[0].y), int(x[0].z), int(x[0].w), x[1], spline);
  if (f == PROBE_SAMPLE_CURL_SPLINE) return sample_curl_spline(vec3(x[1]), spline);
  if (f == PROBE_SPLINE_VELOCITY) return vec4(spline_velocity(vec3(x[1]), spline), 0.0f);
  if (f == PROBE_SPLINE_WARP_VELOCITY) return vec4(warp_velocity(vec3(x[1]), spline), 0.0f);
  if (f == PROBE_SAMPLE_CURL_SPLINE_NODE) return sample_curl_spline_node(vec3(x[1]), spline, int(x[0].y));
  if (f == PROBE_SAMPLE_CURL_SPLINE_NODE_TURNED)
    return sample_curl_spline_node_turned(vec3(x[1]), spline, int(x[0].y), x[0].z);
  if (f == PROBE_SAMPLE_CURL_SPLINE_IN_TIME) return sample_curl_spline_in_time(vec3(x[1]), spline, x[0].y, x[0].z);
  if (f == PROBE_WARP_GRID_SAMPLE) return warp_grid_sample(vec3(x[1]), spline, int(x[0].y));
  if (f == PROBE_SPLINE_VELOCITY_IN_TIME)
    return vec4(spline_velocity_in_time(vec3(x[1]), spline, x[0].y, x[0].z), 0.0f);
  return vec4(curl_spline_node(int(x[0].y), int(x[0].z), int(x[0].w), int(x[1].x), int(x[1].y)),
              0.0f);  // PROBE_CURL_SPLINE_NODE
}
#ifndef __cplusplus
vec4 probe_curl_spline(mat4 x) { return probe_curl_spline(x, probe_spline); }
#endif
