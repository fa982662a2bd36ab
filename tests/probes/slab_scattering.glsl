// Probe of lib/slab_scattering.glsl (shared GLSL/C++ subset; tests/test_library_probes.cpp).
// x[0] = (function, tau, mu0, depth), x[1] = (phase_down, phase_up, 0, 0).
const int PROBE_SLAB_LIGHT = 0;    // (reflectance, direct + diffuse transmittance, J at depth, b1 - a1)
const int PROBE_SLAB_SINGLE = 1;   // (single scattering down, up, the source's x, y)
const int PROBE_SLAB_SKY = 2;      // (the sky's source, 0, 0, 0)
#ifndef __cplusplus
#include "../lib/slab_scattering.glsl"
#endif
vec4 probe_slab_scattering(mat4 x) {
  float tau = x[0].y;
  float mu0 = x[0].z;
  vec2 source = slab_source(tau, mu0, x[1].x, x[1].y);
  if (int(x[0].x) == PROBE_SLAB_SKY) return vec4(slab_sky_source(tau), 0.0f, 0.0f, 0.0f);
  if (int(x[0].x) == PROBE_SLAB_SINGLE) return vec4(slab_single_scattering(tau, mu0, x[1].x, x[1].y), source);
  return vec4(slab_reflectance(tau, mu0), slab_direct_transmittance(tau, mu0) + slab_diffuse_transmittance(tau),
              slab_source_at(source, x[0].w), slab_moment_difference(tau));
}
