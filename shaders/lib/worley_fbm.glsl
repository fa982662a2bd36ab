// Fractal sums (fBm) of inverted Worley noise 1 - F1, with their gradients.
#ifndef NEPHELE_WORLEY_FBM_GLSL
#define NEPHELE_WORLEY_FBM_GLSL
#include "prelude.glsl"
#include "worley.glsl"
#include "parameters.glsl"


// sum_k gain^k (1 - F1(p frequency lacunarity^k)) / sum_k gain^k and its gradient d/dp.
// Returns vec4(gradient, value); value lies in [1 - sqrt(3), 1] and is 1 on feature points.
vec4 inverted_worley_fbm(vec3 p, IN(FbmParams) params) {
  vec4 sum = vec4(0.0f);
  float amplitude = 1.0f;
  float frequency = params.frequency;
  float norm = 0.0f;
  ivec3 period = params.period;
  for (int octave = 0; octave < params.octaves; ++octave) {
    vec4 f1 = worley_f1(p * frequency, period, noise_key(params.seed, uint(octave)));
    sum += amplitude * vec4(-frequency * vec3(f1), 1.0f - f1.w);
    norm += amplitude;
    amplitude *= params.gain;
    frequency *= params.lacunarity;
    period = ivec3(vec3(period) * params.lacunarity + 0.5f);
  }
  return norm > 0.0f ? sum / norm : vec4(0.0f);
}

#endif
