// The smooth Worley potential of the flow (worley.glsl smooth_worley, worley_fbm.glsl
// smooth_worley_fbm): continuity of the value and the gradient where classic F1 jumps, and the
// gradient against finite differences everywhere.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>

#include "shader_math/shader_math.hpp"

using namespace nephele::glsl;

namespace {

// Largest difference quotient |g(p + h d) - g(p)| / h of a vector function along a straight
// walk of `length` cells (direction d), which crosses about 3 length cell faces and many
// points entering or leaving the 27-cell search.
double largest_quotient(const std::function<vec3(vec3)>& g, vec3 start, vec3 d, float length, float h) {
  double largest = 0.0;
  vec3 previous = g(start);
  const int steps = static_cast<int>(length / h);
  for (int k = 1; k <= steps; ++k) {
    const vec3 next = g(start + (float(k) * h) * d);
    largest = std::max(largest, static_cast<double>(glm::length(next - previous)) / h);
    previous = next;
  }
  return largest;
}

const uvec3 kKey = noise_key(4u, 0u);
const vec3 kStart(0.3f, -2.1f, 1.7f);
const vec3 kDirection = glm::normalize(vec3(0.83f, 0.41f, 0.37f));
constexpr float kWalk = 12.0f;  // cells

// A gradient that is continuous (Lipschitz) has difference quotients bounded by its Hessian
// whatever h; one that jumps by J somewhere on the walk has quotients of J / h. Shrinking h
// tenfold leaves the first within a factor 1.5 (the walk samples the Hessian's peak more
// finely), and multiplies the second by about 10.
constexpr double kBoundedGrowth = 1.5;
constexpr double kJumpGrowth = 5.0;

}  // namespace

TEST_CASE("the smooth Worley gradient has bounded difference quotients where the F1 gradient jumps",
          "[fast][worley][smooth]") {
  auto smooth = [](vec3 p) { return vec3(smooth_worley(p, ivec3(0), kKey, 0.3f)); };
  auto classic = [](vec3 p) { return vec3(worley_f1(p, ivec3(0), kKey)); };
  const double smooth_coarse = largest_quotient(smooth, kStart, kDirection, kWalk, 1e-2f);
  const double smooth_fine = largest_quotient(smooth, kStart, kDirection, kWalk, 1e-3f);
  const double classic_coarse = largest_quotient(classic, kStart, kDirection, kWalk, 1e-2f);
  const double classic_fine = largest_quotient(classic, kStart, kDirection, kWalk, 1e-3f);
  INFO("smooth " << smooth_coarse << " -> " << smooth_fine << ", F1 " << classic_coarse << " -> " << classic_fine);
  CHECK(smooth_fine <= kBoundedGrowth * smooth_coarse);
  CHECK(classic_fine >= kJumpGrowth * classic_coarse);
}

TEST_CASE("the smooth Worley value has bounded difference quotients at every lambda", "[fast][worley][smooth]") {
  for (float lambda : {0.02f, 0.1f, 1.0f, 10.0f}) {
    auto value = [lambda](vec3 p) { return vec3(smooth_worley(p, ivec3(0), kKey, lambda).w); };
    const double coarse = largest_quotient(value, kStart, kDirection, kWalk, 1e-2f);
    const double fine = largest_quotient(value, kStart, kDirection, kWalk, 1e-3f);
    INFO("lambda " << lambda << ": " << coarse << " -> " << fine);
    CHECK(fine <= kBoundedGrowth * coarse);
  }
}

TEST_CASE("the smooth Worley gradient matches central differences at every point", "[fast][worley][smooth]") {
  // No kink to skip, unlike F1. Truncation h^2 |W'''| / 6 with |W'''| below about 1e3 for
  // lambda = 0.3 (K''' <= 120, the smooth maximum's |grad K|^3 / lambda^2 <= 9.3 / 0.09 times a
  // few): 2e-4 at h = 1e-3; rounding 2 ulp of values below 2 / (2h): 2.4e-4; 1e-3 covers both.
  constexpr float h = 1e-3f;
  constexpr float tolerance = 1e-3f;
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> u(-4.0f, 4.0f);
  for (int n = 0; n < 3000; ++n) {
    const vec3 p(u(rng), u(rng), u(rng));
    const vec4 g = smooth_worley(p, ivec3(0), kKey, 0.3f);
    vec3 central;
    for (int a = 0; a < 3; ++a) {
      vec3 e(0.0f);
      e[a] = h;
      central[a] = static_cast<float>((static_cast<double>(smooth_worley(p + e, ivec3(0), kKey, 0.3f).w) -
                                       smooth_worley(p - e, ivec3(0), kKey, 0.3f).w) /
                                      (2.0 * h));
    }
    REQUIRE(glm::length(vec3(g) - central) < tolerance);
  }
}

TEST_CASE("smooth Worley equals the bump of a lone feature point and stays within its range",
          "[fast][worley][smooth]") {
  const vec3 feature = feature_offset(ivec3(0), ivec3(0), kKey);
  // On a feature point its bump is 1 and the others add lambda ln(1 + sum) >= 0.
  CHECK(smooth_worley(feature, ivec3(0), kKey, 0.3f).w >= 1.0f - 1e-6f);
  std::mt19937 rng(10);
  std::uniform_real_distribution<float> u(-4.0f, 4.0f);
  for (int n = 0; n < 2000; ++n) {
    const float w = smooth_worley(vec3(u(rng), u(rng), u(rng)), ivec3(0), kKey, 0.3f).w;
    REQUIRE(w >= 0.0f);
    REQUIRE(w <= 1.0f + 0.3f * std::log(27.0f) + 1e-6f);
  }
  // The fBm with smoothing 0 is the classic one.
  const FbmParams params{3.0f, 3, 2.0f, 0.5f, 17u, ivec3(0)};
  CHECK(smooth_worley_fbm(vec3(0.2f, 0.4f, 0.7f), params, 0.0f) == inverted_worley_fbm(vec3(0.2f, 0.4f, 0.7f), params));
}
