// Probe of lib/moving_flow.glsl (shared GLSL/C++ subset; tests/test_moving_flow.cpp).
// x[1].xyz the point n, x[1].w the time t; x[2] = (frequency, octaves, seed north, seed south),
// x[3] = (prevailing, strength, generation time L, drift); origin x[0].w. Fixed: lacunarity 2,
// gain 0.3, smoothing 0.3, mix frequency 3, storm-track focus 0.6, 3 zonal cells. The functions
// (x[0].x):
const int PROBE_ZONAL_DRIFT = 0;           // zonal_drift(x[1].x, zonal cells x[0].y)
const int PROBE_DRIFTED_POTENTIAL = 1;     // drifted_potential of the north noise, age x[0].y
const int PROBE_MOVING_CURL_FLOW = 2;      // moving_curl_flow at (n, t)
const int PROBE_BACK_TRAJECTORY = 3;       // back_trajectory from (n, t), age x[0].y, x[0].z steps
const int PROBE_GENERATION_SHARE = 4;      // generation_share(x[1].x), generation_noise's seed
const int PROBE_MOVING_RK4_STEP = 5;       // moving_rk4_step from (n, t), h x[0].y
const int PROBE_MOVING_VELOCITY = 6;       // moving_velocity at (n, t)
const int PROBE_LOOPED_GENERATION = 7;     // looped_generation(x[0].y, x[0].z)
#ifndef __cplusplus
#include "../lib/moving_flow.glsl"
#endif
CurlParams moving_flow_probe_curl(mat4 x) {
  CurlParams c;  // members one by one: C++17 has no parenthesised aggregate initialisation
  c.potential_north.frequency = x[2].x;
  c.potential_north.octaves = int(x[2].y);
  c.potential_north.lacunarity = 2.0f;
  c.potential_north.gain = 0.3f;
  c.potential_north.seed = uint(x[2].z);
  c.potential_north.period = ivec3(0);
  c.potential_south = c.potential_north;
  c.potential_south.seed = uint(x[2].w);
  c.prevailing = x[3].x;
  c.mix_frequency = 3.0f;
  c.strength = x[3].y;
  c.smoothing = 0.3f;
  c.storm_tracks = 0.6f;
  c.zonal_cells = 3;
  c.storm_track_shift = 0.0f;
  return c;
}
FlowMotion moving_flow_probe_motion(mat4 x) {
  FlowMotion m;
  m.generation_time = x[3].z;
  m.origin = int(x[0].w);
  m.drift = x[3].w;
  m.generations = int(x[0].w) % 2 == 1 ? 5 : 0;  // an odd origin: a loop of 5 generations
  return m;
}
vec4 probe_moving_flow(mat4 x) {
  int f = int(x[0].x);
  CurlParams c = moving_flow_probe_curl(x);
  FlowMotion m = moving_flow_probe_motion(x);
  vec3 n = vec3(x[1]);
  vec3 offset = vec3(0.25f, -0.5f, 0.125f);
  if (f == PROBE_ZONAL_DRIFT) {
    c.zonal_cells = int(x[0].y);
    return vec4(zonal_drift(x[1].x, c), 0.0f, 0.0f);
  }
  if (f == PROBE_DRIFTED_POTENTIAL)
    return drifted_potential(n, c.potential_north, c.smoothing, offset, zonal_drift(n.z, c), x[0].y);
  if (f == PROBE_MOVING_CURL_FLOW) return moving_curl_flow(n, c, offset, m, x[1].w);
  MovingCurl field;
  field.curl = c;
  field.offset = offset;
  field.motion = m;
  if (f == PROBE_BACK_TRAJECTORY) return vec4(back_trajectory(n, x[1].w, x[0].y, int(x[0].z), field), 0.0f);
  if (f == PROBE_GENERATION_SHARE)
    return vec4(generation_share(x[1].x), float(generation_noise(c.potential_north, int(x[0].y)).seed >> 8u), 0.0f,
                0.0f);
  // PROBE_MOVING_RK4_STEP
  if (f == PROBE_MOVING_VELOCITY) return vec4(moving_velocity(n, x[1].w, field), 0.0f);
  if (f == PROBE_LOOPED_GENERATION) return vec4(float(looped_generation(int(x[0].y), int(x[0].z))), 0.0f, 0.0f, 0.0f);
  return vec4(moving_rk4_step(n, x[1].w, x[0].y, field), 0.0f);
}
