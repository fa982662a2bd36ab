#pragma once
// Whether a density volume of a given size fits the memory available, checked before any
// allocation so that a size too large is bad input (exit code 2) naming --size.
#include "gpu/context.hpp"

namespace nephele::model {

// Throws core::InputError naming `option` (the option that set the size) and about the largest
// size that fits. Needs `context`
// current (a software driver keeps the texture in host memory too).
void check_model_fits(int size, const gpu::Context& context, const char* option = "--size");

}  // namespace nephele::model
