// Probe of lib/cloud_density.glsl (shared GLSL/C++ subset; tests/test_shader_probes.cpp).
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
  if (f == 0) return vec4(hermite_step(a, b, c), 0.0f, 0.0f, 0.0f);
  if (f == 1) return vec4(sheet_profile(a, b), 0.0f, 0.0f, 0.0f);
  if (f == 2) return vec4(heaped_density(a, b, c, d, e), 0.0f, 0.0f, 0.0f);
  if (f == 3) return vec4(sheet_density(a, b, c, d), 0.0f, 0.0f, 0.0f);
  if (f == 4) return vec4(hermite_step(b, b + 0.5f, a), 0.0f, 0.0f, 0.0f);
  if (f == 5) return vec4(cloud_density(int(x[1].z), a, b, c, d), 0.0f, 0.0f, 0.0f);
  if (f == 6) return vec4(uniform_from_mix(a, b), 0.0f, 0.0f, 0.0f);
  if (f == 7) return vec4(noise_period(int(a)), 0.0f, 0.0f);
  if (f == 8) return vec4(cloud_phase(a, b), 0.0f, 0.0f, 0.0f);
  if (f == 10) return vec4(light_sample(int(a), int(b), c), 0.0f, 0.0f);
  if (f == 11) return vec4(fog_density(a, b, c, d), 0.0f, 0.0f, 0.0f);
  if (f == 12) return vec4(powder_factor(a, b, c), 0.0f, 0.0f, 0.0f);
  return vec4(sun_scattering(a, b), 0.0f, 0.0f, 0.0f);
}
