// The ground's relief under the sun (shaders/lib/ground_relief.glsl, on the CPU twin) against the
// geometry of a tilted plane.
#include <catch2/catch.hpp>

#include <cmath>

#include "shader_math/shader_math.hpp"

using namespace nephele;
using glsl::vec2;
using glsl::vec3;

namespace {
constexpr double degree = M_PI / 180.0;
}

TEST_CASE("flat ground's normal is the vertical, and at the poles any relief is", "[fast][relief]") {
  const vec3 up = glm::normalize(vec3(0.3f, -0.5f, 0.8f));
  const vec3 n = glsl::relief_normal(up, vec2(0.0f));
  for (int c = 0; c < 3; ++c) CHECK(n[c] == Approx(up[c]).margin(1e-6));
  const vec3 pole = glsl::relief_normal(vec3(0.0f, 0.0f, 1.0f), vec2(0.3f, 0.2f));
  CHECK(pole.z == 1.0f);
}

TEST_CASE("ground rising to the east tilts its normal west by the slope's angle, rising north tilts it south",
          "[fast][relief]") {
  // At latitude 0, longitude 0: east is +Y, north +Z.
  const float s = 0.25f;
  const vec3 east_rise = glsl::relief_normal(vec3(1.0f, 0.0f, 0.0f), vec2(s, 0.0f));
  CHECK(east_rise.x == Approx(1.0 / std::sqrt(1.0 + s * s)).epsilon(1e-6));
  CHECK(east_rise.y == Approx(-s / std::sqrt(1.0 + s * s)).epsilon(1e-6));
  CHECK(std::abs(east_rise.z) < 1e-7f);
  // At 45 N, 90 E: up (0, c, c), east (-1, 0, 0), north (0, -c, c); a northward rise tilts the
  // normal south by atan(s).
  const double c = std::sqrt(0.5);
  const vec3 up(0.0f, float(c), float(c)), north(0.0f, float(-c), float(c));
  const vec3 north_rise = glsl::relief_normal(up, vec2(0.0f, s));
  CHECK(glm::dot(north_rise, north) == Approx(-std::sin(std::atan(s))).epsilon(1e-5));
  CHECK(glm::dot(north_rise, up) == Approx(std::cos(std::atan(s))).epsilon(1e-5));
  CHECK(glm::length(north_rise) == Approx(1.0).epsilon(1e-6));
}

TEST_CASE("a slope facing the sun gets more of it by the sine of the sun's elevation plus the slope's angle",
          "[fast][relief]") {
  const vec3 up(1.0f, 0.0f, 0.0f);  // 0 N 0 E: east is +Y
  for (double elevation : {5.0, 20.0, 45.0}) {
    const double e = elevation * degree;
    const vec3 sun(float(std::sin(e)), float(std::cos(e)), 0.0f);  // in the east
    for (float s : {-0.3f, -0.1f, 0.1f, 0.3f}) {
      INFO("elevation " << elevation << " slope " << s);
      // Rising to the east (s > 0) turns the ground away from the eastern sun by atan(s).
      const double expected = std::max(0.0, std::sin(e - std::atan(s)));
      CHECK(glsl::relief_sun_cosine(up, vec2(s, 0.0f), sun) == Approx(expected).margin(2e-7));
    }
    CHECK(glsl::relief_sun_cosine(up, vec2(0.0f), sun) == Approx(std::sin(e)).epsilon(1e-6));
  }
  // A slope steeper than the sun's elevation, facing away from it, is in its own shadow: 0.
  const vec3 low_sun(float(std::sin(5 * degree)), float(std::cos(5 * degree)), 0.0f);
  CHECK(glsl::relief_sun_cosine(up, vec2(0.2f, 0.0f), low_sun) == 0.0f);
}
