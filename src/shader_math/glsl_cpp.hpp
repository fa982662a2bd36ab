#pragma once
// C++ side of the shared GLSL/C++ subset (the GLSL side is shaders/lib/prelude.glsl),
// in the manner of Bruneton's precomputed atmospheric scattering: GLM supplies the GLSL
// types and built-ins, macros supply the parameter qualifiers. Rules for shared files:
// float literals carry an f suffix, no swizzles beyond .x/.y/.z/.w, constructors of built-in
// types only, vec3(v4) for the first three components.
#include <cstdint>
#include <glm/glm.hpp>

// Pre-empts shaders/lib/prelude.glsl, which holds the GLSL definitions of these macros.
#define NEPHELE_PRELUDE_GLSL
#define IN(T) const T&
#define OUT(T) T&
#define INOUT(T) T&
// Work a group of SIMD lanes can skip (prelude.glsl): here a plain loop count.
#define SKIPPABLE(condition, count) ((condition) ? (count) : 0)
// A parameter that only some variants of a function use (prelude.glsl).
#define UNUSED_PARAMETER(name) static_cast<void>(name)

namespace nephele::glsl {
using namespace glm;
using uint = std::uint32_t;
}  // namespace nephele::glsl
