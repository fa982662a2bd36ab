// Probe of lib/curl_flow.glsl (shared GLSL/C++ subset; tests/test_library_probes.cpp).
// x[2] = (frequency, octaves, seed north, seed south), x[3] = (prevailing, mix frequency,
// strength, period); lacunarity 2 and gain 0.3 (the defaults) are fixed. The functions (x[0].x):
const int PROBE_CURL_VELOCITY = 0;
const int PROBE_CURL_VELOCITY_SHIFTED = 1;  // x[0].yzw the offset
const int PROBE_CURL_FLOW_SHIFTED = 2;  // x[0].yzw the offset
const int PROBE_STORM_TRACK_ENVELOPE = 3;  // storm_track_envelope(z x[1].x, focus x[1].y)
const int PROBE_ZONAL_PROFILE_DERIVATIVE = 4;  // zonal_profile_derivative(x[1])
// curl_flow_of_potentials(x[1], w1 = (x[0].yzw, 0.3), w2 = (x[0].wyz, 0.25)), as PROBE_CURL_VELOCITY's flow
const int PROBE_CURL_FLOW_OF_POTENTIALS = 5;
// The smooth PROBE_CURL_VELOCITY and PROBE_CURL_FLOW_SHIFTED take the storm-track focus 0.6 and
// 1 and 3 zonal cells.
#ifndef __cplusplus
#include "../lib/curl_flow.glsl"
#endif
CurlParams curl_flow_probe_params(mat4 x) {
  int f = int(x[0].x);
  CurlParams c;  // members one by one: C++17 has no parenthesised aggregate initialisation
  c.potential_north.frequency = x[2].x;
  c.potential_north.octaves = int(x[2].y);
  c.potential_north.lacunarity = 2.0f;
  c.potential_north.gain = 0.3f;
  c.potential_north.seed = uint(x[2].z);
  c.potential_north.period = ivec3(int(x[3].w));
  c.potential_south = c.potential_north;
  c.potential_south.seed = uint(x[2].w);
  c.prevailing = x[3].x;
  c.mix_frequency = x[3].y;
  c.strength = x[3].z;
  // PROBE_CURL_VELOCITY and PROBE_CURL_FLOW_SHIFTED: the smooth potential with the default
  // storm-track focus; PROBE_CURL_VELOCITY_SHIFTED: classic F1 without it.
  c.smoothing = f == PROBE_CURL_VELOCITY_SHIFTED ? 0.0f : 0.3f;
  c.storm_tracks = f == PROBE_CURL_VELOCITY_SHIFTED ? 0.0f : 0.6f;
  c.zonal_cells = f == PROBE_CURL_VELOCITY_SHIFTED ? 0 : (f == PROBE_CURL_FLOW_SHIFTED ? 3 : 1);
  c.storm_track_shift = f == PROBE_CURL_FLOW_SHIFTED ? 0.0326f : 0.0f;  // August's tracks
  return c;
}
vec4 probe_curl_flow(mat4 x) {
  int f = int(x[0].x);
  CurlParams c = curl_flow_probe_params(x);
  if (f == PROBE_CURL_VELOCITY) return vec4(curl_velocity(vec3(x[1]), c), 0.0f);
  if (f == PROBE_CURL_FLOW_SHIFTED) return curl_flow_shifted(vec3(x[1]), c, vec3(x[0].y, x[0].z, x[0].w));
  if (f == PROBE_CURL_FLOW_OF_POTENTIALS)
    return curl_flow_of_potentials(vec3(x[1]), vec4(x[0].y, x[0].z, x[0].w, 0.3f), vec4(x[0].w, x[0].y, x[0].z, 0.25f),
                                   c);
  if (f == PROBE_STORM_TRACK_ENVELOPE) return vec4(storm_track_envelope(x[1].x, x[1].y), 0.0f, 0.0f);
  if (f == PROBE_ZONAL_PROFILE_DERIVATIVE)
    return vec4(zonal_profile_derivative(x[1].x, x[1].y, int(x[1].z), x[1].w), 0.0f, 0.0f, 0.0f);
  // PROBE_CURL_VELOCITY_SHIFTED
  return vec4(curl_velocity_shifted(vec3(x[1]), c, vec3(x[0].y, x[0].z, x[0].w)), 0.0f);
}
