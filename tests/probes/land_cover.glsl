// Probe of lib/land_cover.glsl (shared GLSL/C++ subset; tests/test_library_probes.cpp). The
// GLSL side reads the land cover bound to texture unit 8. The functions (x[0].x):
const int PROBE_LAND_SAMPLE = 0;      // land_sample, water_coverage at footprint x[0].y
const int PROBE_LAND_PATTERNS = 1;    // field_albedo at footprint x[0].y and crop stage x[0].z, crop_albedo
const int PROBE_LAND_URBAN = 2;       // urban_albedo, ground_texture at footprint x[0].y
const int PROBE_LAND_NATURE = 3;      // forest_cover, snow_cover, land_noise, pattern_detail
const int PROBE_GROUND_SURFACE = 4;   // ground_surface: albedo and water
const int PROBE_LAND_MEANS = 5;       // field_mean_albedo and row_crop_albedo's green at crop stage x[0].z
#ifndef __cplusplus
layout(binding = 8) uniform sampler2DArray land_texture;
#include "../lib/land_cover.glsl"
#endif

// Two levels of 8 x 8 texels: the near one a 4 km square, the far one a 16 km square.
TerrainParams probe_land_params() {
  TerrainParams t;
  t.enabled = 1;
  t.extent = 8000.0f;
  t.top = 1000.0f;
  t.texel = 2000.0f;
  t.reach = 0.0f;
  t.land = 1;
  t.land_near = 2000.0f;
  t.land_far = 8000.0f;
  t.land_texels = 8.0f;
  t.snow_line = 1500.0f;
  t.crop_stage = 1.4f;
  return t;
}

// x[0] = (function, footprint, altitude, slope or snow line), x[1] = a horizontal coordinate
// (x, y), x[2] = a normal, x[3] = further numbers.
vec4 probe_land_cover(mat4 x, IN(LandCoverTexture) land) {
  int f = int(x[0].x);
  TerrainParams t = probe_land_params();
  vec2 xy = vec2(x[1]);
  float footprint = x[0].y;
  if (f == PROBE_LAND_SAMPLE) {
    vec3 s = land_sample(xy, t, land);
    return vec4(s.x, s.y, water_coverage(s, footprint), s.z);
  }
  if (f == PROBE_LAND_PATTERNS) return vec4(field_albedo(xy, footprint, x[0].z), crop_albedo(x[0].z).y);
  if (f == PROBE_LAND_URBAN) return vec4(urban_albedo(xy, footprint), ground_texture(xy, footprint));
  if (f == PROBE_LAND_NATURE) {
    return vec4(forest_cover(xy, x[0].z, x[0].w, footprint), snow_cover(xy, x[0].z, x[0].w, x[3].x),
                land_noise(xy, x[3].y, 1u), pattern_detail(footprint, x[3].y));
  }
  if (f == PROBE_LAND_MEANS) return vec4(field_mean_albedo(x[0].z), row_crop_albedo(x[0].z).y);
  GroundSurface s = ground_surface(xy, x[0].z, vec3(x[2]), vec3(0.0f, 0.0f, 1.0f), footprint, t, land);
  return vec4(s.albedo, s.water);  // PROBE_GROUND_SURFACE
}

#ifndef __cplusplus
// The GPU probe passes x alone: the land cover bound to unit 8.
vec4 probe_land_cover(mat4 x) { return probe_land_cover(x, land_texture); }
#endif
