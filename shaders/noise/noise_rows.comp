#version 450
// The texture generator: each invocation computes one row segment of one channel with the row
// walk of noise_rows.glsl; segments with texels that the walk cannot vouch for (F1 > 1) go to
// a list that noise_patch.comp recomputes. Invocations of a group hold consecutive rows, so
// the walk along x (cells, loop bounds) is the same for every lane of a SIMD vector (32 rows:
// four of llvmpipe's 8-lane vectors, fewer groups to schedule than with 8). Variants
// (defines), so that a SIMD driver, which runs both sides of every branch, runs only what the
// channel needs: NOISE_TYPE (a NOISE_* number), NOISE_OCTAVES, for perlin-worley
// NOISE_WORLEY_OCTAVES, and NOISE_PERLIN_WIDE when a Perlin channel's last octave has cells
// of 8 texels or more (perlin_row_wide).
#extension GL_ARB_gpu_shader_int64 : enable
layout(local_size_x = 32, local_size_y = 1, local_size_z = 1) in;

#ifdef GL_ARB_gpu_shader_int64
// Eight floats per store: llvmpipe stores to buffers one lane and one component at a time, at
// a cost of about 25 instructions each (docs/noise.md).
layout(std430, binding = 0) writeonly buffer Values { u64vec4 values[]; };
#define VALUES_PER_ELEMENT 8
#else
layout(std430, binding = 0) writeonly buffer Values { vec4 values[]; };
#define VALUES_PER_ELEMENT 4
#endif
// Entries: (y | slice << 16, t0, texel bits 0-31, texel bits 32-63) of the segment.
layout(std430, binding = 1) buffer Patches { uint patch_count; uint patch_capacity; uint pad0; uint pad1; uvec4 patches[]; };

#include "../lib/noise_types.glsl"
// The segment's finished texels, stored to `values` in chunks at the end.
float noise_out[NOISE_SEGMENT];
int row_t0;
#define NOISE_OUT(x, value) noise_out[(x) - row_t0] = (value)
int row_element;  // the row's first element in `values`
void store_chunk(int x0, vec4 lo, vec4 hi) {
#ifdef GL_ARB_gpu_shader_int64
  values[row_element + x0 / 8] = u64vec4(packUint2x32(floatBitsToUint(vec2(lo.x, lo.y))),
                                         packUint2x32(floatBitsToUint(vec2(lo.z, lo.w))),
                                         packUint2x32(floatBitsToUint(vec2(hi.x, hi.y))),
                                         packUint2x32(floatBitsToUint(vec2(hi.z, hi.w))));
#else
  values[row_element + x0 / 4] = lo;
  values[row_element + x0 / 4 + 1] = hi;
#endif
}
#define NOISE_OUT8(x0, n, lo, hi) store_chunk(x0, lo, hi)
#include "../lib/noise_rows.glsl"

#ifndef NOISE_TYPE
#define NOISE_TYPE 0
#endif
#ifndef NOISE_OCTAVES
#define NOISE_OCTAVES 1
#endif
#ifndef NOISE_WORLEY_OCTAVES
#define NOISE_WORLEY_OCTAVES 1
#endif

uniform NoiseChannel u_channel;
uniform ivec3 u_size;  // texels of the whole texture
uniform int u_z0;      // first slice of this dispatch
uniform int u_slices;  // slices in this dispatch
uniform int u_stride;  // floats per row in `values`, a multiple of NOISE_SEGMENT

void main() {
  int y = int(gl_GlobalInvocationID.x);
  int slice = int(gl_GlobalInvocationID.y);
  int t0 = int(gl_GlobalInvocationID.z) * NOISE_SEGMENT;
  if (y >= u_size.y || slice >= u_slices || t0 >= u_size.x) return;
  int z = u_z0 + slice;
  int count = min(NOISE_SEGMENT, u_size.x - t0);
  row_t0 = t0;
  row_element = (slice * u_size.y + y) * u_stride / VALUES_PER_ELEMENT;
  FbmParams fbm = u_channel.fbm;
  fbm.octaves = NOISE_OCTAVES;
  FbmParams worley = u_channel.worley;
  worley.octaves = NOISE_WORLEY_OCTAVES;
  NoiseFinish finish = NoiseFinish(NOISE_TYPE, fbm_norm(fbm), fbm_norm(worley));
  uvec2 beyond = uvec2(0u);
#if NOISE_TYPE == 2
  perlin_fbm_row(t0, count, y, z, fbm, 0, true, finish);
#elif NOISE_TYPE == 3
  perlin_fbm_row(t0, count, y, z, fbm, 0, false, finish);
  worley_fbm_row(t0, count, y, z, worley, NOISE_SEGMENT, true, finish, beyond);
#else
  worley_fbm_row(t0, count, y, z, fbm, 0, true, finish, beyond);
#endif
#ifndef NOISE_PERLIN_WIDE  // (perlin_row_wide stored its chunks)
  int element = ((slice * u_size.y + y) * u_stride + t0) / VALUES_PER_ELEMENT;
  // The whole segment, unrolled: constant indices make the array reads plain loads and keep
  // the stores out of a loop (texels past count land in the row's padding).
  for (int i = 0; i < NOISE_SEGMENT; i += 8) {
#ifdef GL_ARB_gpu_shader_int64
    values[element + i / 8] = u64vec4(packUint2x32(floatBitsToUint(vec2(noise_out[i], noise_out[i + 1]))),
                                      packUint2x32(floatBitsToUint(vec2(noise_out[i + 2], noise_out[i + 3]))),
                                      packUint2x32(floatBitsToUint(vec2(noise_out[i + 4], noise_out[i + 5]))),
                                      packUint2x32(floatBitsToUint(vec2(noise_out[i + 6], noise_out[i + 7]))));
#else
    values[element + i / 4] = vec4(noise_out[i], noise_out[i + 1], noise_out[i + 2], noise_out[i + 3]);
    values[element + i / 4 + 1] = vec4(noise_out[i + 4], noise_out[i + 5], noise_out[i + 6], noise_out[i + 7]);
#endif
  }
#endif
  if (beyond != uvec2(0u)) {
    uint slot = atomicAdd(patch_count, 1u);
    if (slot < patch_capacity)
      patches[slot] = uvec4(uint(y) | (uint(slice) << 16u), uint(t0), beyond.x, beyond.y);
  }
}
