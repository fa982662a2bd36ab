// Solid angles of cube map texels as fixed-point integers, read from a table the host computes
// in double (src/cover/gpu_reductions.cpp): one entry per texel of a face's octant, since the
// solid angle is symmetric under i -> N-1-i, j -> N-1-j and i <-> j. A unit is 2^-S of the
// sphere (S from the host), so sums of units over the sphere are exact 64-bit integers and do
// not depend on the order in which invocations add them.
#include "reduction_words.glsl"

layout(std430, binding = 5) readonly buffer TexelWeights {
  uint texel_weight_units[];
};

uint texel_weight(int i, int j, int size) {
  int a = min(i, size - 1 - i);
  int b = min(j, size - 1 - j);
  int lo = min(a, b), hi = max(a, b);
  return texel_weight_units[hi * (hi + 1) / 2 + lo];
}
