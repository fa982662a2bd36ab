// Probe of lib/land_mosaic.glsl (shared GLSL/C++ subset; tests/test_library_probes.cpp).
// x[0] = (function, footprint m, day or relief texel m, radius m), x[1] = the unit vertical, x[2] =
// the day map's colour and alpha, x[3] = (roughness) or a sample (value, deviation, unresolved,
// share).
// The functions (x[0].x):
const int PROBE_MOSAIC_SAMPLE = 0;  // mosaic_sample: value, deviation, relief slopes (roughness x[3].x)
const int PROBE_MOSAIC_PARTS = 1;   // its unresolved deviation; mosaic_forest_share, mosaic_vegetation of x[2]; the fields' octave
const int PROBE_MOSAIC_FOREST = 2;  // mosaic_forest of the sample x[3].xyz and share x[3].w; forest_contrast
const int PROBE_LAND_MOSAIC = 3;    // land_mosaic (at the sample without relief); mosaic_luminance of x[2]
#ifndef __cplusplus
#include "../lib/land_mosaic.glsl"
#endif
vec4 probe_land_mosaic(mat4 x) {
  int f = int(x[0].x);
  float footprint = x[0].y;
  float radius = x[0].w;
  vec3 up = vec3(x[1]);
  if (f == PROBE_MOSAIC_SAMPLE) {
    MosaicSample s = mosaic_sample(up, radius, footprint, x[3].x, x[0].z);
    return vec4(s.value, s.deviation, s.relief);
  }
  if (f == PROBE_MOSAIC_PARTS) {
    MosaicSample s = mosaic_sample(up, radius, footprint, 0.0f, 1.0f);
    return vec4(s.unresolved, mosaic_forest_share(vec3(x[2])), mosaic_vegetation(vec3(x[2])),
                mosaic_octave(up * (radius / MOSAIC_FIELD_WAVELENGTH), 3).w);
  }
  if (f == PROBE_MOSAIC_FOREST) {
    MosaicSample s;
    s.value = x[3].x;
    s.deviation = x[3].y;
    s.unresolved = x[3].z;
    s.relief = vec2(0.0f);
    return vec4(mosaic_forest(s, x[3].w), forest_contrast());
  }
  MosaicSample s = mosaic_sample(up, radius, footprint, 0.0f, 1.0f);
  return vec4(land_mosaic(up, x[2], radius, footprint, x[0].z, s), mosaic_luminance(vec3(x[2])));
}
