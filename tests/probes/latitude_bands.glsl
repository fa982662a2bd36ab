// Probe of lib/latitude_bands.glsl (shared GLSL/C++ subset; tests/test_library_probes.cpp).
// x[0] = (function, bands, coordinate or t, 0), x[1] = a direction. The functions (x[0].x):
const int PROBE_BAND_COORDINATE = 0;
const int PROBE_BAND_OF = 1;  // band_of, band_fraction
const int PROBE_BAND_NEIGHBOURS = 2;
const int PROBE_CATMULL_ROM_WEIGHTS = 3;
#ifndef __cplusplus
#include "../lib/latitude_bands.glsl"
#endif
vec4 probe_latitude_bands(mat4 x) {
  int f = int(x[0].x);
  int bands = int(x[0].y);
  if (f == PROBE_BAND_COORDINATE) return vec4(band_coordinate(vec3(x[1]), bands), 0.0f, 0.0f, 0.0f);
  if (f == PROBE_BAND_OF) return vec4(float(band_of(x[0].z, bands)), band_fraction(x[0].z, bands), 0.0f, 0.0f);
  if (f == PROBE_BAND_NEIGHBOURS) return vec4(band_neighbours(x[0].z, bands));
  return catmull_rom_weights(x[0].z);  // PROBE_CATMULL_ROM_WEIGHTS
}
