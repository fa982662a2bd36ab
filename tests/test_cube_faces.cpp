// Cube face conventions against an independent transcription of OpenGL 4.6 table 8.19.
#include <catch2/catch.hpp>

#include "cover/solid_angle.hpp"
#include "shader_math/shader_math.hpp"
#include "tolerances.hpp"

using namespace nephele::glsl;
using nephele::test::kDoubleUlp;
using nephele::test::kUlp;
using nephele::test::kUnitLength;

namespace {

// s = (sc / |ma| + 1) / 2 of a texel direction against (i + 0.5) / N, for N = 8: sc = 2 (i + 0.5)
// / N - 1 and the expected value are exact (N a power of 2); normalize multiplies sc by the
// factor k (one rounding) and the major component 1 by it exactly, the division by |ma| = k
// rounds once more (two roundings of |sc| <= 1) and + 1 once (a value below 2, 2^-24 absolute);
// / 2 is exact: 1.5 x 2^-24 = 9e-8. 1e-6 is 11x looser (kept as set).
constexpr double kFaceCoordinate = 1e-6;
static_assert(kFaceCoordinate >= 1.5 * kUlp);
// cube_face_coords(3 cube_face_point(sc, tc)): 3 sc rounds once (3 x 1 is exact), the division by
// 3 once more: two roundings of |sc| < 1, 2^-23 = 1.2e-7; 1e-6 is 8x looser (kept as set).
constexpr double kInverse = 1e-6;
static_assert(kInverse >= 2 * kUlp);
// 6 x the sum of a face's texel solid angles against 4 pi, relative. The texel values are
// differences of the antiderivative F at the corners, whose own errors cancel in the sum
// (telescoping) but for the face's 4 corners; each texel adds about one rounding of values below
// pi/6 (the subtraction of F values of similar size is exact, Sterbenz), and the recursive sum
// of N^2 terms (N - 1) 2^-53 relative in the worst case. At N = 255 that worst case, 65024 x
// 2^-53 = 7.2e-12, exceeds 1e-12; the typical (random-walk) error, 255 x 2^-53 = 2.8e-14, is
// 35x below it. A bound for the typical error, not the worst (kept as set).
constexpr double kSphereSum = 1e-12;
static_assert(kSphereSum >= 255 * kDoubleUlp * 4);
// A texel's solid angle against (2/N)^2 (1 + x^2 + y^2)^(-3/2) at its centre (the midpoint rule),
// N = 1024, h = 2/N: the midpoint rule errs by h^2/24 (f_xx + f_yy) / f relative, 4/3 h^2/24 =
// 2.1e-7 at the corner (u = 1 + x^2 + y^2 = 3: f_xx / f = -3/u + 15 x^2/u^2 = 2/3 per axis); the
// centre texel (centre (1/N, 1/N), compared with f = 1) adds 3/N^2: about 3.8e-6 there. 1e-3 is
// 250x looser (kept as set).
constexpr double kSmallTexelRelative = 1e-3;
static_assert(kSmallTexelRelative >= 3.0 / (1024.0 * 1024.0) + (2.0 / 1024) * (2.0 / 1024) / 4);

// Table 8.19 as written in the specification: (sc, tc, ma) for each face.
struct TableEntry {
  float sc, tc, ma;
};
TableEntry table_8_19(int face, vec3 r) {
  switch (face) {
    case 0: return {-r.z, -r.y, r.x};
    case 1: return {r.z, -r.y, r.x};
    case 2: return {r.x, r.z, r.y};
    case 3: return {r.x, -r.z, r.y};
    case 4: return {r.x, -r.y, r.z};
    default: return {-r.x, -r.y, r.z};
  }
}

}  // namespace

TEST_CASE("texel directions follow table 8.19 with texel centres at (i + 0.5) / N", "[fast][cube]") {
  const int size = 8;
  for (int face = 0; face < 6; ++face) {
    for (int j = 0; j < size; ++j) {
      for (int i = 0; i < size; ++i) {
        const vec3 r = texel_direction(face, i, j, size);
        INFO("face " << face << " texel " << i << "," << j);
        REQUIRE(length(r) == Approx(1.0f).epsilon(0).margin(kUnitLength));
        REQUIRE(cube_face_of(r) == face);
        const TableEntry e = table_8_19(face, r);
        const float s = (e.sc / std::abs(e.ma) + 1.0f) / 2.0f;
        const float t = (e.tc / std::abs(e.ma) + 1.0f) / 2.0f;
        CHECK(s == Approx((i + 0.5f) / size).epsilon(0).margin(kFaceCoordinate));
        CHECK(t == Approx((j + 0.5f) / size).epsilon(0).margin(kFaceCoordinate));
      }
    }
  }
}

TEST_CASE("face +Z is the north pole face and its row 0 lies towards +Y", "[fast][cube]") {
  // +Z: tc = -ry, so t = 0 (row 0, the top of the stored image) is at ry = +1.
  const vec3 top_left = texel_direction(4, 0, 0, 2);
  CHECK(top_left.z > 0.0f);
  CHECK(top_left.y > 0.0f);
  CHECK(top_left.x < 0.0f);
  CHECK(texel_direction(0, 0, 0, 1).x == Approx(1.0f));  // +X centre is latitude 0 longitude 0
  CHECK(texel_direction(2, 0, 0, 1).y == Approx(1.0f));  // +Y centre is longitude 90 E
}

TEST_CASE("cube_face_coords inverts cube_face_point", "[fast][cube]") {
  for (int face = 0; face < 6; ++face) {
    for (float sc : {-0.9f, -0.3f, 0.0f, 0.55f, 0.99f}) {
      for (float tc : {-0.99f, -0.1f, 0.4f, 0.8f}) {
        const vec3 r = 3.0f * cube_face_point(face, sc, tc);  // any positive scale
        REQUIRE(cube_face_of(r) == face);
        const vec2 back = cube_face_coords(face, r);
        CHECK(back.x == Approx(sc).epsilon(0).margin(kInverse));
        CHECK(back.y == Approx(tc).epsilon(0).margin(kInverse));
      }
    }
  }
}

TEST_CASE("texel solid angles sum to the sphere and shrink towards the corners", "[fast][cube]") {
  for (int size : {1, 2, 3, 16, 255}) {
    const auto angles = nephele::cover::face_texel_solid_angles(size);
    double sum = 0;
    for (double a : angles) sum += a;
    INFO("size " << size);
    CHECK(6.0 * sum == Approx(4.0 * M_PI).epsilon(kSphereSum));
  }
  // For small texels the solid angle tends to (2/N)^2 (1 + x^2 + y^2)^(-3/2).
  const int n = 1024;
  const auto angles = nephele::cover::face_texel_solid_angles(n);
  const double texel_area = (2.0 / n) * (2.0 / n);
  const double x = 1.0 - 1.0 / n;  // corner texel centre
  CHECK(angles[0] == Approx(texel_area * std::pow(1.0 + 2.0 * x * x, -1.5)).epsilon(kSmallTexelRelative));
  CHECK(angles[(n / 2) * n + n / 2] == Approx(texel_area).epsilon(kSmallTexelRelative));
}
