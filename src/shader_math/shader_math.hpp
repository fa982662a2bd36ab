#pragma once
// The GLSL function library of shaders/lib compiled as C++: the CPU twin of every pass.
// Functions live in nephele::glsl with internal linkage (one copy per translation unit).
#include <vector>

#include "shader_math/glsl_cpp.hpp"

namespace nephele::glsl {

// A cube map in host memory, vec4 per texel, faces in GL order, rows from t = 0.
struct CubeSource {
  int size = 0;
  const vec4* texels = nullptr;
  vec4 fetch(int face, int i, int j) const {
    return texels[(static_cast<size_t>(face) * size + j) * size + i];
  }
};

}  // namespace nephele::glsl

#define CUBE_SOURCE_PARAM , IN(CubeSource) source
#define CUBE_SOURCE_ARG , source
#define CUBE_FETCH(face, i, j) source.fetch(face, i, j)
#define CUBE_SIZE source.size
// The warp's stepping rules are templates over the velocity source (shaders/lib/warp_step.glsl):
// warp_velocity below for the cube map and the procedural curl, or any callable vec3(vec3).
#define WARP_TEMPLATE template <class Field>
#define WARP_FIELD_PARAM , IN(Field) field
#define WARP_FIELD_ARG , field
#define WARP_VELOCITY(w) warp_velocity(w, field)

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
namespace nephele::glsl {
// Types first, with external linkage, so that APIs across translation units can use them.
#include "lib/parameters.glsl"
#include "lib/render_types.glsl"
#include "lib/noise_types.glsl"
namespace {
#include "lib/portable_math.glsl"
#include "lib/hash.glsl"
#include "lib/cube_faces.glsl"
#include "lib/worley.glsl"
#include "lib/worley_fbm.glsl"
#include "lib/perlin.glsl"
#include "lib/tileable_noise.glsl"
#include "lib/noise_rows.glsl"
#include "lib/curl_flow.glsl"
#include "lib/cube_sampling.glsl"
vec3 warp_velocity(vec3 w, IN(CubeSource) source) { return vec3(sample_cube_bilinear(w, source)); }
vec3 warp_velocity(vec3 w, IN(CurlParams) curl) { return curl_velocity(w, curl); }
template <class F>
vec3 warp_velocity(vec3 w, const F& velocity) { return velocity(w); }
#include "lib/warp_step.glsl"
#include "lib/cover_density.glsl"
#include "lib/equirect_mapping.glsl"
#include "lib/ray_sphere.glsl"
#include "lib/atmosphere.glsl"
#include "lib/cloud_density.glsl"
}  // namespace
}  // namespace nephele::glsl
#pragma GCC diagnostic pop

#undef CUBE_SOURCE_PARAM
#undef CUBE_SOURCE_ARG
#undef CUBE_FETCH
#undef CUBE_SIZE
#undef WARP_TEMPLATE
#undef WARP_FIELD_PARAM
#undef WARP_FIELD_ARG
#undef WARP_VELOCITY
