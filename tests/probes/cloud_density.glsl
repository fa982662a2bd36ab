// Probe of lib/cloud_density.glsl (shared GLSL/C++ subset; tests/test_library_probes.cpp).
// x[0] = (function, a, b, c), x[1] = (d, e, cloud type, 0). The functions (x[0].x):
const int PROBE_HERMITE_STEP = 0;  // hermite_step(a, b, c)
const int PROBE_SHEET_PROFILE = 1;
const int PROBE_HEAPED_DENSITY = 2;
const int PROBE_SHEET_DENSITY = 3;
const int PROBE_HERMITE_STEP_HALF_WIDTH = 4;  // hermite_step(b, b + 0.5, a)
const int PROBE_CLOUD_DENSITY = 5;
const int PROBE_UNIFORM_FROM_MIX = 6;
const int PROBE_NOISE_PERIOD = 7;
const int PROBE_CLOUD_PHASE = 8;
const int PROBE_SUN_SCATTERING = 9;
const int PROBE_LIGHT_SAMPLE = 10;
const int PROBE_FOG_DENSITY = 11;
const int PROBE_POWDER_FACTOR = 12;
const int PROBE_SHEET_AMOUNT = 13;  // sheet_amount(a, b)
#ifndef __cplusplus
#include "../lib/cloud_density.glsl"
#endif
vec4 probe_cloud_density(mat4 x) {
  int f = int(x[0].x);
  float a = x[0].y;
  float b = x[0].z;
  float c = x[0].w;
  float d = x[1].x;
  float e = x[1].y;
  if (f == PROBE_HERMITE_STEP) return vec4(hermite_step(a, b, c), 0.0f, 0.0f, 0.0f);
  if (f == PROBE_SHEET_PROFILE) return vec4(sheet_profile(a, b), 0.0f, 0.0f, 0.0f);
  if (f == PROBE_HEAPED_DENSITY) return vec4(heaped_density(a, b, c, d, e), 0.0f, 0.0f, 0.0f);
  if (f == PROBE_SHEET_DENSITY) return vec4(sheet_density(a, b, c, d), 0.0f, 0.0f, 0.0f);
  if (f == PROBE_HERMITE_STEP_HALF_WIDTH) return vec4(hermite_step(b, b + 0.5f, a), 0.0f, 0.0f, 0.0f);
  if (f == PROBE_CLOUD_DENSITY) return vec4(cloud_density(int(x[1].z), a, b, c, d), 0.0f, 0.0f, 0.0f);
  if (f == PROBE_UNIFORM_FROM_MIX) return vec4(uniform_from_mix(a, b), 0.0f, 0.0f, 0.0f);
  if (f == PROBE_NOISE_PERIOD) return vec4(noise_period(int(a)), 0.0f, 0.0f);
  if (f == PROBE_CLOUD_PHASE) return vec4(cloud_phase(a, b), 0.0f, 0.0f, 0.0f);
  if (f == PROBE_LIGHT_SAMPLE) return vec4(light_sample(int(a), int(b), c), 0.0f, 0.0f);
  if (f == PROBE_FOG_DENSITY) return vec4(fog_density(a, b, c, d), 0.0f, 0.0f, 0.0f);
  if (f == PROBE_POWDER_FACTOR) return vec4(powder_factor(a, b, c), 0.0f, 0.0f, 0.0f);
  if (f == PROBE_SHEET_AMOUNT) return vec4(sheet_amount(a, b), 0.0f, 0.0f, 0.0f);
  return vec4(sun_scattering(a, b), 0.0f, 0.0f, 0.0f);  // PROBE_SUN_SCATTERING
}
