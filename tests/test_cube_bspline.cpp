// Cubic B-spline filtering of cube maps by four bilinear lookups (shaders/lib/cube_bspline.glsl),
// checked against the 4 x 4 convolution it stands for and across face edges.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include "shader_math/shader_math.hpp"
#include "tolerances.hpp"

using namespace nephele::glsl;
using nephele::test::kUlp;

namespace {

float filtered(vec3 d, const CubeSource& source) {
  const CubeBsplineTaps taps = cube_bspline_taps(d, float(source.size));
  const float c00 = sample_cube_bilinear(taps.d00, source).x, c10 = sample_cube_bilinear(taps.d10, source).x;
  const float c01 = sample_cube_bilinear(taps.d01, source).x, c11 = sample_cube_bilinear(taps.d11, source).x;
  return mix(mix(c00, c10, taps.g.x), mix(c01, c11, taps.g.x), taps.g.y);
}

std::vector<vec4> cube_from(int size, const std::function<float(vec3)>& field) {
  std::vector<vec4> texels(6 * std::size_t(size) * size);
  for (int f = 0; f < 6; ++f)
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i)
        texels[(std::size_t(f) * size + j) * size + i] = vec4(field(texel_direction(f, i, j, size)), 0, 0, 0);
  return texels;
}

}  // namespace

TEST_CASE("the cubic B-spline's weights are positive, sum to 1 and reproduce a linear ramp", "[fast][sampling]") {
  for (int k = 0; k <= 100; ++k) {
    const float f = float(k) / 100.0f;
    const vec4 w = bspline_weights(f);
    CHECK(std::min({w.x, w.y, w.z, w.w}) >= 0.0f);
    // Four values below 1 summed: a few ulp.
    CHECK(w.x + w.y + w.z + w.w == Approx(1.0).margin(8 * kUlp));
    // The mean position of the weights is the point itself: -w0 + w2 + 2 w3 = f.
    CHECK(-w.x + w.z + 2.0f * w.w == Approx(f).margin(16 * kUlp));
  }
}

TEST_CASE("four bilinear lookups give the B-spline convolution of the 4 x 4 texels inside a face", "[fast][sampling]") {
  const int size = 16;
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<vec4> texels(6 * size * size);
  for (auto& t : texels) t = vec4(u(rng), 0, 0, 0);
  const CubeSource source{size, texels.data()};
  // Each lookup's fraction u = st size - 1/2 is recomputed from a direction made from the tap's
  // face coordinate: about 6 ulp of `size` each way, so each of the three mixes moves by at most
  // that times a neighbour difference (below 1), 3 x 6 x 16 ulp, plus the weights' and the
  // convolution's own roundings (16 products and sums of values below 1): 320 ulp in all.
  constexpr float kTaps = (3 * 6 * 16 + 32) * kUlp;
  int checked = 0;
  while (checked < 500) {
    const vec3 d = normalize(vec3(u(rng) * 2 - 1, u(rng) * 2 - 1, u(rng) * 2 - 1));
    const int face = cube_face_of(d);
    const vec2 x = (0.5f * cube_face_coords(face, d) + 0.5f) * float(size) - 0.5f;
    const int i = int(std::floor(x.x)), j = int(std::floor(x.y));
    if (i < 1 || j < 1 || i + 2 >= size || j + 2 >= size) continue;  // the 4 x 4 texels inside the face
    const vec4 ws = bspline_weights(x.x - float(i)), wt = bspline_weights(x.y - float(j));
    double expected = 0;
    for (int b = 0; b < 4; ++b)
      for (int a = 0; a < 4; ++a) expected += ws[a] * wt[b] * source.fetch(face, i - 1 + a, j - 1 + b).x;
    INFO("direction " << d.x << ", " << d.y << ", " << d.z);
    REQUIRE(filtered(d, source) == Approx(expected).margin(kTaps));
    ++checked;
  }
}

TEST_CASE("the B-spline filtered cube map has no step across face edges for a smooth field", "[fast][sampling]") {
  const int size = 16;
  // A field linear in the direction: each face's texels sample it on a curved grid, so a filter
  // on one face's plane and one on its neighbour's differ by the field's curvature on the plane:
  // bilinear interpolation errs by at most h^2/8 |f''| and the B-spline's smoothing by
  // (1/3) h^2 |f''| / 2, with h = 2/size face units a texel and |f''| <= 3 for a unit-gradient
  // field on the plane |x| <= 1; either side may err by the sum, so the step is below twice it.
  const float h = 2.0f / size;
  const float kStep = 2.0f * (h * h / 8.0f * 3.0f + h * h / 3.0f * 3.0f / 2.0f);
  const auto texels = cube_from(size, [](vec3 d) { return 0.5f + 0.3f * d.x - 0.2f * d.y + 0.25f * d.z; });
  const CubeSource source{size, texels.data()};
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> u(-0.95f, 0.95f);
  float worst = 0.0f;
  for (int face = 0; face < 6; ++face)
    for (int k = 0; k < 40; ++k) {
      // A point on the edge sc = 1 of `face` and the points 1e-4 either side of it.
      const float tc = u(rng), offset = 1e-4f;
      const vec3 inside = normalize(cube_face_point(face, 1.0f - offset, tc));
      const vec3 outside = normalize(cube_face_point(face, 1.0f + offset, tc));
      REQUIRE(cube_face_of(outside) != face);
      worst = std::max(worst, std::abs(filtered(inside, source) - filtered(outside, source)));
    }
  INFO("largest step " << worst << ", bound " << kStep);
  CHECK(worst < kStep);
}
