// Words of the GPU reductions (src/cover/gpu_reductions.cpp): 64-bit integer sums as two
// 32-bit words, and floats as integers of the same order, so that atomics give results that do
// not depend on the order in which invocations add them.
#ifndef NEPHELE_REDUCTION_WORDS_GLSL
#define NEPHELE_REDUCTION_WORDS_GLSL

// Adds `units` to the 64-bit counter at words (2 slot, 2 slot + 1) of `counters`: the low word
// with atomicAdd, and a carry into the high word when it wraps. Integer addition commutes, so
// the sum is the same whatever the order.
#define ADD_UNITS64(counters, slot, units)                              \
  {                                                                     \
    uint add_units_ = (units);                                          \
    uint old_units_ = atomicAdd(counters[2 * (slot)], add_units_);      \
    if (old_units_ > 0xFFFFFFFFu - add_units_) atomicAdd(counters[2 * (slot) + 1], 1u); \
  }

// Floats as unsigned integers of the same order (for atomicMin and atomicMax).
uint sortable_bits(float value) {
  uint bits = floatBitsToUint(value);
  return (bits & 0x80000000u) != 0u ? ~bits : bits | 0x80000000u;
}

#endif
