#version 450
// Recomputes the texels that noise_rows.comp listed (F1 > 1 in some Worley octave, where the
// 27 neighbour cells may miss the nearest feature point) with the exact point functions.
layout(local_size_x = 8, local_size_y = 1, local_size_z = 1) in;
#include "../lib/tileable_noise.glsl"

#ifndef NOISE_TYPE
#define NOISE_TYPE 0
#endif

layout(std430, binding = 0) writeonly buffer Values { float values[]; };
layout(std430, binding = 1) readonly buffer Patches { uint patch_count; uint patch_capacity; uint pad0; uint pad1; uvec4 patches[]; };

uniform NoiseChannel u_channel;
uniform ivec3 u_size;
uniform int u_z0;
uniform int u_stride;

void main() {
  uint k = gl_GlobalInvocationID.x;
  if (k >= min(patch_count, patch_capacity)) return;
  uvec4 entry = patches[k];
  int y = int(entry.x & 0xFFFFu);
  int slice = int(entry.x >> 16u);
  int t0 = int(entry.y);
  uvec2 mask = uvec2(entry.z, entry.w);
  do {  // an entry has at least one bit set
    int bit = mask.x != 0u ? findLSB(mask.x) : 32 + findLSB(mask.y);
    mask[bit >> 5] &= ~(1u << uint(bit & 31));
    int x = t0 + bit;
    vec3 p = vec3(ivec3(x, y, u_z0 + slice)) + 0.5f;
#if NOISE_TYPE == 3
    float value = perlin_worley_channel_value(p, u_channel);
#else
    float value = worley_channel_value(p, u_channel);
#endif
    values[(slice * u_size.y + y) * u_stride + x] = value;
  } while (mask != uvec2(0u));
}
