// Integration of the warp field: each texel's point follows the flow on the unit sphere.
// Requires cube_sampling.glsl's CUBE_* macros naming the curl cube map.
#ifndef NEPHELE_WARP_STEP_GLSL
#define NEPHELE_WARP_STEP_GLSL
#include "prelude.glsl"
#include "cube_sampling.glsl"

vec3 flow_velocity(vec3 w CUBE_SOURCE_PARAM) {
  return vec3(sample_cube_bilinear(w CUBE_SOURCE_ARG));
}

// The stepping rule (one replaceable function): forward Euler projected back onto the
// sphere, W <- normalize(W + h v(W)).
vec3 warp_step(vec3 w, float h CUBE_SOURCE_PARAM) {
  return normalize(w + h * flow_velocity(w CUBE_SOURCE_ARG));
}

vec3 integrate_warp(vec3 start, int steps, float h CUBE_SOURCE_PARAM) {
  vec3 w = start;
  for (int k = 0; k < steps; ++k) {
    w = warp_step(w, h CUBE_SOURCE_ARG);
  }
  return w;
}

#endif
