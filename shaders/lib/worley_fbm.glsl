// Fractal sums (fBm) of inverted Worley noise 1 - F1, with their gradients.
#ifndef NEPHELE_WORLEY_FBM_GLSL
#define NEPHELE_WORLEY_FBM_GLSL
#include "prelude.glsl"
#include "worley.glsl"
#include "parameters.glsl"

// The parameters of an fBm, member by member (C++17 has no parenthesised aggregate
// initialisation, and the struct is parameters.glsl's, which holds no functions).
FbmParams make_fbm_params(float frequency, int octaves, float lacunarity, float gain, uint seed, ivec3 period) {
  FbmParams fbm;
  fbm.frequency = frequency;
  fbm.octaves = octaves;
  fbm.lacunarity = lacunarity;
  fbm.gain = gain;
  fbm.seed = seed;
  fbm.period = period;
  return fbm;
}

// sum_k gain^k n_k(p frequency lacunarity^k) / sum_k gain^k and its gradient d/dp, where n_k
// is 1 - F1 (smoothing 0) or smooth_worley with lambda = smoothing (worley.glsl).
vec4 smooth_worley_fbm(vec3 p, IN(FbmParams) params, float smoothing) {
  vec4 sum = vec4(0.0f);
  float amplitude = 1.0f;
  float frequency = params.frequency;
  float norm = 0.0f;
  ivec3 period = params.period;
  for (int octave = 0; octave < params.octaves; ++octave) {
    uvec3 key = noise_key(params.seed, uint(octave));
    vec4 octave_value;
    if (smoothing > 0.0f) {
      vec4 w = smooth_worley(p * frequency, period, key, smoothing);
      octave_value = vec4(frequency * vec3(w), w.w);
    } else {
      vec4 f1 = worley_f1(p * frequency, period, key);
      octave_value = vec4(-frequency * vec3(f1), 1.0f - f1.w);
    }
    sum += amplitude * octave_value;
    norm += amplitude;
    amplitude *= params.gain;
    frequency *= params.lacunarity;
    period = ivec3(vec3(period) * params.lacunarity + 0.5f);
  }
  return norm > 0.0f ? sum / norm : vec4(0.0f);
}

// The classic fBm of 1 - F1: value in [1 - sqrt(3), 1], 1 on feature points.
vec4 inverted_worley_fbm(vec3 p, IN(FbmParams) params) {
  return smooth_worley_fbm(p, params, 0.0f);
}

// The weights' sum of an fBm's octaves, sum_k gain^k over k < octaves: its normalisation.
float fbm_norm(IN(FbmParams) params) {
  float norm = 0.0f;
  float amplitude = 1.0f;
  for (int octave = 0; octave < params.octaves; ++octave) {
    norm += amplitude;
    amplitude *= params.gain;
  }
  return norm;
}

// Octaves [first, last) of inverted_worley_fbm's value before the normalisation: sum_k gain^k
// (1 - F1(p frequency lacunarity^k)) with each octave's frequency, period and key as there, so that
// the sums of [0, g) and [g, octaves), over fbm_norm, make the whole fBm (up to the additions'
// rounding). The density pass takes the low octaves at the warp grid's nodes and the others at
// each texel (docs/numerics.md, "The noise grid"). The first loop only steps the octaves' scales:
// the Worley searches run in the second, for [first, last) alone.
float inverted_worley_octaves(vec3 p, IN(FbmParams) params, int first, int last) {
  float amplitude = 1.0f;
  float frequency = params.frequency;
  ivec3 period = params.period;
  for (int octave = 0; octave < first; ++octave) {
    amplitude *= params.gain;
    frequency *= params.lacunarity;
    period = ivec3(vec3(period) * params.lacunarity + 0.5f);
  }
  float sum = 0.0f;
  for (int octave = first; octave < last; ++octave) {
    sum += amplitude * (1.0f - worley_f1(p * frequency, period, noise_key(params.seed, uint(octave))).w);
    amplitude *= params.gain;
    frequency *= params.lacunarity;
    period = ivec3(vec3(period) * params.lacunarity + 0.5f);
  }
  return sum;
}

// The renderer's noise volume's detail channel (render/noise_volume.comp, G, before the host's
// rank equalisation): inverted Worley fBm of 8 cells and 3 octaves of gain 1/2 a period, of its
// own seed. The coverage windows' calibration evaluates the same (tests/test_webanck_coverage.cpp).
FbmParams noise_volume_detail_fbm(uint seed) {
  return make_fbm_params(8.0f, 3, 2.0f, 0.5f, seed ^ 0x5bd1e995u, ivec3(8));
}

#endif
