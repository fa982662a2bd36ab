// Probe of lib/latitude_bands.glsl (shared GLSL/C++ subset; tests/test_library_probes.cpp).
#ifndef __cplusplus
#include "../lib/latitude_bands.glsl"
#endif
vec4 probe_latitude_bands(mat4 x) {
  int f = int(x[0].x);
  int bands = int(x[0].y);
  if (f == 0) return vec4(band_coordinate(vec3(x[1]), bands), 0.0f, 0.0f, 0.0f);
  if (f == 1) return vec4(float(band_of(x[0].z, bands)), band_fraction(x[0].z, bands), 0.0f, 0.0f);
  if (f == 2) return vec4(band_neighbours(x[0].z, bands));
  return catmull_rom_weights(x[0].z);
}
