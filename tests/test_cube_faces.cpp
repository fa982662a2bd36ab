// Cube face conventions against an independent transcription of OpenGL 4.6 table 8.19.
#include <catch2/catch.hpp>

#include "cover/solid_angle.hpp"
#include "shader_math/shader_math.hpp"

using namespace nephele::glsl;

namespace {

// Table 8.19 as written in the specification: (sc, tc, ma) for each face.
struct TableEntry { float sc, tc, ma; };
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

TEST_CASE("texel directions follow table 8.19 with texel centres at (i + 0.5) / N", "[cube]") {
  const int size = 8;
  for (int face = 0; face < 6; ++face) {
    for (int j = 0; j < size; ++j) {
      for (int i = 0; i < size; ++i) {
        const vec3 r = texel_direction(face, i, j, size);
        INFO("face " << face << " texel " << i << "," << j);
        REQUIRE(length(r) == Approx(1.0f).margin(1e-6));
        REQUIRE(cube_face_of(r) == face);
        const TableEntry e = table_8_19(face, r);
        const float s = (e.sc / std::abs(e.ma) + 1.0f) / 2.0f;
        const float t = (e.tc / std::abs(e.ma) + 1.0f) / 2.0f;
        CHECK(s == Approx((i + 0.5f) / size).margin(1e-6));
        CHECK(t == Approx((j + 0.5f) / size).margin(1e-6));
      }
    }
  }
}

TEST_CASE("face +Z is the north pole face and its row 0 lies towards +Y", "[cube]") {
  // +Z: tc = -ry, so t = 0 (row 0, the top of the stored image) is at ry = +1.
  const vec3 top_left = texel_direction(4, 0, 0, 2);
  CHECK(top_left.z > 0.0f);
  CHECK(top_left.y > 0.0f);
  CHECK(top_left.x < 0.0f);
  CHECK(texel_direction(0, 0, 0, 1).x == Approx(1.0f));  // +X centre is latitude 0 longitude 0
  CHECK(texel_direction(2, 0, 0, 1).y == Approx(1.0f));  // +Y centre is longitude 90 E
}

TEST_CASE("cube_face_coords inverts cube_face_point", "[cube]") {
  for (int face = 0; face < 6; ++face) {
    for (float sc : {-0.9f, -0.3f, 0.0f, 0.55f, 0.99f}) {
      for (float tc : {-0.99f, -0.1f, 0.4f, 0.8f}) {
        const vec3 r = 3.0f * cube_face_point(face, sc, tc);  // any positive scale
        REQUIRE(cube_face_of(r) == face);
        const vec2 back = cube_face_coords(face, r);
        CHECK(back.x == Approx(sc).margin(1e-6));
        CHECK(back.y == Approx(tc).margin(1e-6));
      }
    }
  }
}

TEST_CASE("texel solid angles sum to the sphere and shrink towards the corners", "[cube]") {
  for (int size : {1, 2, 3, 16, 255}) {
    const auto angles = nephele::cover::face_texel_solid_angles(size);
    double sum = 0;
    for (double a : angles) sum += a;
    INFO("size " << size);
    CHECK(6.0 * sum == Approx(4.0 * M_PI).epsilon(1e-12));
  }
  // For small texels the solid angle tends to (2/N)^2 (1 + x^2 + y^2)^(-3/2).
  const int n = 1024;
  const auto angles = nephele::cover::face_texel_solid_angles(n);
  const double texel_area = (2.0 / n) * (2.0 / n);
  const double x = 1.0 - 1.0 / n;  // corner texel centre
  CHECK(angles[0] == Approx(texel_area * std::pow(1.0 + 2.0 * x * x, -1.5)).epsilon(1e-3));
  CHECK(angles[(n / 2) * n + n / 2] == Approx(texel_area).epsilon(1e-3));
}
