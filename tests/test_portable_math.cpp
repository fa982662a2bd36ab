// Elementary functions written out in the shader library.
#include <catch2/catch.hpp>

#include <cmath>

#include "shader_math/shader_math.hpp"
#include "tolerances.hpp"

using namespace nephele::glsl;
using nephele::test::kPortableAsin;
using nephele::test::kUlp;

namespace {

// At |x| = 1, sqrt(1 - a) = 0 and portable_asin returns its constant 1.5707963268f: pi/2
// rounded to float, within half an ulp of values in [1, 2) (2^-24 = 6e-8; it is 4.4e-8 off);
// 1e-7 is 1.7x looser (kept as set).
constexpr double kAsinAtOne = 1e-7;
static_assert(kAsinAtOne >= kUlp);

}  // namespace

TEST_CASE("portable_asin is within 2e-8 of arcsin plus float rounding", "[fast][math]") {
  // kPortableAsin: Abramowitz and Stegun's 2e-8 and the float evaluation (tests/tolerances.hpp).
  double worst = 0;
  for (int k = -100000; k <= 100000; ++k) {
    const float x = k / 100000.0f;
    worst = std::max(worst, std::abs(portable_asin(x) - std::asin(static_cast<double>(x))));
  }
  CHECK(worst < kPortableAsin);
  CHECK(portable_asin(1.0f) == Approx(M_PI / 2).epsilon(0).margin(kAsinAtOne));
  CHECK(portable_asin(-1.0f) == Approx(-M_PI / 2).epsilon(0).margin(kAsinAtOne));
  // At 0 the two rounded constants 1.5707963268f and 1.5707963050f differ by one ulp of pi/2
  // (2^-23 = 1.2e-7), so portable_asin(0) is 1.2e-7, not 0: within kPortableAsin.
  CHECK(portable_asin(0.0f) == Approx(0.0).epsilon(0).margin(kPortableAsin));
}
