// Probe of lib/curl_flow.glsl (shared GLSL/C++ subset; tests/test_library_probes.cpp).
// x[2] = (frequency, octaves, seed north, seed south), x[3] = (prevailing, mix frequency,
// strength, period); lacunarity 2 and gain 0.3 (the defaults) are fixed. Functions: 0
// curl_velocity, 1 curl_velocity_shifted (x[0].yzw the offset), 2 curl_flow_shifted, 3
// storm_track_envelope(z x[1].x, focus x[1].y), 4 zonal_profile_derivative(x[1]).
// The smooth functions 0 and 2 take the storm-track focus 0.6 and 1 and 3 zonal cells.
#ifndef __cplusplus
#include "../lib/curl_flow.glsl"
#endif
CurlParams curl_flow_probe_params(mat4 x) {
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
  // Functions 0 and 2: the smooth potential with the default storm-track focus; 1: classic F1
  // without it.
  c.smoothing = int(x[0].x) == 1 ? 0.0f : 0.3f;
  c.storm_tracks = int(x[0].x) == 1 ? 0.0f : 0.6f;
  c.zonal_cells = int(x[0].x) == 1 ? 0 : int(x[0].x) + 1;  // 0: 1 cell, 2: 3 cells
  c.storm_track_shift = int(x[0].x) == 2 ? 0.0326f : 0.0f;  // function 2: August's tracks
  return c;
}
vec4 probe_curl_flow(mat4 x) {
  CurlParams c = curl_flow_probe_params(x);
  if (int(x[0].x) == 0) return vec4(curl_velocity(vec3(x[1]), c), 0.0f);
  if (int(x[0].x) == 2) return curl_flow_shifted(vec3(x[1]), c, vec3(x[0].y, x[0].z, x[0].w));
  if (int(x[0].x) == 3) return vec4(storm_track_envelope(x[1].x, x[1].y), 0.0f, 0.0f);
  if (int(x[0].x) == 4)
    return vec4(zonal_profile_derivative(x[1].x, x[1].y, int(x[1].z), x[1].w), 0.0f, 0.0f, 0.0f);
  return vec4(curl_velocity_shifted(vec3(x[1]), c, vec3(x[0].y, x[0].z, x[0].w)), 0.0f);
}
