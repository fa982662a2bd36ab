// Probe of lib/worley.glsl (shared GLSL/C++ subset; tests/test_shader_probes.cpp).
#ifndef __cplusplus
#include "../lib/worley.glsl"
#endif
vec4 probe_worley(mat4 x) {
  int f = int(x[0].x);
  ivec3 period = ivec3(vec3(x[2]));
  uvec3 key = uvec3(vec3(x[3]));
  // w: the remainder of index x[1].x by 7 from the given quotient x[1].y (integer arithmetic).
  if (f == 0) return vec4(vec3(wrap_cell(ivec3(vec3(x[1])), period)), float(wrap_remainder(int(x[1].x), 7, int(x[1].y))));
  if (f == 1) return vec4(feature_offset(ivec3(vec3(x[1])), period, key), 0.0f);
  if (f == 2) {
    float best = x[0].y;
    vec3 best_delta = vec3(0.0f);
    worley_candidate(ivec3(0), ivec3(int(x[0].z), int(x[0].w), 1), vec3(x[1]), period, key, best, best_delta);
    worley_nearer(vec3(x[1]), ivec3(1, 0, 0), vec3(x[1].w), best, best_delta);
    return vec4(best_delta, best);
  }
  if (f == 3) return vec4(wrapped_feature_offset(ivec3(vec3(x[1])), key), 0.0f);
  if (f == 4) return smooth_worley(vec3(x[1]), period, key, x[0].y);
  if (f == 5) {
    // The three wrapped neighbours along x, and one step from the wrapped y along x[0].z.
    int y = wrap_axis(int(x[1].y), period.y);
    return vec4(vec3(wrapped_neighbours(int(x[1].x), period.x)), float(wrap_step(y, int(x[0].z), period.y)));
  }
  return worley_f1(vec3(x[1]), period, key);  // f == 6
}
