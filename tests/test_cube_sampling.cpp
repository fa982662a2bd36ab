// Seamless bilinear sampling of cube maps and the warp step built on it.
#include <catch2/catch.hpp>

#include <random>

#include "shader_math/shader_math.hpp"
#include "tolerances.hpp"

using namespace nephele::glsl;
using nephele::test::kUlp;
using nephele::test::kUnitLength;

namespace {

// Sampling at a texel centre of a size-8 map: the face coordinates of texel_direction come back
// within a few ulp of values below 1 (the direction's normalize, the projection's division:
// 4 ulp, 2.4e-7), st = coords / 2 + 1/2 adds half an ulp, u = st size - 1/2 multiplies by 8 and
// rounds once more (2^-24 of 8: 4.8e-7): a fraction error of at most 8 x 5 + 8 = 48 x 2^-24 =
// 2.9e-6 of a texel on each axis. Each fraction's error moves each of the 4 components by at most
// that times a neighbour difference (below 1 for values in [0, 1]), so the length by at most
// 2 x (2.9e-6 + 2.9e-6) = 1.1e-5 in the worst case, slightly above the 1e-5 used: the check
// relies on those worst cases not all coinciding (typical fraction errors are a few ulp of 8,
// ~1e-6 of a texel as the former comment said). Not a strict bound: kept as set.
constexpr float kTexelCentre = 1.0e-5f;
// Across a face edge at relative offset d either side: both face coordinates move by at most
// 2d (|coordinate| <= 1), i.e. by size d texels (size / 2 texels per face unit); each texel step
// changes each of the 4 components (values in [0, 1]) by at most 1, so the sample's length by at
// most 2 x 2 x size d = 4 size d. The neighbouring face's coordinates change no faster (the
// map between the faces' coordinates has derivative at most 1 near the edge); the check allows
// another factor 2 on top (a margin, not derived).
constexpr float kEdgeOffset = 1.0e-4f;
constexpr float kEdgeSlopePerSizeOffset = 4.0f;
constexpr float kEdgeMargin = 2.0f;
// A zero flow leaves w + h 0 = w, renormalised 20 times: each normalize of a unit vector moves a
// component by at most 1.5 ulp (the multiplier's rounding), which over 20 steps could add up to
// 20 x 1.5 x sqrt(3) ulp = 3.1e-6 in the worst case. The check's 1e-6 is tighter than that worst
// case: it relies on renormalising a unit float vector reaching a fixed point after a step or
// two (empirical, holds for all 1000 points here).
constexpr float kStillFlow = 1.0e-6f;

std::vector<vec4> random_cube(int size, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<vec4> texels(6 * size * size);
  for (auto& t : texels) t = vec4(u(rng), u(rng), u(rng), u(rng));
  return texels;
}

}  // namespace

TEST_CASE("sampling at a texel centre returns the texel", "[fast][sampling]") {
  const int size = 8;
  const auto texels = random_cube(size, 1);
  const CubeSource source{size, texels.data()};
  for (int face = 0; face < 6; ++face)
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i) {
        const vec4 s = sample_cube_bilinear(texel_direction(face, i, j, size), source);
        // The bilinear fraction of a centre is 0 up to rounding (~1e-6 of a texel).
        REQUIRE(length(s - source.fetch(face, i, j)) < kTexelCentre);
      }
}

TEST_CASE("sampling is continuous across face edges", "[fast][sampling]") {
  // Points just either side of an edge interpolate between the same texels; with texel values
  // in [0, 1] the sample changes by at most (2 texels^-1 per face unit) x distance.
  const int size = 8;
  const auto texels = random_cube(size, 2);
  const CubeSource source{size, texels.data()};
  const float offset = kEdgeOffset;
  int checked = 0;
  for (int face = 0; face < 6; ++face) {
    for (float along = -1.0f + 2.0f / size; along <= 1.0f - 2.0f / size; along += 0.037f) {
      const vec2 edge_points[4] = {vec2(1, along), vec2(-1, along), vec2(along, 1), vec2(along, -1)};
      for (const vec2 e : edge_points) {
        const vec3 inside = normalize(cube_face_point(face, e.x * (1 - offset), e.y * (1 - offset)));
        const vec3 outside = normalize(cube_face_point(face, e.x * (1 + offset), e.y * (1 + offset)));
        const vec4 a = sample_cube_bilinear(inside, source);
        const vec4 b = sample_cube_bilinear(outside, source);
        REQUIRE(length(a - b) < kEdgeSlopePerSizeOffset * size * offset * kEdgeMargin);
        ++checked;
      }
    }
  }
  CHECK(checked > 100);
}

TEST_CASE("a warp step stays on the unit sphere and zero flow leaves points in place", "[fast][warp]") {
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
    REQUIRE(std::abs(length(moved) - 1.0f) < kUnitLength);
    REQUIRE(length(integrate_warp(w, 20, 0.05f, still) - w) < kStillFlow);
    REQUIRE(integrate_warp(w, 0, 0.05f, source) == w);
  }
}
