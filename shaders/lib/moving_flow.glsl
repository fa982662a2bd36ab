// The flow that moves: curl_flow.glsl's stream function with vortices that are born, drift with
// the zonal wind and die, and the back-trajectories that carry the cloud density along it
// (docs/algorithm.md, "The moving flow"). Times are in flow units (the warp's T = K h is one
// such time), counted from the origin of FlowMotion.
#ifndef NEPHELE_MOVING_FLOW_GLSL
#define NEPHELE_MOVING_FLOW_GLSL
#include "prelude.glsl"
#include "parameters.glsl"
#include "hash.glsl"
#include "curl_flow.glsl"

// The angular speed about the axis, omega = u / cos(lat), of the zonal wind u = -s P Z'(lat) of
// the stream function's zonal term, and d omega / dz (z = sin lat). For 1 to 3 cells Z'(lat) is
// 3 cos(lat) times a polynomial of z^2 (zonal_profile_derivative), so omega is that polynomial:
// smooth on the whole sphere. For 0 cells (Z = m = sin(a lat)) omega = a cos(a lat) / cos(lat),
// singular at the poles unless a is odd; there the drift is set to 0 within 1e-3 of a pole.
vec2 zonal_drift(float z, IN(CurlParams) params) {
  float k = -params.strength * params.prevailing;
  float s = z * z;
  if (params.zonal_cells == 0) {
    float c = sqrt(max(1.0f - s, 0.0f));
    if (c < 1.0e-3f) return vec2(0.0f);
    float a = params.mix_frequency;
    float latitude = portable_asin(z);
    float omega = a * cos(a * latitude) / c;
    // d/dz = (1 / cos lat) d/dlat of a cos(a lat) / cos(lat).
    float slope = (-a * a * sin(a * latitude) * c + a * cos(a * latitude) * z) / (c * c * c);
    return k * vec2(omega, slope);
  }
  if (params.zonal_cells == 2) return k * vec2(3.0f * (1.0f - 2.0f * s), -12.0f * z);
  if (params.zonal_cells == 3) {
    // 3 (1 - 4s)(1 - 4s/3) = 3 - 16 s + 16 s^2; d/dz = (-16 + 32 s) 2z.
    return k * vec2(3.0f - 16.0f * s + 16.0f * s * s, (-32.0f + 64.0f * s) * z);
  }
  return k * vec2(3.0f, 0.0f);
}

// The noise of generation g of a potential: its own seed, so that generations are independent.
FbmParams generation_noise(IN(FbmParams) noise, int generation) {
  FbmParams out_noise = noise;
  out_noise.seed = pcg3d(uvec3(noise.seed, uint(generation), 0x85EBCA6Bu)).x;
  return out_noise;
}

// Generation g's index in a loop of `generations` (--loop: g mod generations, also for negative g),
// or g itself when generations is 0. GLSL leaves % undefined for negative operands (4.50 section
// 5.9), so a negative g takes the remainder of -g.
int looped_generation(int generation, int generations) {
  if (generations <= 0) return generation;
  if (generation >= 0) return generation % generations;
  int r = (-generation) % generations;
  return r == 0 ? 0 : generations - r;
}

// A potential whose pattern has drifted east by the angle omega(z) age about the axis:
// W(R(beta) n) with beta = -omega(z) age, R the rotation about z. Its gradient by the chain
// rule: R^T grad W + (grad W . (e_z x R n)) (d beta / dz) e_z, with d beta / dz = -age omega'(z),
// so that the curl of the drifted potential is exactly divergence-free as every curl is.
// `drift` is zonal_drift's (omega, omega'); `offset` shifts the noise as in curl_flow_shifted.
vec4 drifted_potential(vec3 n, IN(FbmParams) noise, float smoothing, vec3 offset, vec2 drift, float age) {
  float beta = -drift.x * age;
  float c = cos(beta);
  float s = sin(beta);
  vec3 p = vec3(c * n.x - s * n.y, s * n.x + c * n.y, n.z);
  vec4 w = smooth_worley_fbm(p + offset, noise, smoothing);
  vec3 gradient = vec3(c * w.x + s * w.y, -s * w.x + c * w.y, w.z);
  gradient.z += (w.y * p.x - w.x * p.y) * (-age * drift.y);
  return vec4(gradient, w.w);
}

// The share of the younger of the two generations alive at `phase` = t / L - floor(t / L):
// sin^2(pi/2 phase), the older has cos^2. The shares sum to 1, and each generation's rises from
// 0 at its birth ((g - 1) L) to 1 at its centre (g L) and falls back to 0 at its death, with
// zero slope at both ends: vortices grow and decay, nothing switches.
float generation_share(float phase) {
  float rise = sin(1.57079633f * phase);
  return rise * rise;
}

// curl_flow_shifted's flow and cyclonic depth at time t: each potential is the sum of the two
// generations alive at t, weighted by generation_share, each drifted by its age t - g L.
vec4 moving_curl_flow(vec3 n, IN(CurlParams) params, vec3 offset, IN(FlowMotion) motion, float t) {
  float position = t / motion.generation_time;
  float first = floor(position);
  float phase = position - first;
  int older = motion.origin + int(first);
  float young = generation_share(phase);
  vec2 drift = motion.drift * zonal_drift(clamp(n.z, -1.0f, 1.0f), params);
  float older_age = phase * motion.generation_time;
  float younger_age = older_age - motion.generation_time;
  float lambda = params.smoothing;
  int first_seed = looped_generation(older, motion.generations);
  int second_seed = looped_generation(older + 1, motion.generations);
  vec4 w1 = (1.0f - young) * drifted_potential(n, generation_noise(params.potential_north, first_seed), lambda, offset,
                                                drift, older_age) +
            young * drifted_potential(n, generation_noise(params.potential_north, second_seed), lambda, offset, drift,
                                      younger_age);
  vec4 w2 = (1.0f - young) * drifted_potential(n, generation_noise(params.potential_south, first_seed), lambda, offset,
                                                drift, older_age) +
            young * drifted_potential(n, generation_noise(params.potential_south, second_seed), lambda, offset, drift,
                                      younger_age);
  return curl_flow_of_potentials(n, w1, w2, params);
}

// The stepping rules below are written once for every source of the moving flow, `WarpField
// field` (as warp_step.glsl's for the steady flow), whose velocity at w at time t is
// moving_velocity(w, t, field): in C++ a template; in GLSL the includer's #define, by default
// MovingCurl, the procedural flow (shaders/cover/moving_warp.comp also has the splines of the
// flow at time nodes, curl_spline.glsl's spline_velocity_in_time).
#ifndef __cplusplus
#ifndef WARP_TEMPLATE
#define WARP_TEMPLATE
#endif
#ifndef WarpField
#define WarpField MovingCurl
#endif
#endif

// The procedural moving flow at the unit vector w and time t.
vec3 moving_velocity(vec3 w, float t, IN(MovingCurl) field) {
  return vec3(moving_curl_flow(w, field.curl, field.offset, field.motion, t));
}

// Classical Runge-Kutta for the time-dependent flow, dW/dt = v(W, t): stages at t, t + h/2,
// t + h/2 and t + h (warp_step.glsl's rk4_step is for steady fields). Stage points off the
// sphere are normalised (the field is continued constant along rays, as in warp_step.glsl).
// A negative h steps back in time. Stages in a loop: the flow's code is compiled once.
WARP_TEMPLATE
vec3 moving_rk4_step(vec3 w, float t, float h, WarpField field) {
  vec3 k = vec3(0.0f);
  vec3 sum = vec3(0.0f);
  for (int stage = 0; stage < 4; ++stage) {
    float advance = stage == 0 ? 0.0f : (stage == 3 ? h : 0.5f * h);
    vec3 x = stage == 0 ? w : normalize(w + advance * k);
    k = moving_velocity(x, t + advance, field);
    sum = stage == 0 ? k : sum + (stage == 3 ? k : 2.0f * k);
  }
  return normalize(w + (h / 6.0f) * sum);
}

// Where the air at x at time t was `age` earlier: the back-trajectory through the moving flow in
// `steps` RK4 steps of -age / steps. The density found there, carried forward, is the cloud at x.
WARP_TEMPLATE
vec3 back_trajectory(vec3 x, float t, float age, int steps, WarpField field) {
  float h = -age / float(max(steps, 1));
  vec3 w = x;
  for (int k = 0; k < steps; ++k) {
    w = moving_rk4_step(w, t + float(k) * h, h, field);
  }
  return w;
}

#endif
