#pragma once
// The GLSL function library of shaders/lib compiled as C++: the CPU twin of every pass.
// The functions are compiled once, in shader_math.cpp; this header declares them. The
// declarations are generated from the GLSL files at build time (cmake/shader_declarations.cmake),
// so there is no second copy of a signature to keep in step. warp_step.glsl's stepping rules
// are templates over the velocity source and stay visible here, to be instantiated for any
// field (the cube map, the curl, the tests' analytic flows).
#include "shader_math/hooks.hpp"

namespace nephele::glsl {
#include "shader_math/declarations.hpp"
}  // namespace nephele::glsl

#undef WARP_TEMPLATE
