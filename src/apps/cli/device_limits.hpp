#pragma once
// Checks of a requested cube map size against the driver's limit and the memory available.
#include "gpu/egl_context.hpp"

namespace nephele::cli {

// Throws UsageError naming --size and the allowed range when `size` does not fit.
void check_cover_fits(const gpu::EglContext& context, int size);

}  // namespace nephele::cli
