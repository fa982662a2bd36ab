// Probe of lib/cover_density.glsl (shared GLSL/C++ subset; tests/test_library_probes.cpp).
// x[0] = (function, a, b, c), x[1] = the point, x[2] = (frequency, octaves, lacunarity, gain),
// x[3] = (seed, offset or further numbers). The functions (x[0].x):
const int PROBE_COVER_DENSITY = 0;
const int PROBE_COVER_DENSITY_SHIFTED = 1;
const int PROBE_COVER_FROM_DENSITY = 2;  // cover_from_density(a, b, c, x[3].y)
const int PROBE_SHAPED_DENSITY = 3;  // shaped_density(a, b, c, x[3].y, x[3].z)
const int PROBE_LAYER_BLEND = 4;  // layer_blend(a, b, c)
const int PROBE_SYSTEM_EDGE = 5;  // system_edge(a)
const int PROBE_WITH_SYSTEMS = 6;  // with_systems(a, b), with_cells(a, c) in y, with_moats(a, c) in z
const int PROBE_NOISE_BLEND = 7;  // noise_blend(a, b, c)
const int PROBE_CONTRAST = 8;  // cover_contrast(x[3].z, x[3].w, x[1].x), contrasted_cover(a, b, c, x[3].y, x[3].z) in y,
                               // cover_from_excess(a, c, x[3].y, x[3].w) in z
const int PROBE_COVER_DENSITY_FROM_GRID = 9;  // cover_density_from_grid(x[1], a, int(b), params, x[3].yzw)
#ifndef __cplusplus
#include "../lib/cover_density.glsl"
#endif
vec4 probe_cover_density(mat4 x) {
  int f = int(x[0].x);
  FbmParams params = make_fbm_params(x[2].x, int(x[2].y), x[2].z, x[2].w, uint(x[3].x), ivec3(0));
  if (f == PROBE_COVER_DENSITY) return vec4(cover_density(vec3(x[1]), params), 0.0f, 0.0f, 0.0f);
  if (f == PROBE_COVER_DENSITY_SHIFTED)
    return vec4(cover_density_shifted(vec3(x[1]), params, vec3(x[3].y, x[3].z, x[3].w)), 0.0f, 0.0f, 0.0f);
  if (f == PROBE_COVER_DENSITY_FROM_GRID)
    return vec4(cover_density_from_grid(vec3(x[1]), x[0].y, int(x[0].z), params, vec3(x[3].y, x[3].z, x[3].w)), 0.0f,
                0.0f, 0.0f);
  if (f == PROBE_LAYER_BLEND) return vec4(layer_blend(x[0].y, x[0].z, x[0].w), 0.0f, 0.0f, 0.0f);
  if (f == PROBE_SHAPED_DENSITY)
    return vec4(shaped_density(x[0].y, x[0].z, x[0].w, x[3].y, x[3].z), 0.0f, 0.0f, 0.0f);
  if (f == PROBE_NOISE_BLEND) return vec4(noise_blend(x[0].y, x[0].z, x[0].w), 0.0f, 0.0f, 0.0f);
  if (f == PROBE_WITH_SYSTEMS)
    return vec4(with_systems(x[0].y, x[0].z), with_cells(x[0].y, x[0].w), with_moats(x[0].y, x[0].w), 0.0f);
  if (f == PROBE_CONTRAST)
    return vec4(cover_contrast(x[3].z, x[3].w, x[1].x), contrasted_cover(x[0].y, x[0].z, x[0].w, x[3].y, x[3].z),
                cover_from_excess(x[0].y, x[0].w, x[3].y, x[3].w), 0.0f);
  if (f == PROBE_SYSTEM_EDGE) return vec4(system_edge(x[0].y), 0.0f, 0.0f, 0.0f);
  return vec4(cover_from_density(x[0].y, x[0].z, x[0].w, x[3].y), 0.0f, 0.0f, 0.0f);  // PROBE_COVER_FROM_DENSITY
}
