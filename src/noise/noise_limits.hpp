#pragma once
// Whether a noise texture fits the driver's 3D texture limit and the memory available, checked
// before any allocation so that a size too large is bad input (exit code 2).
#include "gpu/context.hpp"
#include "noise/noise_spec.hpp"

namespace nephele::noise {

// Throws core::InputError naming --width, --height or --depth (or `size_option` for all three,
// when the user gave one size) and the allowed range. Needs `context` current.
void check_noise_fits(const TextureSpec& spec, const gpu::Context& context, const char* size_option = nullptr);

}  // namespace nephele::noise
