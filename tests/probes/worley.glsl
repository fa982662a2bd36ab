// Probe of lib/worley.glsl (shared GLSL/C++ subset; tests/test_library_probes.cpp).
// x[0] = (function, a, b, c), x[1] = the point or cell, x[2] = the period, x[3] = the key. The
// functions (x[0].x):
const int PROBE_WRAP_CELL = 0;  // wrap_cell, wrap_remainder
const int PROBE_FEATURE_OFFSET = 1;
const int PROBE_WORLEY_CANDIDATE = 2;  // worley_candidate, worley_nearer
const int PROBE_WRAPPED_FEATURE_OFFSET = 3;
const int PROBE_SMOOTH_WORLEY = 4;
const int PROBE_WRAPPED_NEIGHBOURS = 5;  // wrapped_neighbours, wrap_axis, wrap_step
const int PROBE_WORLEY_F1 = 6;
const int PROBE_NEAREST_CELL = 7;  // nearest_cell(p, worley_f1(p, ...)), F1 in w
const int PROBE_F1_SEARCHED = 8;  // worley_f1_searched(p, ..., int(c)), F1 capped at 1e3 (1e15 where none searched)
const int PROBE_NEIGHBOUR_OFFSET = 9;  // neighbour_offset(int(c))
const int PROBE_WIDER_SEARCH = 10;     // worley_wider_search(floor(p), fract(p), ..., best a): (delta, best)
const int PROBE_WORLEY_RESULT = 11;    // worley_result(a, x[1].xyz)
const int PROBE_NEAR_OFFSET = 13;       // near_offset(int(c), x[1].xyz)
const int PROBE_WORLEY_CELL = 12;      // worley_cell(p, period): cell in xyz, f.x + xs.x + ys.z + zs.y in w
const int PROBE_WIDER_OFFSET = 14;     // wider_offset(int(c))
#ifndef __cplusplus
#include "../lib/worley.glsl"
#endif
vec4 probe_worley(mat4 x) {
  int f = int(x[0].x);
  ivec3 period = ivec3(vec3(x[2]));
  uvec3 key = uvec3(vec3(x[3]));
  // w: the remainder of index x[1].x by 7 from the given quotient x[1].y (integer arithmetic).
  if (f == PROBE_WRAP_CELL)
    return vec4(vec3(wrap_cell(ivec3(vec3(x[1])), period)), float(wrap_remainder(int(x[1].x), 7, int(x[1].y))));
  if (f == PROBE_FEATURE_OFFSET) return vec4(feature_offset(ivec3(vec3(x[1])), period, key), 0.0f);
  if (f == PROBE_WORLEY_CANDIDATE) {
    float best = x[0].y;
    vec3 best_delta = vec3(0.0f);
    worley_candidate(ivec3(0), ivec3(int(x[0].z), int(x[0].w), 1), vec3(x[1]), period, key, best, best_delta);
    worley_nearer(vec3(x[1]), ivec3(1, 0, 0), vec3(x[1].w), best, best_delta);
    return vec4(best_delta, best);
  }
  if (f == PROBE_WRAPPED_FEATURE_OFFSET) return vec4(wrapped_feature_offset(ivec3(vec3(x[1])), key), 0.0f);
  if (f == PROBE_SMOOTH_WORLEY) return smooth_worley(vec3(x[1]), period, key, x[0].y);
  if (f == PROBE_WRAPPED_NEIGHBOURS) {
    // The three wrapped neighbours along x, and one step from the wrapped y along x[0].z.
    int y = wrap_axis(int(x[1].y), period.y);
    return vec4(vec3(wrapped_neighbours(int(x[1].x), period.x)), float(wrap_step(y, int(x[0].z), period.y)));
  }
  if (f == PROBE_NEAREST_CELL) {
    vec4 f1 = worley_f1(vec3(x[1]), period, key);
    return vec4(vec3(nearest_cell(vec3(x[1]), f1)), f1.w);
  }
  if (f == PROBE_F1_SEARCHED) {
    vec4 f1 = worley_f1_searched(vec3(x[1]), period, key, int(x[0].w));
    return vec4(vec3(f1), min(f1.w, 1.0e3f));
  }
  if (f == PROBE_NEIGHBOUR_OFFSET) return vec4(vec3(neighbour_offset(int(x[0].w))), 0.0f);
  if (f == PROBE_NEAR_OFFSET) return vec4(vec3(near_offset(int(x[0].w), vec3(x[1]))), 0.0f);
  if (f == PROBE_WIDER_OFFSET) return vec4(vec3(wider_offset(int(x[0].w))), 0.0f);
  if (f == PROBE_WIDER_SEARCH) {
    float best = x[0].y;
    vec3 best_delta = vec3(0.0f);
    vec3 p = vec3(x[1]);
    worley_wider_search(ivec3(floor(p)), p - floor(p), period, key, WIDER_CELLS, best, best_delta);
    return vec4(best_delta, best);
  }
  if (f == PROBE_WORLEY_RESULT) return worley_result(x[0].y, vec3(x[1]));
  if (f == PROBE_WORLEY_CELL) {
    WorleyCell c = worley_cell(vec3(x[1]), period);
    return vec4(vec3(c.cell), c.f.x + float(c.xs.x + c.ys.z + c.zs.y));
  }
  return worley_f1(vec3(x[1]), period, key);  // PROBE_WORLEY_F1
}
