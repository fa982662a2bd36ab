// Probe of lib/noise_rows.glsl (shared GLSL/C++ subset; tests/test_library_probes.cpp).
// A probe walks one row segment (texels t0 .. t0 + count - 1 of row y, slice z) and returns
// four of its texels: t0 + i0 + k stride, k = 0..3. Texels that the Worley walk flags (F1 > 1,
// to be recomputed by the point functions) read -1. In GLSL the walk's output is a private
// array of the invocation, in C++ the arrays of a NoiseRowTarget.
// x[0] = (function, channel type, t0, y), x[1] = (z, count, i0, stride),
// x[2] = (frequency, octaves, lacunarity, gain), x[3] = (seed, period); the Worley part of
// perlin-worley is the channel's fBm with seed + 1. The functions (x[0].x):
const int PROBE_CHANNEL_WALK = 0;  // the channel's walk as noise_rows.comp runs it
const int PROBE_CHANNEL_POINTS = 1;  // noise_channel_value at the same texels
const int PROBE_ROW_SETUP = 2;  // fbm_norm, texels_below, perlin_row_is_wide, finish_texel
const int PROBE_ROW_FRAMES = 3;  // worley_slab, perlin_row_frame
const int PROBE_WORLEY_ROW = 4;
const int PROBE_PERLIN_ROW = 5;
const int PROBE_PERLIN_ROW_WIDE = 6;
const int PROBE_PERLIN_ROW_FINISH = 7;
const int PROBE_NOISE_TAKE = 8;
#ifdef __cplusplus
#define NOISE_ROWS_PROBE_PARAM , IN(NoiseRowTarget) target
#define NOISE_ROWS_PROBE_ARG , target
#define NOISE_ROWS_PROBE_VALUE(t) target.out[t]
#else
#include "../lib/noise_types.glsl"
float noise_rows_probe_out[NOISE_SEGMENT];
int noise_rows_probe_t0;
void noise_rows_probe_out8(int x0, vec4 lo, vec4 hi) {
  for (int j = 0; j < 4; ++j) {
    noise_rows_probe_out[x0 - noise_rows_probe_t0 + j] = lo[j];
    noise_rows_probe_out[x0 - noise_rows_probe_t0 + 4 + j] = hi[j];
  }
}
#define NOISE_OUT(x, value) noise_rows_probe_out[(x) - noise_rows_probe_t0] = (value)
#define NOISE_OUT8(x0, n, lo, hi) noise_rows_probe_out8(x0, lo, hi)
#include "../lib/noise_rows.glsl"
#define NOISE_ROWS_PROBE_PARAM
#define NOISE_ROWS_PROBE_ARG
#define NOISE_ROWS_PROBE_VALUE(t) noise_rows_probe_out[(t) - noise_rows_probe_t0]
#endif

NoiseChannel noise_rows_probe_channel(mat4 x) {
  NoiseChannel channel;  // members one by one: C++17 has no parenthesised aggregate initialisation
  channel.type = int(x[0].y);
  channel.fbm.frequency = x[2].x;
  channel.fbm.octaves = int(x[2].y);
  channel.fbm.lacunarity = x[2].z;
  channel.fbm.gain = x[2].w;
  channel.fbm.seed = uint(x[3].x);
  channel.fbm.period = ivec3(vec3(x[3].y, x[3].z, x[3].w));
  channel.worley = channel.fbm;
  channel.worley.seed = uint(x[3].x) + 1u;
  return channel;
}

vec4 noise_rows_probe_walk(mat4 x NOISE_ROWS_PROBE_PARAM) {
  int f = int(x[0].x);
  int t0 = int(x[0].z);
  int y = int(x[0].w);
  int z = int(x[1].x);
  int count = int(x[1].y);
  int first = t0 + int(x[1].z);
  int stride = int(x[1].w);
  NoiseChannel channel = noise_rows_probe_channel(x);
  FbmParams fbm = channel.fbm;
  NoiseFinish finish;
  finish.type = channel.type;
  finish.norm = fbm_norm(fbm);
  finish.worley_norm = fbm_norm(channel.worley);
  uvec3 key = noise_key(fbm.seed, 0u);
  uvec2 beyond = uvec2(0u);
  if (f == PROBE_CHANNEL_POINTS) {
    // The point functions that the walk accelerates, at the same texel centres.
    vec4 v = vec4(0.0f);
    for (int k = 0; k < 4; ++k)
      v[k] = noise_channel_value(vec3(float(first + k * stride), float(y), float(z)) + 0.5f, channel);
    return v;
  }
  if (f == PROBE_ROW_SETUP) {
    return vec4(fbm_norm(fbm), float(texels_below(t0, fbm.frequency)), perlin_row_is_wide(fbm.frequency) ? 1.0f : 0.0f,
                finish_texel(finish, x[1].z, x[1].w));
  }
  if (f == PROBE_ROW_FRAMES) {
    // Feature point k of the slab at lattice x = t0 around lattice row (y, z) seen from offsets
    // (x[1].w, x[1].w / 2), and the frame of the Perlin walk along texel row (y, z).
    int k = int(x[1].z);
    WorleySlab slab = worley_slab(t0, ivec3(y - 1, y, y + 1), ivec3(z - 1, z, z + 1), x[1].w, 0.5f * x[1].w, key);
    PerlinRowFrame frame = perlin_row_frame(y, z, fbm.frequency, fbm.period);
    return vec4(slab.x[k], slab.dyz[k], frame.fy, frame.w.y);
  }
  if (f == PROBE_CHANNEL_WALK) {
    // The channel's walk as shaders/noise/noise_rows.comp runs it.
    if (channel.type == NOISE_PERLIN) {
      perlin_fbm_row(t0, count, y, z, fbm, 0, true, finish NOISE_ROWS_PROBE_ARG);
    } else if (channel.type == NOISE_PERLIN_WORLEY) {
      perlin_fbm_row(t0, count, y, z, fbm, 0, false, finish NOISE_ROWS_PROBE_ARG);
      worley_fbm_row(t0, count, y, z, channel.worley, NOISE_SEGMENT, true, finish, beyond NOISE_ROWS_PROBE_ARG);
    } else {
      worley_fbm_row(t0, count, y, z, fbm, 0, true, finish, beyond NOISE_ROWS_PROBE_ARG);
    }
  } else if (f == PROBE_WORLEY_ROW) {
    worley_row(t0, count, y, z, fbm.frequency, fbm.period, key, 1.0f, 0, false, true, finish,
               beyond NOISE_ROWS_PROBE_ARG);
  } else if (f == PROBE_PERLIN_ROW) {
    perlin_row(t0, count, y, z, fbm.frequency, fbm.period, key, 1.0f, 0, false, true, finish NOISE_ROWS_PROBE_ARG);
  } else if (f == PROBE_PERLIN_ROW_WIDE) {
    perlin_row_wide(t0, count, y, z, fbm.frequency, fbm.period, key, 1.0f, 0, false, finish NOISE_ROWS_PROBE_ARG);
  } else if (f == PROBE_PERLIN_ROW_FINISH) {
    perlin_row_finish(t0, count, y, z, fbm.frequency, fbm.period, key, 1.0f, 0, false, finish NOISE_ROWS_PROBE_ARG);
  } else {
    // PROBE_NOISE_TAKE: two terms of texel t0, stored, then added and emitted.
    noise_take(t0, 0, 0, x[1].z, false, false, finish NOISE_ROWS_PROBE_ARG);
    noise_take(t0, 0, 0, x[1].w, true, true, finish NOISE_ROWS_PROBE_ARG);
    return vec4(NOISE_ROWS_PROBE_VALUE(t0), 0.0f, 0.0f, 0.0f);
  }
  vec4 v = vec4(0.0f);
  for (int k = 0; k < 4; ++k) {
    int i = first + k * stride - t0;
    bool flagged = (beyond[i >> 5] & (1u << uint(i & 31))) != 0u;
    v[k] = flagged ? -1.0f : NOISE_ROWS_PROBE_VALUE(first + k * stride);
  }
  return v;
}

#ifdef __cplusplus
vec4 probe_noise_rows(mat4 x) {
  std::vector<float> sums(NOISE_SUMS, 0.0f);
  std::vector<float> out(int(x[0].z) + NOISE_SEGMENT, 0.0f);
  NoiseRowTarget target;
  target.sums = sums.data();
  target.out = out.data();
  return noise_rows_probe_walk(x, target);
}
#undef NOISE_ROWS_PROBE_PARAM
#undef NOISE_ROWS_PROBE_ARG
#undef NOISE_ROWS_PROBE_VALUE
#else
vec4 probe_noise_rows(mat4 x) {
  noise_rows_probe_t0 = int(x[0].z);
  return noise_rows_probe_walk(x);
}
#endif
