// Words of the GPU reductions (src/cover/gpu_reductions.cpp): 64-bit integer sums as two
// 32-bit words, and floats as integers of the same order, so that atomics give results that do
// not depend on the order in which invocations add them.
#ifndef NEPHELE_REDUCTION_WORDS_GLSL
#define NEPHELE_REDUCTION_WORDS_GLSL

// Adds the 64-bit number `words` (low, high) to the counter at words (2 slot, 2 slot + 1) of
// `counters`: the low word with atomicAdd, and the high word plus a carry when the low one
// wraps. Integer addition commutes, so the sum is the same whatever the order.
#define ADD_WORDS64(counters, slot, words)                                            \
  {                                                                                   \
    uvec2 add_words_ = (words);                                                       \
    uint old_low_ = atomicAdd(counters[2 * (slot)], add_words_.x);                    \
    uint high_ = add_words_.y + (old_low_ > 0xFFFFFFFFu - add_words_.x ? 1u : 0u);    \
    if (high_ != 0u) atomicAdd(counters[2 * (slot) + 1], high_);                      \
  }
#define ADD_UNITS64(counters, slot, units) ADD_WORDS64(counters, slot, uvec2((units), 0u))

// `sum` + `units` as a 64-bit number (low, high): an invocation sums its texels' units here
// and adds the total with one ADD_WORDS64 instead of an atomic per texel.
uvec2 add_units(uvec2 sum, uint units) {
  uint carry;
  uint low = uaddCarry(sum.x, units, carry);
  return uvec2(low, sum.y + carry);
}

// Floats as unsigned integers of the same order (for atomicMin and atomicMax).
uint sortable_bits(float value) {
  uint bits = floatBitsToUint(value);
  return (bits & 0x80000000u) != 0u ? ~bits : bits | 0x80000000u;
}

#endif
