#pragma once
// The steady cover's parameters: the table's defaults with --flow steady, one flow and one warp.
// The tests of the steady warp's numerics, passes and climate use it; the moving flow (the
// default) has its own tests (test_moving_flow.cpp, test_moving_cover.cpp).
#include "cover/cover_parameters.hpp"

namespace nephele::test {

inline cover::CoverParameters steady_cover() {
  cover::CoverParameters p;
  p.flow = cover::Flow::steady;
  return p;
}

}  // namespace nephele::test
