// Seamless bilinear sampling of cube maps and the warp step built on it.
#include <catch2/catch.hpp>

#include <random>

#include "shader_math/shader_math.hpp"

using namespace nephele::glsl;

namespace {

std::vector<vec4> random_cube(int size, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<vec4> texels(6 * size * size);
  for (auto& t : texels) t = vec4(u(rng), u(rng), u(rng), u(rng));
  return texels;
}

}  // namespace

TEST_CASE("sampling at a texel centre returns the texel", "[sampling]") {
  const int size = 8;
  const auto texels = random_cube(size, 1);
  const CubeSource source{size, texels.data()};
  for (int face = 0; face < 6; ++face)
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i) {
        const vec4 s = sample_cube_bilinear(texel_direction(face, i, j, size), source);
        // The bilinear fraction of a centre is 0 up to rounding (~1e-6 of a texel).
        REQUIRE(length(s - source.fetch(face, i, j)) < 1e-5f);
      }
}

TEST_CASE("sampling is continuous across face edges", "[sampling]") {
  // Points just either side of an edge interpolate between the same texels; with texel values
  // in [0, 1] the sample changes by at most (2 texels^-1 per face unit) x distance.
  const int size = 8;
  const auto texels = random_cube(size, 2);
  const CubeSource source{size, texels.data()};
  const float offset = 1e-4f;
  int checked = 0;
  for (int face = 0; face < 6; ++face) {
    for (float along = -1.0f + 2.0f / size; along <= 1.0f - 2.0f / size; along += 0.037f) {
      const vec2 edge_points[4] = {vec2(1, along), vec2(-1, along), vec2(along, 1), vec2(along, -1)};
      for (const vec2 e : edge_points) {
        const vec3 inside = normalize(cube_face_point(face, e.x * (1 - offset), e.y * (1 - offset)));
        const vec3 outside = normalize(cube_face_point(face, e.x * (1 + offset), e.y * (1 + offset)));
        const vec4 a = sample_cube_bilinear(inside, source);
        const vec4 b = sample_cube_bilinear(outside, source);
        REQUIRE(length(a - b) < 4.0f * size * offset * 2.0f);
        ++checked;
      }
    }
  }
  CHECK(checked > 100);
}

TEST_CASE("a warp step stays on the unit sphere and zero flow leaves points in place", "[warp]") {
  const int size = 4;
  auto texels = random_cube(size, 3);
  for (auto& t : texels) t = 10.0f * (t - 0.5f);  // large arbitrary velocities
  const CubeSource source{size, texels.data()};
  std::vector<vec4> zero(texels.size(), vec4(0.0f));
  const CubeSource still{size, zero.data()};
  std::mt19937 rng(4);
  std::normal_distribution<float> g;
  for (int k = 0; k < 1000; ++k) {
    const vec3 w = normalize(vec3(g(rng), g(rng), g(rng)));
    const vec3 moved = integrate_warp(w, 20, 0.05f, source);
    REQUIRE(std::abs(length(moved) - 1.0f) < 1e-6f);
    REQUIRE(length(integrate_warp(w, 20, 0.05f, still) - w) < 1e-6f);
    REQUIRE(integrate_warp(w, 0, 0.05f, source) == w);
  }
}
