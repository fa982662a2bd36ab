// Probe of lib/terrain.glsl (shared GLSL/C++ subset; tests/test_library_probes.cpp). The GLSL
// side reads the height field bound to texture unit 4. The functions (x[0].x):
const int PROBE_TERRAIN_PLANE = 0;
const int PROBE_TERRAIN_ALTITUDE = 1;  // terrain_altitude, terrain_clearance, terrain_ceiling
const int PROBE_TERRAIN_HIT = 2;
const int PROBE_TERRAIN_NORMAL = 3;
const int PROBE_TERRAIN_SUNLIT = 4;  // terrain_sunlit at terrain_normal
#ifndef __cplusplus
layout(binding = 4) uniform sampler2D terrain_heights;
#include "../lib/terrain.glsl"
#endif

// A 40 km square of 8 x 8 texels (5 km apart) on a sphere of radius 6367 km.
TerrainParams probe_terrain_params() {
  TerrainParams t;
  t.enabled = 1;
  t.extent = 20000.0f;
  t.top = 1201.0f;
  t.texel = 5000.0f;
  t.reach = 5000.0f;  // a ceiling window of 3 texels (the test's regional::terrain_ceilings)
  t.land = 0;  // no land cover (tests/probes/land_cover.glsl probes it)
  t.land_near = 1.0f;
  t.land_far = 1.0f;
  t.land_texels = 1.0f;
  t.snow_line = 2500.0f;
  t.crop_stage = 1.0f;
  return t;
}

// x[0] = (function, a, b, c), x[1] = a point (relative to the sphere's centre), x[2] = a
// direction, x[3] = further numbers.
vec4 probe_terrain(mat4 x, IN(TerrainTexture) terrain) {
  int f = int(x[0].x);
  float earth_radius = 6367000.0f;
  TerrainParams t = probe_terrain_params();
  t.enabled = int(x[0].w);
  vec3 q = vec3(x[1]);
  vec3 d = vec3(x[2]);
  if (f == PROBE_TERRAIN_PLANE) return vec4(terrain_plane(q, earth_radius), 0.0f, 0.0f);
  if (f == PROBE_TERRAIN_ALTITUDE) {
    return vec4(terrain_altitude(vec2(x[3]), t, terrain), terrain_clearance(q, earth_radius, t, terrain),
                terrain_ceiling(vec2(x[3]), t, terrain), 0.0f);
  }
  if (f == PROBE_TERRAIN_HIT) {
    int loops = 0;
    float s = terrain_hit(q, d, earth_radius, x[0].y, t, loops, terrain);
    return vec4(s, float(loops), 0.0f, 0.0f);
  }
  if (f == PROBE_TERRAIN_NORMAL) return vec4(terrain_normal(q, earth_radius, t, terrain), 0.0f);
  // PROBE_TERRAIN_SUNLIT
  int loops = 0;
  vec3 normal = terrain_normal(q, earth_radius, t, terrain);
  // Called before the vector is built: C++ leaves the order of a constructor's arguments open.
  float sunlit = terrain_sunlit(q, normal, d, earth_radius, t, loops, terrain);
  return vec4(sunlit, float(loops), 0.0f, 0.0f);
}

#ifndef __cplusplus
// The GPU probe passes x alone: the height field bound to unit 4.
vec4 probe_terrain(mat4 x) { return probe_terrain(x, terrain_heights); }
#endif
