#pragma once
// Which flow warps the cover (--flow): the steady flow of one warp, or the moving flow whose
// vortices and clouds evolve in time (cover/moving_flow.hpp, docs/algorithm.md).
#include <optional>
#include <string>

namespace nephele::cover {

enum class Flow { steady, moving };

const char* flow_name(Flow flow);
std::optional<Flow> parse_flow(const std::string& name);

}  // namespace nephele::cover
