#pragma once
// Checks of requested sizes against the driver's limits and the memory available, made before
// any allocation so that a size too large is bad input (exit 2), not a failure halfway.
#include <string>

#include "gpu/egl_context.hpp"

namespace nephele::cli {

// Throws UsageError naming --size and the allowed range when `size` does not fit.
void check_cover_fits(const gpu::EglContext& context, int size);
// Throws UsageError starting with `option` (--size, or "FILE: 'size'") when a width x height
// render does not fit the driver's image limits or the memory available.
void check_render_fits(const gpu::EglContext& context, int width, int height, const std::string& option);

}  // namespace nephele::cli
