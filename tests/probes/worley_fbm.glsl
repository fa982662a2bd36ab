// Probe of lib/worley_fbm.glsl (shared GLSL/C++ subset; tests/test_library_probes.cpp).
// x[0] = (function, lambda or first octave, last octave, 0), x[1] = the point, x[2] = (frequency, octaves, lacunarity,
// gain), x[3] = (seed, period). The functions (x[0].x):
const int PROBE_INVERTED_WORLEY_FBM = 0;
const int PROBE_SMOOTH_WORLEY_FBM = 1;  // smooth_worley_fbm with lambda x[0].y
const int PROBE_NOISE_VOLUME_DETAIL = 2;  // inverted_worley_fbm with noise_volume_detail_fbm(seed)
// inverted_worley_octaves(p, params, x[0].y, x[0].z), fbm_norm(params) in y
const int PROBE_INVERTED_WORLEY_OCTAVES = 3;
#ifndef __cplusplus
#include "../lib/worley_fbm.glsl"
#endif
vec4 probe_worley_fbm(mat4 x) {
  FbmParams params =
      make_fbm_params(x[2].x, int(x[2].y), x[2].z, x[2].w, uint(x[3].x), ivec3(vec3(x[3].y, x[3].z, x[3].w)));
  if (int(x[0].x) == PROBE_SMOOTH_WORLEY_FBM) return smooth_worley_fbm(vec3(x[1]), params, x[0].y);
  if (int(x[0].x) == PROBE_INVERTED_WORLEY_OCTAVES)
    return vec4(inverted_worley_octaves(vec3(x[1]), params, int(x[0].y), int(x[0].z)), fbm_norm(params), 0.0f, 0.0f);
  if (int(x[0].x) == PROBE_NOISE_VOLUME_DETAIL) return inverted_worley_fbm(vec3(x[1]), noise_volume_detail_fbm(params.seed));
  return inverted_worley_fbm(vec3(x[1]), params);  // PROBE_INVERTED_WORLEY_FBM
}
