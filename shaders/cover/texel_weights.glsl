// Solid angles of cube map texels as fixed-point integers, read from a table the host computes
// in double (src/cover/gpu_reductions.cpp): one entry per texel of a face's octant, since the
// solid angle is symmetric under i -> N-1-i, j -> N-1-j and i <-> j. A unit is 2^-S of the
// sphere (S from the host), so sums of units over the sphere are exact 64-bit integers and do
// not depend on the order in which invocations add them.
#include "reduction_words.glsl"

// The table is a buffer texture (R32UI), not a shader storage block: a face of 16384 texels has
// 8192 x 8193 / 2 entries, 134 MB, past the 128 MiB that drivers give a storage block (llvmpipe's
// limit, where the face centres' weights read as 0); a buffer texture holds 2^27 texels there.
layout(binding = 5) uniform usamplerBuffer texel_weights;

uint texel_weight(int i, int j, int size) {
  int a = min(i, size - 1 - i);
  int b = min(j, size - 1 - j);
  int lo = min(a, b), hi = max(a, b);
  return texelFetch(texel_weights, hi * (hi + 1) / 2 + lo).x;
}
