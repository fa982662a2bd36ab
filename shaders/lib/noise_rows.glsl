// The texture generator's fast path: one invocation walks a segment of a row of texels along
// x, so the lattice data of a cell (hashes, feature points, gradients) is computed once per
// cell and row instead of once per texel, and the y and z parts of every distance and dot
// product once per row. Perlin gives the same floats as the point functions of
// tileable_noise.glsl (bit for bit in C++; a GPU may fuse multiply-adds). Worley adds the y
// and z terms of a squared distance before the x term, one rounding apart from worley_f1
// (|dF1| <= 2^-24 F1), and leaves one case to the caller: texels whose F1 exceeds 1, where the
// 27 neighbour cells may not hold the nearest feature point, are flagged and must be
// recomputed with the point functions.
//
// Loops whose trip count is at least one are written do { } while (): SIMD CPU drivers such
// as llvmpipe run the body of a for loop once more with all lanes masked (docs/noise.md).
#ifndef NEPHELE_NOISE_ROWS_GLSL
#define NEPHELE_NOISE_ROWS_GLSL
#include "prelude.glsl"
#include "noise_types.glsl"
#include "tileable_noise.glsl"
// fbm_norm: the octaves' weights as the point functions sum them.
#include "worley_fbm.glsl"

// Where the walk keeps its sums (NOISE_SUMS floats, part k at offset k NOISE_SEGMENT) and where
// the last octave puts each texel's value. In GLSL the sums are a private array of the
// invocation (passed as an inout parameter, a large array is copied at every call: Mesa 22 took
// seconds to compile that) and the includer defines NOISE_OUT(x, value) to store texel x of the
// row, and NOISE_OUT8(x0, n, lo, hi) for texels x0 .. x0 + 7 (n of them in the row, the rest
// in its padding); in C++ both are arrays of the caller.
const int NOISE_SUMS = 2 * NOISE_SEGMENT;
#ifdef __cplusplus
struct NoiseRowTarget {
  float* sums;  // NOISE_SUMS floats
  float* out;   // the row, indexed by x
};
#define NOISE_ROW_PARAM , IN(NoiseRowTarget) target
#define NOISE_ROW_ARG , target
#define NOISE_SUM(i) target.sums[i]
#define NOISE_OUT(x, value) target.out[x] = (value)
void noise_out8(float* out, int x0, int n, vec4 lo, vec4 hi) {
  for (int j = 0; j < n; ++j) out[x0 + j] = j < 4 ? lo[j] : hi[j - 4];
}
#define NOISE_OUT8(x0, n, lo, hi) noise_out8(target.out, x0, n, lo, hi)
#else
#define NOISE_ROW_PARAM
#define NOISE_ROW_ARG
#define NOISE_SUM(i) noise_sums[i]
float noise_sums[NOISE_SUMS];
#endif

// The value of a texel from its fBm sum, as noise_channel_value computes it; perlin_sum is the
// Perlin part's sum of perlin-worley (whose Worley part emits).
float finish_texel(IN(NoiseFinish) finish, float sum, float perlin_sum) {
  if (finish.type == NOISE_PERLIN) return perlin_unit(sum / finish.norm);
  if (finish.type == NOISE_PERLIN_WORLEY)
    return perlin_worley(perlin_unit(perlin_sum / finish.norm), worley_unit(sum / finish.worley_norm, true));
  return worley_unit(sum / finish.norm, finish.type == NOISE_INVERTED_WORLEY);
}

// What the row walks do with each texel's term: store it (octave 0), add it to the sums, or,
// with emit, finish the texel and hand it to NOISE_OUT. Callers pass constant flags so that
// the compiler keeps only one of these per call.
void noise_take(int t, int i, int sums, float term, bool accumulate, bool emit,
                IN(NoiseFinish) finish NOISE_ROW_PARAM) {
  float total = accumulate ? NOISE_SUM(sums + i) + term : term;
  if (emit) {
    NOISE_OUT(t, finish_texel(finish, total, NOISE_SUM(i)));
  } else {
    NOISE_SUM(sums + i) = total;
  }
}

// The number of texels t >= 0 whose centre (t + 1/2) frequency lies below the integer c, i.e.
// the first texel of cell c, with the same float rounding as the texels' own coordinates.
// The estimate errs by float rounding only (far below a texel for sizes up to 2^16), so one
// step either way settles it; no loop, which a SIMD driver would run at least twice.
int texels_below(int c, float frequency) {
  int t = max(int(ceil(float(c) / frequency - 0.5f)), 0);
  if ((float(t) + 0.5f) * frequency < float(c)) t += 1;
  if (t > 0 && (float(t - 1) + 0.5f) * frequency >= float(c)) t -= 1;
  return t;
}

// Feature points of the cells (x, ys[j], zs[k]) (wrapped indices) as seen from the row through
// (fy, fz): their x offsets, and the y and z terms of the squared distance (formed as
// worley_candidate forms them), summed once per row so that a texel needs one multiply-add.
WorleySlab worley_slab(int x, ivec3 ys, ivec3 zs, float fy, float fz, uvec3 key) {
  WorleySlab slab;
  for (int k = 0; k < 3; ++k) {
    for (int j = 0; j < 3; ++j) {
      vec3 feature = hash_to_unit3(pcg3d(uvec3(ivec3(x, ys[j], zs[k])) ^ key));
      float dy = fy - (float(j - 1) + feature.y);
      float dz = fz - (float(k - 1) + feature.z);
      slab.x[3 * k + j] = feature.x;
      slab.dyz[3 * k + j] = dy * dy + dz * dz;
    }
  }
  return slab;
}

// Takes (noise_take) weight F1 (worley_f1 at p frequency) for the texels t0 <= t < t0 + count
// of the row (y, z) into sums + t - t0, and sets bit t - t0 of `beyond` where F1 > 1. Cells
// must be at least one texel wide (frequency <= 1), count >= 1.
void worley_row(int t0, int count, int y, int z, float frequency, ivec3 period, uvec3 key,
                float weight, int sums, bool accumulate, bool emit, IN(NoiseFinish) finish,
                INOUT(uvec2) beyond NOISE_ROW_PARAM) {
  float py = (float(y) + 0.5f) * frequency;
  float pz = (float(z) + 0.5f) * frequency;
  float by = floor(py);
  float bz = floor(pz);
  float fy = py - by;
  float fz = pz - bz;
  int cy = int(by);
  int cz = int(bz);
  ivec3 ys = wrapped_neighbours(cy, period.y);
  ivec3 zs = wrapped_neighbours(cz, period.z);
  int cx = int(floor((float(t0) + 0.5f) * frequency));
  int last = int(floor((float(t0 + count - 1) + 0.5f) * frequency));
  WorleySlab left = worley_slab(wrap_axis(cx - 1, period.x), ys, zs, fy, fz, key);
  WorleySlab middle = worley_slab(wrap_axis(cx, period.x), ys, zs, fy, fz, key);
  int t = t0;
  do {
    WorleySlab right = worley_slab(wrap_axis(cx + 1, period.x), ys, zs, fy, fz, key);
    int end = min(t0 + count, texels_below(cx + 1, frequency));
    if (t < end) {  // float rounding can leave a cell one texel wide without a texel centre
      do {
        float fx = (float(t) + 0.5f) * frequency - float(cx);
        float best = 1.0e30f;
        for (int n = 0; n < 9; ++n) {
          // (offset + feature) - as in worley_candidate, so that the floats agree
          float dl = fx - (-1.0f + left.x[n]);
          float dm = fx - middle.x[n];
          float dr = fx - (1.0f + right.x[n]);
          best = min(best, dl * dl + left.dyz[n]);
          best = min(best, dm * dm + middle.dyz[n]);
          best = min(best, dr * dr + right.dyz[n]);
        }
        int i = t - t0;
        noise_take(t, i, sums, weight * sqrt(best), accumulate, emit, finish NOISE_ROW_ARG);
        if (best > 1.0f) beyond[i >> 5] |= 1u << uint(i & 31);
        ++t;
      } while (t < end);
    }
    left = middle;
    middle = right;
    ++cx;
  } while (cx <= last);
}

// The part of a Perlin row walk that depends on the row (y, z) only (PerlinRowFrame).
PerlinRowFrame perlin_row_frame(int y, int z, float frequency, ivec3 period) {
  PerlinRowFrame r;
  float py = (float(y) + 0.5f) * frequency;
  float pz = (float(z) + 0.5f) * frequency;
  float by = floor(py);
  float bz = floor(pz);
  r.fy = py - by;
  r.fz = pz - bz;
  int cy = wrap_axis(int(by), period.y);
  int cz = wrap_axis(int(bz), period.z);
  r.ys = ivec2(cy, wrap_step(cy, 1, period.y));
  r.zs = ivec2(cz, wrap_step(cz, 1, period.z));
  r.w = perlin_yz_weights(r.fy, r.fz);
  return r;
}

// Takes weight perlin_noise(p frequency) for the texels of a row segment, as worley_row.
void perlin_row(int t0, int count, int y, int z, float frequency, ivec3 period, uvec3 key,
                float weight, int sums, bool accumulate, bool emit, IN(NoiseFinish) finish
                NOISE_ROW_PARAM) {
  PerlinRowFrame r = perlin_row_frame(y, z, frequency, period);
  int cx = int(floor((float(t0) + 0.5f) * frequency));
  int last = int(floor((float(t0 + count - 1) + 0.5f) * frequency));
  vec2 face0 = perlin_face(wrap_axis(cx, period.x), r.ys, r.zs, r.fy, r.fz, r.w, key);
  int t = t0;
  do {
    vec2 face1 = perlin_face(wrap_axis(cx + 1, period.x), r.ys, r.zs, r.fy, r.fz, r.w, key);
    int end = min(t0 + count, texels_below(cx + 1, frequency));
    if (t < end) {
      do {
        float fx = (float(t) + 0.5f) * frequency - float(cx);
        noise_take(t, t - t0, sums, weight * perlin_along_row(face0, face1, fx), accumulate, emit,
                   finish NOISE_ROW_ARG);
        ++t;
      } while (t < end);
    }
    face0 = face1;
    ++cx;
  } while (cx <= last);
}

// Whether perlin_row_wide may walk an octave: 8 texels then span at most two cells. Exactly 8
// texels per cell is exact in float; otherwise the 1% margin covers the rounding of texel
// positions far beyond any texture size.
bool perlin_row_is_wide(float frequency) {
  return frequency == 0.125f || frequency <= 0.124f;
}

// perlin_row for an octave that finishes a Perlin channel and whose cells are at least 8
// texels wide: eight texels per pass, unrolled, each taking the faces of its own cell (the
// chunk's first cell or the next one), and handed to NOISE_OUT8 from registers. A SIMD driver
// pays more for a loop pass and a private-array store per texel than for the noise itself.
// The faces slide once per chunk (a SIMD driver computes the next face every chunk). t0 must
// be a multiple of NOISE_SEGMENT and the row padded to one.
void perlin_row_wide(int t0, int count, int y, int z, float frequency, ivec3 period, uvec3 key,
                     float weight, int sums, bool accumulate, IN(NoiseFinish) finish NOISE_ROW_PARAM) {
  PerlinRowFrame r = perlin_row_frame(y, z, frequency, period);
  int cx = int(floor((float(t0) + 0.5f) * frequency));
  vec2 face0 = perlin_face(wrap_axis(cx, period.x), r.ys, r.zs, r.fy, r.fz, r.w, key);
  vec2 face1 = perlin_face(wrap_axis(cx + 1, period.x), r.ys, r.zs, r.fy, r.fz, r.w, key);
  vec2 face2 = perlin_face(wrap_axis(cx + 2, period.x), r.ys, r.zs, r.fy, r.fz, r.w, key);
  // The whole segment, unrolled (a constant trip count): no loop to run, constant indices.
  // Texels past count fill the row's padding.
  for (int chunk = 0; chunk < NOISE_SEGMENT; chunk += 8) {
    int t = t0 + chunk;
    float v[8];
    for (int j = 0; j < 8; ++j) {
      float px = (float(t + j) + 0.5f) * frequency;
      float cell = floor(px);
      bool next = cell > float(cx);
      float term = weight * perlin_along_row(next ? face1 : face0, next ? face2 : face1, px - cell);
      v[j] = finish_texel(finish, accumulate ? NOISE_SUM(sums + chunk + j) + term : term, 0.0f);
    }
    NOISE_OUT8(t, clamp(count - chunk, 0, 8), vec4(v[0], v[1], v[2], v[3]), vec4(v[4], v[5], v[6], v[7]));
    bool slide = floor((float(t + 8) + 0.5f) * frequency) > float(cx);
    vec2 face3 = perlin_face(wrap_axis(cx + 3, period.x), r.ys, r.zs, r.fy, r.fz, r.w, key);
    if (slide) {
      face0 = face1;
      face1 = face2;
      face2 = face3;
      cx += 1;
    }
  }
}

// The finishing octave of a Perlin channel: perlin_row_wide where it applies. The choice is a
// define in GLSL (NOISE_PERLIN_WIDE, set by the host by the same rule), as a SIMD driver would
// run both.
void perlin_row_finish(int t0, int count, int y, int z, float frequency, ivec3 period, uvec3 key,
                       float weight, int sums, bool accumulate, IN(NoiseFinish) finish NOISE_ROW_PARAM) {
#ifdef __cplusplus
  bool wide = perlin_row_is_wide(frequency);
#elif defined(NOISE_PERLIN_WIDE)
  const bool wide = true;
#else
  const bool wide = false;
#endif
  if (wide) {
    perlin_row_wide(t0, count, y, z, frequency, period, key, weight, sums, accumulate, finish NOISE_ROW_ARG);
  } else {
    perlin_row(t0, count, y, z, frequency, period, key, weight, sums, accumulate, true, finish NOISE_ROW_ARG);
  }
}

// The octaves of worley_fbm_mean over a row segment: octave 0 stores its terms into the sums
// (the point functions' 0 + 1 F1 is the same float), later octaves add theirs, and with emit
// the last octave finishes each texel instead of storing it. Three calls with constant flags
// rather than flags that vary in one loop: a SIMD driver would run every variant each octave.
// A shader may make fbm.octaves a compile-time constant; the conditions then fold away (such
// drivers also run the body of a loop that runs zero times).
void worley_fbm_row(int t0, int count, int y, int z, IN(FbmParams) fbm, int sums, bool emit,
                    IN(NoiseFinish) finish, INOUT(uvec2) beyond NOISE_ROW_PARAM) {
  int last = fbm.octaves - 1;
  if (last == 0) {
    worley_row(t0, count, y, z, fbm.frequency, fbm.period, noise_key(fbm.seed, 0u), 1.0f, sums,
               false, emit, finish, beyond NOISE_ROW_ARG);
  } else {
    worley_row(t0, count, y, z, fbm.frequency, fbm.period, noise_key(fbm.seed, 0u), 1.0f, sums,
               false, false, finish, beyond NOISE_ROW_ARG);
    float amplitude = 1.0f;
    float frequency = fbm.frequency;
    ivec3 period = fbm.period;
    next_octave(fbm, amplitude, frequency, period);
    int octave = 1;
    if (last > 1) {
      do {
        worley_row(t0, count, y, z, frequency, period, noise_key(fbm.seed, uint(octave)), amplitude,
                   sums, true, false, finish, beyond NOISE_ROW_ARG);
        next_octave(fbm, amplitude, frequency, period);
        ++octave;
      } while (octave < last);
    }
    worley_row(t0, count, y, z, frequency, period, noise_key(fbm.seed, uint(octave)), amplitude,
               sums, true, emit, finish, beyond NOISE_ROW_ARG);
  }
}

// The same for perlin_fbm_mean.
void perlin_fbm_row(int t0, int count, int y, int z, IN(FbmParams) fbm, int sums, bool emit,
                    IN(NoiseFinish) finish NOISE_ROW_PARAM) {
  int last = fbm.octaves - 1;
  if (last == 0) {
    if (emit) {
      perlin_row_finish(t0, count, y, z, fbm.frequency, fbm.period, noise_key(fbm.seed, 0u), 1.0f, sums,
                        false, finish NOISE_ROW_ARG);
    } else {
      perlin_row(t0, count, y, z, fbm.frequency, fbm.period, noise_key(fbm.seed, 0u), 1.0f, sums,
                 false, false, finish NOISE_ROW_ARG);
    }
  } else {
    perlin_row(t0, count, y, z, fbm.frequency, fbm.period, noise_key(fbm.seed, 0u), 1.0f, sums,
               false, false, finish NOISE_ROW_ARG);
    float amplitude = 1.0f;
    float frequency = fbm.frequency;
    ivec3 period = fbm.period;
    next_octave(fbm, amplitude, frequency, period);
    int octave = 1;
    if (last > 1) {
      do {
        perlin_row(t0, count, y, z, frequency, period, noise_key(fbm.seed, uint(octave)), amplitude,
                   sums, true, false, finish NOISE_ROW_ARG);
        next_octave(fbm, amplitude, frequency, period);
        ++octave;
      } while (octave < last);
    }
    if (emit) {
      perlin_row_finish(t0, count, y, z, frequency, period, noise_key(fbm.seed, uint(octave)), amplitude,
                        sums, true, finish NOISE_ROW_ARG);
    } else {
      perlin_row(t0, count, y, z, frequency, period, noise_key(fbm.seed, uint(octave)), amplitude,
                 sums, true, false, finish NOISE_ROW_ARG);
    }
  }
}

#ifdef __cplusplus
// The macros above were expanded where they were used; keep them out of other C++ code.
#undef NOISE_ROW_PARAM
#undef NOISE_ROW_ARG
#undef NOISE_SUM
#undef NOISE_OUT
#undef NOISE_OUT8
#endif

#endif
