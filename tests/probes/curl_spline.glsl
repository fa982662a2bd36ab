// Probe of lib/curl_spline.glsl (shared GLSL/C++ subset; tests/test_library_probes.cpp).
// The coefficient grid has SPLINE_PROBE_CELLS nodes per face edge inside the face (and
// SPLINE_MARGIN more on each side), vec4 per node, faces in GL order and rows from j = 0: in GLSL
// the buffer at binding 2, in C++ a SplineSource over the same floats.
// x[0] = (function, a, b, c); functions: 0 cubic_bspline_weights(a), 1
// prefilter_cubic_bspline(x[1], x[2], x[3]), 2 curl_spline_row(face a, i b, j c, weights x[1]),
// 3 sample_curl_spline(x[1]), 4 spline_velocity(x[1]), 5 curl_spline_node(face a, i b, j c,
// margin x[1].x, cells x[1].y).
const int SPLINE_PROBE_CELLS = 4;
#ifdef __cplusplus
#define SPLINE_SOURCE_PARAM , IN(SplineSource) spline
#define SPLINE_SOURCE_ARG , spline
#else
layout(std430, binding = 2) readonly buffer ProbeSpline { vec4 probe_spline[]; };
#define SPLINE_SOURCE_PARAM
#define SPLINE_SOURCE_ARG
#define SPLINE_PROBE_EXTENT (SPLINE_PROBE_CELLS + 2 * 2)
#define SPLINE_FETCH(face, i, j) probe_spline[((face) * SPLINE_PROBE_EXTENT + (j)) * SPLINE_PROBE_EXTENT + (i)]
#define SPLINE_CELLS SPLINE_PROBE_CELLS
#include "../lib/curl_spline.glsl"
#endif
vec4 probe_curl_spline(mat4 x SPLINE_SOURCE_PARAM) {
  int f = int(x[0].x);
  if (f == 0) return cubic_bspline_weights(x[0].y);
  if (f == 1) return prefilter_cubic_bspline(x[1], x[2], x[3]);
  if (f == 2) return curl_spline_row(int(x[0].y), int(x[0].z), int(x[0].w), x[1] SPLINE_SOURCE_ARG);
  if (f == 3) return sample_curl_spline(vec3(x[1]) SPLINE_SOURCE_ARG);
  if (f == 4) return vec4(spline_velocity(vec3(x[1]) SPLINE_SOURCE_ARG), 0.0f);
  return vec4(curl_spline_node(int(x[0].y), int(x[0].z), int(x[0].w), int(x[1].x), int(x[1].y)), 0.0f);
}
#undef SPLINE_SOURCE_PARAM
#undef SPLINE_SOURCE_ARG
