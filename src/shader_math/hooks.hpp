#pragma once
// What the GLSL library (shaders/lib) expects its includer to define, for C++: the cube map
// source of cube_sampling.glsl and the velocity source of warp_step.glsl's templates. Shared by
// shader_math.hpp (declarations) and shader_math.cpp (the one compiled copy of the functions).
#include <cstddef>

#include "shader_math/glsl_cpp.hpp"

namespace nephele::glsl {

#include "lib/parameters.glsl"

// A cube map in host memory, vec4 per texel, faces in GL order, rows from t = 0.
struct CubeSource {
  int size = 0;
  const vec4* texels = nullptr;
  vec4 fetch(int face, int i, int j) const {
    return texels[(static_cast<size_t>(face) * size + j) * size + i];
  }
};

// The velocity sources of the warp's stepping rules: the sampled cube map, the procedural curl,
// or any callable vec3(vec3) (the analytic flows of the tests). Declared before warp_step.glsl
// so that its templates find them for callables, whose namespace ADL would not search.
vec3 warp_velocity(vec3 w, IN(CubeSource) source);
vec3 warp_velocity(vec3 w, IN(CurlParams) curl);
template <class F>
vec3 warp_velocity(vec3 w, const F& velocity) { return velocity(w); }

}  // namespace nephele::glsl

#define CUBE_SOURCE_PARAM , IN(CubeSource) source
#define CUBE_SOURCE_ARG , source
#define CUBE_FETCH(face, i, j) source.fetch(face, i, j)
#define CUBE_SIZE source.size
// The warp's stepping rules are templates over the velocity source (shaders/lib/warp_step.glsl).
#define WARP_TEMPLATE template <class Field>
#define WARP_FIELD_PARAM , IN(Field) field
#define WARP_FIELD_ARG , field
#define WARP_VELOCITY(w) warp_velocity(w, field)
