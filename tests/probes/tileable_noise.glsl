// Probe of lib/tileable_noise.glsl (shared GLSL/C++ subset; tests/test_library_probes.cpp).
// x[1] = the point (texel units), x[2] = (frequency, octaves, lacunarity, gain) of the channel's
// fBm, x[3] = (seed, period); the Worley part of perlin-worley has half the frequency and
// period, one octave fewer and seed + 1. x[0] = (function, channel type, a, b). The functions
// (x[0].x):
const int PROBE_NEXT_OCTAVE = 0;  // next_octave from amplitude a, frequency b
const int PROBE_FBM_MEANS = 1;  // worley_fbm_mean, perlin_fbm_mean, noise_fbm_mean
const int PROBE_UNIT_MAPS = 2;  // worley_unit(a), perlin_unit(b), perlin_worley(a, b)
const int PROBE_CHANNEL_VALUES = 3;  // the channel values of each type and noise_channel_value
#ifndef __cplusplus
#include "../lib/tileable_noise.glsl"
#endif
NoiseChannel tileable_noise_probe_channel(mat4 x, int type) {
  NoiseChannel channel;  // members one by one: C++17 has no parenthesised aggregate initialisation
  channel.type = type;
  channel.fbm.frequency = x[2].x;
  channel.fbm.octaves = int(x[2].y);
  channel.fbm.lacunarity = x[2].z;
  channel.fbm.gain = x[2].w;
  channel.fbm.seed = uint(x[3].x);
  channel.fbm.period = ivec3(vec3(x[3].y, x[3].z, x[3].w));
  channel.worley = channel.fbm;
  channel.worley.frequency = 0.5f * x[2].x;
  channel.worley.octaves = max(int(x[2].y) - 1, 1);
  channel.worley.seed = uint(x[3].x) + 1u;
  channel.worley.period = channel.fbm.period / 2;
  return channel;
}
vec4 probe_tileable_noise(mat4 x) {
  int f = int(x[0].x);
  vec3 p = vec3(x[1]);
  NoiseChannel channel = tileable_noise_probe_channel(x, int(x[0].y));
  if (f == PROBE_NEXT_OCTAVE) {
    float amplitude = x[0].z;
    float frequency = x[0].w;
    ivec3 period = channel.fbm.period;
    next_octave(channel.fbm, amplitude, frequency, period);
    return vec4(amplitude, frequency, float(period.x), float(period.z));
  }
  if (f == PROBE_FBM_MEANS)
    return vec4(worley_fbm_mean(p, channel.fbm), perlin_fbm_mean(p, channel.fbm),
                noise_fbm_mean(p, channel.fbm, false), noise_fbm_mean(p, channel.fbm, true));
  if (f == PROBE_UNIT_MAPS)
    return vec4(worley_unit(x[0].z, false), worley_unit(x[0].z, true), perlin_unit(x[0].w),
                perlin_worley(x[0].z, x[0].w));
  // PROBE_CHANNEL_VALUES
  return vec4(worley_channel_value(p, channel), perlin_channel_value(p, channel),
              perlin_worley_channel_value(p, channel), noise_channel_value(p, channel));
}
