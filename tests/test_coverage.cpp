// Calibration of the coverage threshold by solid angle.
#include <catch2/catch.hpp>

#include <random>

#include "cover/coverage_threshold.hpp"
#include "shader_math/shader_math.hpp"
#include "tolerances.hpp"

using namespace nephele::cover;
using nephele::test::kFractionSum;

namespace {

std::vector<float> random_densities(int size, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-0.3f, 0.9f);
  std::vector<float> d(6 * size * size);
  for (auto& x : d) x = u(rng);
  return d;
}

}  // namespace

TEST_CASE("the calibrated cloudy fraction is within one texel's share of the target", "[fast][coverage]") {
  for (int size : {1, 2, 3, 17, 64}) {
    const auto densities = random_densities(size, size);
    for (double target : {0.0, 0.01, 0.25, 0.5, 0.67, 0.99, 1.0}) {
      const CoverageCalibration c = calibrate_coverage(densities, size, target);
      INFO("size " << size << " target " << target << " achieved " << c.achieved_fraction);
      CHECK(std::abs(c.achieved_fraction - target) <= c.max_texel_fraction + kFractionSum);
      // The reported fraction is the one the threshold gives.
      double recount = 0;
      std::vector<float> cover(densities.size());
      for (size_t k = 0; k < densities.size(); ++k)
        cover[k] = nephele::glsl::cover_from_density(densities[k], c.threshold, c.density_max, 0.05f);
      CHECK(cloudy_fraction(cover, size) == Approx(c.achieved_fraction).epsilon(0).margin(kFractionSum));
      (void)recount;
    }
  }
}

TEST_CASE("coverage 0 leaves every texel clear and coverage 1 makes every texel cloudy", "[fast][coverage][extreme]") {
  const int size = 9;
  const auto densities = random_densities(size, 1);
  const auto none = calibrate_coverage(densities, size, 0.0);
  const auto all = calibrate_coverage(densities, size, 1.0);
  CHECK(none.achieved_fraction == 0.0);
  // All texels' solid angles (6 x 9^2 = 486) summed: (N - 1) 2^-53 = 5.4e-14 relative, plus the
  // solid angles' own rounding against 4 pi: within kFractionSum.
  CHECK(all.achieved_fraction == Approx(1.0).epsilon(kFractionSum));
  for (float d : densities) {
    for (float softness : {0.0f, 0.05f}) {
      CHECK(nephele::glsl::cover_from_density(d, none.threshold, none.density_max, softness) == 0.0f);
      CHECK(nephele::glsl::cover_from_density(d, all.threshold, all.density_max, softness) > 0.0f);
    }
  }
}

TEST_CASE("a constant density field cannot be split and reports what it achieves", "[fast][coverage][extreme]") {
  const int size = 4;
  const std::vector<float> flat(6 * size * size, 0.25f);
  const auto half = calibrate_coverage(flat, size, 0.5);
  // All texels are equal, so the only achievable fractions are 0 and 1.
  CHECK((half.achieved_fraction == 0.0 || half.achieved_fraction == Approx(1.0)));
}

TEST_CASE("with softness 0 the remap is a ramp from the threshold to the largest density", "[fast][coverage]") {
  using nephele::glsl::cover_from_density;
  CHECK(cover_from_density(0.2f, 0.2f, 0.8f, 0.0f) == 0.0f);
  CHECK(cover_from_density(0.5f, 0.2f, 0.8f, 0.0f) == Approx(0.5f));
  CHECK(cover_from_density(0.8f, 0.2f, 0.8f, 0.0f) == 1.0f);
  CHECK(cover_from_density(0.1f, 0.2f, 0.8f, 0.0f) == 0.0f);
  CHECK(cover_from_density(0.5f, 0.8f, 0.8f, 0.0f) == 0.0f);  // empty span: nothing cloudy
}

TEST_CASE("with a softness the remap starts at the edge value and saturates towards 1", "[fast][coverage]") {
  using nephele::glsl::cover_from_density;
  const float s = 0.05f, edge = nephele::glsl::COVER_EDGE;
  // At and below the threshold: clear.
  CHECK(cover_from_density(0.2f, 0.2f, 0.8f, s) == 0.0f);
  CHECK(cover_from_density(0.1f, 0.2f, 0.8f, s) == 0.0f);
  // Just above it: the edge value, the jump of a sharp cloud boundary.
  CHECK(cover_from_density(0.2f + 1e-6f, 0.2f, 0.8f, s) == Approx(edge).margin(1e-4));
  // One softness above: 1 - (1 - edge) / e; three: within 5 % of 1, whatever the largest density.
  CHECK(cover_from_density(0.25f, 0.2f, 0.8f, s) == Approx(1.0 - (1.0 - edge) / M_E).margin(1e-5));
  CHECK(cover_from_density(0.35f, 0.2f, 0.8f, s) == Approx(1.0 - (1.0 - edge) * std::exp(-3.0)).margin(1e-5));
  CHECK(cover_from_density(0.35f, 0.2f, 5.0f, s) == cover_from_density(0.35f, 0.2f, 0.8f, s));
  // Monotone in the density.
  float previous = 0.0f;
  for (float d = 0.2f; d < 1.0f; d += 0.01f) {
    const float c = cover_from_density(d, 0.2f, 0.8f, s);
    CHECK(c >= previous);
    CHECK(c < 1.0f + 1e-7f);
    previous = c;
  }
}
