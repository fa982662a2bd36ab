// Probe of lib/sun_glint.glsl (shared GLSL/C++ subset; tests/test_library_probes.cpp).
// PROBE_SUN_GLINT: x[0] = (function, wind, cos_i, tan2_beta), x[1] = up, x[2] = view, x[3] = sun.
// PROBE_SEA_WIND: x[0] = (function, mean wind, 0, 0), x[1] = the point (m).
const int PROBE_SUN_GLINT = 0;
const int PROBE_SEA_WIND = 1;
#ifndef __cplusplus
#include "../lib/sun_glint.glsl"
#endif
vec4 probe_sun_glint(mat4 x) {
  if (int(x[0].x) == PROBE_SEA_WIND) return vec4(sea_wind_speed(vec3(x[1]), x[0].y), 0.0f, 0.0f, 0.0f);
  float wind = x[0].y;
  return vec4(sea_slope_variance(wind), water_fresnel(x[0].z), sea_slope_density(x[0].w, sea_slope_variance(wind)),
              sun_glint_brdf(vec3(x[1]), vec3(x[2]), vec3(x[3]), wind));
}
