#pragma once
// Whether a cover of a given size fits the driver's limits and the memory available, checked
// before any allocation so that a size too large is bad input (exit code 2).
#include <string>

#include "cover/flow_kind.hpp"
#include "gpu/context.hpp"

namespace nephele::cover {

// Throws core::InputError naming `option`, the size and the allowed range when `size` does not
// fit. Needs `context` current.
void check_cover_fits(const gpu::Context& context, int size, const std::string& option = "--size",
                      Flow flow = Flow::steady);

}  // namespace nephele::cover
