// Tileable noise textures, evaluated point by point: the reference for the row walk of
// noise_rows.glsl (which the texture generator runs) and for random access. Points are in
// texel units: texel t has its centre at t + 1/2 (docs/noise.md).
#ifndef NEPHELE_TILEABLE_NOISE_GLSL
#define NEPHELE_TILEABLE_NOISE_GLSL
#include "prelude.glsl"
#include "noise_types.glsl"
#include "worley.glsl"
#include "perlin.glsl"

// F1 with one feature point per unit cell is below sqrt(3) (the feature point of p's own
// cell is nearer than the cell's diagonal), so F1 / sqrt(3) lies in [0, 1] without clipping.
const float WORLEY_F1_BOUND = 1.7320508f;

// Octave k + 1 from octave k, as inverted_worley_fbm (worley_fbm.glsl) steps: the period is
// rounded to whole cells; the texture generator only accepts lacunarities that keep it exact.
void next_octave(IN(FbmParams) fbm, INOUT(float) amplitude, INOUT(float) frequency,
                 INOUT(ivec3) period) {
  amplitude *= fbm.gain;
  frequency *= fbm.lacunarity;
  period = ivec3(vec3(period) * fbm.lacunarity + 0.5f);
}

// sum_k a_k n_k / sum_k a_k over the octaves, a_k = gain^k, f_k = frequency lacunarity^k,
// octave k hashed with noise_key(seed, k); n_k = F1(p f_k) (worley_f1) or, with perlin,
// perlin_noise(p f_k). Callers pass a constant flag. Needs octaves >= 1.
float noise_fbm_mean(vec3 p, IN(FbmParams) fbm, bool perlin) {
  float sum = 0.0f;
  float norm = 0.0f;
  float amplitude = 1.0f;
  float frequency = fbm.frequency;
  ivec3 period = fbm.period;
  int octave = 0;
  do {
    uvec3 key = noise_key(fbm.seed, uint(octave));
    float value = perlin ? perlin_noise(p * frequency, period, key) : worley_f1(p * frequency, period, key).w;
    sum += amplitude * value;
    norm += amplitude;
    next_octave(fbm, amplitude, frequency, period);
    ++octave;
  } while (octave < fbm.octaves);
  return sum / norm;
}

// The weighted mean of worley_f1's F1 (see noise_fbm_mean).
float worley_fbm_mean(vec3 p, IN(FbmParams) fbm) { return noise_fbm_mean(p, fbm, false); }

// The weighted mean of perlin_noise, in [-PERLIN_BOUND, PERLIN_BOUND].
float perlin_fbm_mean(vec3 p, IN(FbmParams) fbm) { return noise_fbm_mean(p, fbm, true); }

// [0, 1] values of the channel types from the means above.
float worley_unit(float mean_f1, bool inverted) {
  float v = mean_f1 * (1.0f / WORLEY_F1_BOUND);
  return inverted ? 1.0f - v : v;
}

float perlin_unit(float mean_noise) {
  return 0.5f + mean_noise * (0.5f / PERLIN_BOUND);
}

// Perlin-Worley after A. Schneider, "The real-time volumetric cloudscapes of Horizon Zero
// Dawn", SIGGRAPH 2015 course, and GPU Pro 7 (2016): remap(perlin, worley - 1, 1, 0, 1) with
// remap(v, l, h, a, b) = a + (v - l)(b - a)/(h - l) and worley the inverted Worley fBm. For
// perlin, worley in [0, 1] the result lies in [0, 1]: the Perlin field, dilated by the
// billowy Worley cells.
float perlin_worley(float perlin, float worley) {
  return (perlin - (worley - 1.0f)) / (1.0f - (worley - 1.0f));
}

float worley_channel_value(vec3 p, IN(NoiseChannel) channel) {
  return worley_unit(worley_fbm_mean(p, channel.fbm), channel.type == NOISE_INVERTED_WORLEY);
}

float perlin_channel_value(vec3 p, IN(NoiseChannel) channel) {
  return perlin_unit(perlin_fbm_mean(p, channel.fbm));
}

float perlin_worley_channel_value(vec3 p, IN(NoiseChannel) channel) {
  return perlin_worley(perlin_unit(perlin_fbm_mean(p, channel.fbm)),
                       worley_unit(worley_fbm_mean(p, channel.worley), true));
}

// The value of a channel at p (texel units), in [0, 1]. Shaders call the type's function
// directly: GPUs built on SIMD lanes may run every branch of a run-time switch.
float noise_channel_value(vec3 p, IN(NoiseChannel) channel) {
  if (channel.type == NOISE_PERLIN) return perlin_channel_value(p, channel);
  if (channel.type == NOISE_PERLIN_WORLEY) return perlin_worley_channel_value(p, channel);
  return worley_channel_value(p, channel);
}

#endif
