// Probe of lib/warp_step.glsl (shared GLSL/C++ subset; tests/test_library_probes.cpp).
// Two velocity sources: the curl cube map sampled bilinearly (WARP_PROBE_CUBE_SIZE^2 texels per
// face; in GLSL the cube map image at the probe's data binding, in C++ a CubeSource over the same floats) and the
// procedural curl of warp_probe_curl(). C++ instantiates the stepping templates for each
// (CubeSource, CurlParams); GLSL, with one source per shader, passes a flag that switches
// (warp_probe_uses_curl).
// x[0] = (function, integrator, h, steps), x[1] = (start, procedural), x[2] = (flow time,
// first step, max step, tolerance), x[3] = (attempt limit, part, t, attempts). The functions
// (x[0].x); the first three read the cube map directly (warp_probe_sampled):
const int PROBE_FLOW_VELOCITY = 0;
const int PROBE_WARP_STEP = 1;
const int PROBE_INTEGRATE_WARP = 2;
const int PROBE_VELOCITY_AT = 3;  // velocity_at(1.5 w), procedural when x[1].w != 0
const int PROBE_SCHEME_STEP = 4;  // euler_step, heun_step, rk4_step (rk4_step_from), geodesic_step
const int PROBE_FIXED_STEP = 5;  // fixed_step(RK4), procedural
const int PROBE_INTEGRATE_FIXED = 6;  // integrate_fixed(Heun) or integrate_fixed_from(RK4)
const int PROBE_BOGACKI_SHAMPINE_STEP = 7;  // procedural
const int PROBE_ADVANCE_ADAPTIVE = 8;
const int PROBE_INTEGRATE_ADAPTIVE = 9;  // procedural
#ifndef __cplusplus
#include "../lib/curl_flow.glsl"
#endif
const int WARP_PROBE_CUBE_SIZE = 8;
CurlParams warp_probe_curl() {
  CurlParams c;  // the parameter table's defaults but one octave (its code is inlined at each site)
  c.potential_north.frequency = 2.0f;
  c.potential_north.octaves = 1;
  c.potential_north.lacunarity = 2.0f;
  c.potential_north.gain = 0.3f;
  c.potential_north.seed = 5u;
  c.potential_north.period = ivec3(0);
  c.potential_south = c.potential_north;
  c.potential_south.seed = 6u;
  c.prevailing = 0.5f;
  c.mix_frequency = 2.5f;
  c.strength = 0.5f;
  c.smoothing = 0.0f;  // the classic potential these cases were set up with
  c.storm_tracks = 0.0f;
  c.zonal_cells = 0;
  c.storm_track_shift = 0.0f;
  return c;
}
#ifndef __cplusplus
layout(rgba32f, binding = 2) uniform readonly imageCube probe_cube;
#include "../lib/cube_sampling.glsl"
// The GPU's velocity source is a flag, true for the procedural curl and false for the probe's
// cube map, passed as a constant at each call (warp_probe_uses_curl), which the compiler
// propagates into the inlined code (the other source's code then goes).
#define WarpField bool
vec3 warp_velocity(vec3 w, bool procedural) {
  return procedural ? curl_velocity(w, warp_probe_curl()) : vec3(sample_cube_bilinear(w, probe_cube));
}
#include "../lib/warp_step.glsl"
#endif

// The sampled field's reference functions (the cube map only).
vec4 warp_probe_sampled(mat4 x, CubeImage source) {
  int f = int(x[0].x);
  vec3 w = vec3(x[1]);
  if (f == PROBE_FLOW_VELOCITY) return vec4(flow_velocity(w, source), 0.0f);
  if (f == PROBE_WARP_STEP) return vec4(warp_step(w, x[0].z, source), 0.0f);
  return vec4(integrate_warp(w, int(x[0].w), x[0].z, source), 0.0f);  // PROBE_INTEGRATE_WARP
}
// Whether function f is one of warp_probe_sampled's.
bool warp_probe_is_sampled(mat4 x) {
  int f = int(x[0].x);
  return f == PROBE_FLOW_VELOCITY || f == PROBE_WARP_STEP || f == PROBE_INTEGRATE_WARP;
}

// Whether function f runs on the procedural curl. Every velocity source costs the GPU compiler
// its whole code at each call site (Mesa inlines everything), so each function takes one source:
// the schemes run sampled directly and procedural through fixed_step; velocity_at runs both.
bool warp_probe_uses_curl(mat4 x) {
  int f = int(x[0].x);
  if (f == PROBE_VELOCITY_AT) return x[1].w != 0.0f;
  return f == PROBE_FIXED_STEP || f == PROBE_BOGACKI_SHAMPINE_STEP || f == PROBE_INTEGRATE_ADAPTIVE;
}
// The source the stepping rules take: C++ passes the field it was instantiated for, the GPU the
// flag of warp_velocity(vec3, bool) above.
#ifdef __cplusplus
#define WARP_PROBE_SOURCE(procedural) field
#else
#define WARP_PROBE_SOURCE(procedural) (procedural)
#endif

// The stepping rules. fixed_step and integrate_fixed take constant integrators (their dispatch
// is an if chain; the schemes themselves are probed directly), which keeps one scheme's code.
WARP_TEMPLATE
vec4 warp_probe_field(mat4 x, WarpField field) {
  int f = int(x[0].x);
  int integrator = int(x[0].y);
  float h = x[0].z;
  vec3 w = vec3(x[1]);
  if (f == PROBE_VELOCITY_AT) {
    return vec4(velocity_at(1.5f * w, WARP_PROBE_SOURCE(x[1].w != 0.0f)), 0.0f);
  }
  if (f == PROBE_SCHEME_STEP) {
    if (integrator == INTEGRATOR_HEUN) return vec4(heun_step(w, h, WARP_PROBE_SOURCE(false)), 0.0f);
    if (integrator == INTEGRATOR_RK4) {
      // With the flag: the first velocity given, as the warp pass takes it from the curl pass.
      if (x[1].w != 0.0f) return vec4(rk4_step_from(w, velocity_at(w, WARP_PROBE_SOURCE(false)), 1, h,
                                                    WARP_PROBE_SOURCE(false)), 0.0f);
      return vec4(rk4_step(w, h, WARP_PROBE_SOURCE(false)), 0.0f);
    }
    if (integrator == INTEGRATOR_GEODESIC) return vec4(geodesic_step(w, h, WARP_PROBE_SOURCE(false)), 0.0f);
    return vec4(euler_step(w, h, WARP_PROBE_SOURCE(false)), 0.0f);
  }
  if (f == PROBE_FIXED_STEP) {
    return vec4(fixed_step(INTEGRATOR_RK4, w, h, WARP_PROBE_SOURCE(true)), 0.0f);
  }
  if (f == PROBE_INTEGRATE_FIXED) {
    if (x[1].w != 0.0f) {
      vec3 v = velocity_at(w, WARP_PROBE_SOURCE(false));
      return vec4(integrate_fixed_from(INTEGRATOR_RK4, w, v, 1, int(x[0].w), h, WARP_PROBE_SOURCE(false)), 0.0f);
    }
    return vec4(integrate_fixed(INTEGRATOR_HEUN, w, int(x[0].w), h, WARP_PROBE_SOURCE(false)), 0.0f);
  }
  if (f == PROBE_BOGACKI_SHAMPINE_STEP) {
    vec3 k4;
    float error;
    vec3 next = bogacki_shampine_step(w, velocity_at(w, WARP_PROBE_SOURCE(true)), h, k4, error,
                                      WARP_PROBE_SOURCE(true));
    return int(x[3].y) == 0 ? vec4(next, error) : vec4(k4, error);
  }
  if (f == PROBE_ADVANCE_ADAPTIVE) {
    // Continues from flow time x[3].z after int(x[3].w) attempts, with step h.
    float t = x[3].z;
    float step = h;
    int attempts = int(x[3].w);
    bool done = advance_adaptive(w, t, step, attempts, x[2].x, x[2].z, x[2].w, int(x[3].x), WARP_PROBE_SOURCE(false));
    if (int(x[3].y) == 0) return vec4(w, done ? 1.0f : 0.0f);
    return vec4(t, step, float(attempts), done ? 1.0f : 0.0f);
  }
  return integrate_adaptive(w, x[2].x, x[2].y, x[2].z, x[2].w, int(x[3].x),
                            WARP_PROBE_SOURCE(true));  // PROBE_INTEGRATE_ADAPTIVE
}

#ifdef __cplusplus
vec4 probe_warp_step(mat4 x, IN(CubeSource) source) {
  if (warp_probe_is_sampled(x)) return warp_probe_sampled(x, source);
  if (warp_probe_uses_curl(x)) return warp_probe_field(x, warp_probe_curl());
  return warp_probe_field(x, source);
}
#undef WARP_PROBE_SOURCE
#else
vec4 probe_warp_step(mat4 x) {
  if (warp_probe_is_sampled(x)) return warp_probe_sampled(x, probe_cube);
  return warp_probe_field(x, false);  // the flag at each call chooses
}
#endif
