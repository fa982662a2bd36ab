// Elementary functions written out in the shader library.
#include <catch2/catch.hpp>

#include <cmath>

#include "shader_math/shader_math.hpp"

using namespace nephele::glsl;

TEST_CASE("portable_asin is within 2e-8 of arcsin plus float rounding", "[math]") {
  // Abramowitz and Stegun 4.4.46 bound the approximation by 2e-8; float evaluation of the
  // polynomial and sqrt adds about 4 ulp of pi/2 (5e-7).
  double worst = 0;
  for (int k = -100000; k <= 100000; ++k) {
    const float x = k / 100000.0f;
    worst = std::max(worst, std::abs(portable_asin(x) - std::asin(static_cast<double>(x))));
  }
  CHECK(worst < 2e-8 + 5e-7);
  CHECK(portable_asin(1.0f) == Approx(M_PI / 2).margin(1e-7));
  CHECK(portable_asin(-1.0f) == Approx(-M_PI / 2).margin(1e-7));
  CHECK(portable_asin(0.0f) == Approx(0.0).margin(2e-8 + 5e-7));
}
