#pragma once
// Whether a render of a given size fits the driver's image limits and the memory available,
// checked before any allocation so that a size too large is bad input (exit code 2).
#include <string>

#include "gpu/context.hpp"

namespace nephele::render {

// Throws core::InputError starting with `option` (--size, or "FILE: 'size'") when a width x
// height render does not fit. Needs `context` current.
void check_render_fits(const gpu::Context& context, int width, int height, const std::string& option);

}  // namespace nephele::render
