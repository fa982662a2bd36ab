// Integration of the warp field: each texel's point follows the flow dW/dt = v(W) on the unit
// sphere for the flow time T. docs/numerics.md derives the schemes and their limits.
//
// The stepping rules are written once for every velocity source: their last parameter is the
// source, `WarpField field`, whose velocity at the unit vector w is warp_velocity(w, field).
//   C++: WARP_TEMPLATE is `template <class WarpField>`, so that one definition serves the sampled
//        cube map (CubeSource), the procedural curl (CurlParams), the curl spline (SplineSource)
//        and the analytic test flows (any callable); hooks.hpp declares their warp_velocity.
//   GLSL: each compiled variant has one source. WarpField is the includer's #define (by default
//        CubeImage, the sampled curl cube map), and warp_velocity is defined for it: here for
//        CubeImage, in curl_spline.glsl for SplineImage, by the includer otherwise.
#ifndef NEPHELE_WARP_STEP_GLSL
#define NEPHELE_WARP_STEP_GLSL
#include "prelude.glsl"
#include "cube_sampling.glsl"

#ifndef __cplusplus
#define WARP_TEMPLATE
#ifndef WarpField
#define WarpField CubeImage
#endif
#endif

// The velocity sampled bilinearly from the curl cube map.
vec3 flow_velocity(vec3 w, CubeImage source) {
  return vec3(sample_cube_bilinear(w, source));
}

// sfsim's stepping rule, kept as the reference of the sampled Euler warp: forward Euler
// projected back onto the sphere, W <- normalize(W + h v(W)).
vec3 warp_step(vec3 w, float h, CubeImage source) {
  return normalize(w + h * flow_velocity(w, source));
}

vec3 integrate_warp(vec3 start, int steps, float h, CubeImage source) {
  vec3 w = start;
  for (int k = 0; k < steps; ++k) {
    w = warp_step(w, h, source);
  }
  return w;
}

// The sampled curl cube map as the source of the stepping rules below.
vec3 warp_velocity(vec3 w, CubeImage source) { return flow_velocity(w, source); }

// Integrator numbers, shared by the host (src/numerics/integrators.hpp) and the shaders.
const int INTEGRATOR_EULER = 0;
const int INTEGRATOR_HEUN = 1;
const int INTEGRATOR_RK4 = 2;
const int INTEGRATOR_GEODESIC = 3;
const int INTEGRATOR_ADAPTIVE = 4;

// Stage points of the Runge-Kutta schemes leave the sphere. The field is continued constant
// along rays, v(x) = v(x/|x|): it stays tangent (v(x) . x = 0), so the exact flow in R^3 keeps
// |x| and, started on the sphere, is the flow on the sphere. Each scheme therefore keeps its
// order in R^3, and the projection at the end of a step changes W by O(h^(p+1)) only.
WARP_TEMPLATE
vec3 velocity_at(vec3 x, WarpField field) {
  return warp_velocity(normalize(x), field);
}

// Forward Euler, order 1: W <- normalize(W + h v(W)). W is a unit vector, so the velocity is
// taken at W itself, which makes the sampled variant identical to warp_step.
WARP_TEMPLATE
vec3 euler_step(vec3 w, float h, WarpField field) {
  return normalize(w + h * warp_velocity(w, field));
}

// Heun (explicit trapezoidal rule), order 2.
WARP_TEMPLATE
vec3 heun_step(vec3 w, float h, WarpField field) {
  vec3 k1 = warp_velocity(w, field);
  vec3 k2 = velocity_at(w + h * k1, field);
  return normalize(w + (0.5f * h) * (k1 + k2));
}

// Classical Runge-Kutta, order 4: k1 = v(w), k2 = v(w + h/2 k1), k3 = v(w + h/2 k2),
// k4 = v(w + h k3), W <- normalize(w + h/6 (k1 + 2 k2 + 2 k3 + k4)). The stages run in a loop
// so that the velocity's code is compiled once, not four times. Same operations in the same
// order as the unrolled form.
// With first_stage 1 the caller gives k1 = v(w) and stage 0 is skipped; with 0, k1 is unused.
WARP_TEMPLATE
vec3 rk4_step_from(vec3 w, vec3 k1, int first_stage, float h, WarpField field) {
  vec3 k = k1;
  vec3 sum = k1;
  for (int stage = first_stage; stage < 4; ++stage) {
    vec3 x = w;
    if (stage > 0) x = normalize(w + (stage == 3 ? h : 0.5f * h) * k);
    k = warp_velocity(x, field);
    sum = stage == 0 ? k : sum + (stage == 3 ? k : 2.0f * k);
  }
  return normalize(w + (h / 6.0f) * sum);
}

WARP_TEMPLATE
vec3 rk4_step(vec3 w, float h, WarpField field) {
  return rk4_step_from(w, vec3(0.0f), 0, h, field);
}

// Geodesic Euler (Lie-Euler), order 1: along the great circle that starts in the direction of
// v, i.e. a rotation about W x v by the angle h |v|; W stays on the sphere by construction.
// The tangential part of v is used (the sampled field is tangent only up to interpolation).
WARP_TEMPLATE
vec3 geodesic_step(vec3 w, float h, WarpField field) {
  vec3 v = warp_velocity(w, field);
  vec3 tangent = v - dot(v, w) * w;
  float speed = length(tangent);
  if (!(speed > 0.0f)) return w;
  float angle = h * speed;
  return normalize(cos(angle) * w + sin(angle) * (tangent / speed));
}

// One step of the fixed-step scheme `integrator` (an INTEGRATOR_* number, not ADAPTIVE).
WARP_TEMPLATE
vec3 fixed_step(int integrator, vec3 w, float h, WarpField field) {
  if (integrator == INTEGRATOR_HEUN) return heun_step(w, h, field);
  if (integrator == INTEGRATOR_RK4) return rk4_step(w, h, field);
  if (integrator == INTEGRATOR_GEODESIC) return geodesic_step(w, h, field);
  return euler_step(w, h, field);
}

// K steps of size h: the flow map at T = K h.
WARP_TEMPLATE
vec3 integrate_fixed(int integrator, vec3 start, int steps, float h, WarpField field) {
  vec3 w = start;
  for (int k = 0; k < steps; ++k) {
    w = fixed_step(integrator, w, h, field);
  }
  return w;
}

// integrate_fixed, where with `known` 1 the velocity at `start` is given (the curl pass
// computed it at every texel): RK4's first step takes it as its k1 instead of evaluating it
// again, an eighth of the evaluations of the default two-step warp. It must be v(start) to the
// bit for the same result. With `known` 0 this is integrate_fixed (one code path either way:
// llvmpipe would run both sides of a choice between two calls).
WARP_TEMPLATE
vec3 integrate_fixed_from(int integrator, vec3 start, vec3 start_velocity, int known, int steps,
                          float h, WarpField field) {
  if (integrator != INTEGRATOR_RK4) return integrate_fixed(integrator, start, steps, h, field);
  vec3 w = start;
  for (int k = 0; k < steps; ++k) {
    w = rk4_step_from(w, start_velocity, k == 0 ? known : 0, h, field);
  }
  return w;
}

// One step of the Bogacki-Shampine 3(2) pair (P. Bogacki, L. F. Shampine, "A 3(2) pair of
// Runge-Kutta formulas", Appl. Math. Lett. 2(4), 1989, 321-325). k1 = v(w) is given; the
// third-order result is returned (local extrapolation), k4 = v(result) is the next step's k1
// (first same as last), and `error` is |third-order - second-order result|, computed from the
// stage velocities without cancellation.
WARP_TEMPLATE
vec3 bogacki_shampine_step(vec3 w, vec3 k1, float h, OUT(vec3) k4, OUT(float) error, WarpField field) {
  vec3 k2 = velocity_at(w + (0.5f * h) * k1, field);
  vec3 k3 = velocity_at(w + (0.75f * h) * k2, field);
  vec3 next = normalize(w + h * ((2.0f / 9.0f) * k1 + (1.0f / 3.0f) * k2 + (4.0f / 9.0f) * k3));
  k4 = warp_velocity(next, field);
  error = h * length((-5.0f / 72.0f) * k1 + (1.0f / 12.0f) * k2 + (1.0f / 9.0f) * k3 - 0.125f * k4);
  return next;
}

// Adaptive integration over the flow time T with error control per step: a step is accepted
// when its error estimate is at most `tolerance` (radians), and the next step size is
// h (tolerance / error)^(1/3) times a safety factor 0.9, limited to [0.2, 5] times the last
// (Hairer, Norsett, Wanner, "Solving Ordinary Differential Equations I", 2nd ed., II.4).
// Beyond the stability limit of the pair the error estimate grows, so the controller shrinks
// the step by itself; at a jump of the velocity (Worley cell borders) the error estimate is
// proportional to h, so the step shrinks until the jump costs at most `tolerance`.
// This continues an integration: W reached flow time t, h is the next step, `attempts` the
// attempted steps so far, which may grow to `attempt_limit` in this call (the GPU pass splits
// long integrations over several dispatches). Returns whether T was reached.
WARP_TEMPLATE
bool advance_adaptive(INOUT(vec3) w, INOUT(float) t, INOUT(float) h, INOUT(int) attempts, float flow_time,
                      float max_step, float tolerance, int attempt_limit, WarpField field) {
  vec3 k1 = warp_velocity(w, field);
  bool done = !(t < flow_time);
  while (!done && attempts < attempt_limit) {
    float remaining = flow_time - t;
    bool last = h >= remaining;
    float step = last ? remaining : h;
    vec3 k4;
    float error;
    vec3 next = bogacki_shampine_step(w, k1, step, k4, error, field);
    attempts += 1;
    if (error <= tolerance) {
      w = next;
      k1 = k4;
      t += step;
      done = last;
    }
    float factor = 0.9f * pow(tolerance / max(error, 1.0e-30f), 1.0f / 3.0f);
    h = min(step * clamp(factor, 0.2f, 5.0f), max_step);
  }
  return done;
}

// The whole integration from `start`. Returns vec4(W, n): n is the number of attempted steps,
// negated when `max_steps` ran out before T was reached (W is then the point reached so far).
WARP_TEMPLATE
vec4 integrate_adaptive(vec3 start, float flow_time, float first_step, float max_step, float tolerance,
                        int max_steps, WarpField field) {
  vec3 w = start;
  float t = 0.0f;
  float h = min(first_step, max_step);
  int attempts = 0;
  bool done = advance_adaptive(w, t, h, attempts, flow_time, max_step, tolerance, max_steps, field);
  return vec4(w, done ? float(attempts) : -float(attempts));
}

#endif
