// Worley F1 and its fBm: exactness against brute force, gradients against finite differences,
// tiling, value ranges.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "shader_math/shader_math.hpp"
#include "tolerances.hpp"

using namespace nephele::glsl;
using nephele::test::kUlp;

namespace {

// worley_f1 against brute force in double at the same float point p: f = p - floor(p) is exact
// (both sides take the same float p), so only the candidate's delta = f - (o + offset) (two
// roundings of values below 3, 2^-22 each at most), its squared length (3 products and 2 sums,
// 5 roundings of d^2 < 4: 5 x 2^-22) and sqrt (which halves that, plus one rounding) differ:
// about 2 x 2^-22 + 5 x 2^-22 / 2 + 2^-24 < 1.1e-6. The former comment blamed "float rounding
// of positions near 50 (4e-6)", which does not enter: 1e-5 is kept as set, 9x the derivation.
constexpr float kF1VsBruteForce = 1.0e-5f;
static_assert(kF1VsBruteForce >= (2 * 4 + 5 * 4 / 2 + 1) * kUlp);
// The same comparison for points up to 200 (and F1 > 1, only via the 5^3 fallback): the same
// derivation (p - floor(p) is still exact), 1.1e-6; 1e-4 is far looser than that (kept as set).
// Also the margin by which the 27-cell search must miss the exact F1 for a point to count.
constexpr float kFallbackVsBruteForce = 1.0e-4f;
static_assert(kFallbackVsBruteForce >= kF1VsBruteForce);
// F1 is at most sqrt(3) (the farthest a point can be from the feature point of its own cell),
// up to the rounding of kF1VsBruteForce.
constexpr float kF1AboveSqrt3 = kF1VsBruteForce;
// Chi-square with 63 degrees of freedom (64 bins): mean 63, standard deviation sqrt(2 x 63);
// the uniformity test allows 6 standard deviations (a false alarm 1.3e-6 for a good hash,
// and the fixed seed makes it deterministic).
constexpr double kChiSquareSigmas = 6.0;
// A shifted point q = p + k period (|q| < 30) is rounded to half an ulp of 30, 2^-19 / 2 =
// 9.5e-7, per axis, which moves F1 (1-Lipschitz) by at most sqrt(3) x that = 1.7e-6, plus both
// sides' kF1VsBruteForce rounding (1.1e-6 each): 3.9e-6; 1e-5 leaves a factor of 2.5.
constexpr float kTiling = 1.0e-5f;
static_assert(kTiling >= 1.7321f * 16 * kUlp + 2 * (2 * 4 + 5 * 4 / 2 + 1) * kUlp);
// Finite differences of F1 with step h at |p| <= 8: each F1 value is rounded by an ulp of the
// shifted position (2^-21 for |p| in [4, 8)) and kF1VsBruteForce; the central difference divides
// the difference of two by 2h and the one-sided gap that of up to four by h: 2 ulp(8) / (2h) =
// 9.5e-4 for the test's h = 1e-3, rounded up to 2e-3 (the central difference's rounding).
constexpr float kWorleyStep = 1.0e-3f;
constexpr float kCentralRounding = 2.0e-3f;
static_assert(kCentralRounding >= 2 * (8.0f / 8388608.0f) / (2 * kWorleyStep));
// The one-sided gap of a smooth F1 is h |F1''| <= h / F1; the gap above which a kink is assumed
// is 4 h / F1 plus the gap's own rounding, 1e-3 for h = 1e-3 (about the derivation above; the
// factor 4 and this floor are choices of which points to skip, not bounds: empirical).
constexpr float kKinkGapFactor = 4.0f;
constexpr float kKinkGapRounding = 1.0e-3f;
// On a feature point f - (0 + offset) is exactly zero (p = offset, floor 0), so F1 is exactly
// 0; the margin, 16 ulp of values below 1, only guards against a contracted dot product.
constexpr float kAtFeature = 1.0e-6f;
// 0.01 away along x from the feature point, delta = (0.01 + r, 0, 0) with r the rounding of
// feature + 0.01 (the y and z components cancel exactly): the gradient is delta / |delta|,
// (1, 0, 0) to a couple of ulp. 1e-3 is far looser than that (kept as set; it would also
// absorb a neighbouring feature point within 0.01, which the key does not have).
constexpr float kNearFeatureDirection = 1.0e-3f;
// The gradient's length: normalize's rounding, kUnitLength (1e-6); 1e-5 here is 10x looser
// (kept as set).
constexpr float kNearFeatureLength = 1.0e-5f;
// fBm finite differences: the value is within kFbmValueRounding; a central difference divides
// two such errors by 2h: kFbmValueRounding / h. The gap above which a kink is assumed (0.5) is
// a choice (empirical: it keeps more than 2000 of the 3000 points), not a bound.
constexpr float kFbmKinkGap = 0.5f;

// Brute force: the nearest feature point over a 7^3 block of cells, in double precision.
double brute_force_f1(vec3 p, ivec3 period, uvec3 key) {
  const ivec3 cell = ivec3(floor(p));
  const dvec3 f = dvec3(p) - dvec3(floor(p));
  double best = 1e30;
  for (int k = -3; k <= 3; ++k)
    for (int j = -3; j <= 3; ++j)
      for (int i = -3; i <= 3; ++i) {
        const ivec3 o(i, j, k);
        const dvec3 d = f - (dvec3(o) + dvec3(feature_offset(cell + o, period, key)));
        best = std::min(best, glm::dot(d, d));
      }
  return std::sqrt(best);
}

vec3 random_point(std::mt19937& rng, float extent) {
  std::uniform_real_distribution<float> u(-extent, extent);
  return vec3(u(rng), u(rng), u(rng));
}

// Central difference of a scalar function along each axis, plus both one-sided differences
// (their disagreement reveals a kink inside the stencil).
template <class F>
void differences(F f, vec3 p, float h, vec3& central, float& one_sided_gap) {
  one_sided_gap = 0;
  const double f0 = f(p);
  for (int a = 0; a < 3; ++a) {
    vec3 e(0.0f);
    e[a] = h;
    const double plus = f(p + e), minus = f(p - e);
    central[a] = static_cast<float>((plus - minus) / (2.0 * h));
    one_sided_gap = std::max(one_sided_gap, static_cast<float>(std::abs((plus - f0) - (f0 - minus)) / h));
  }
}

}  // namespace

TEST_CASE("worley_f1 finds the nearest feature point exactly also when F1 exceeds 1", "[fast][worley]") {
  std::mt19937 rng(7);
  const uvec3 key = noise_key(3u, 0u);
  int beyond_one = 0;
  for (int n = 0; n < 20000; ++n) {
    const vec3 p = random_point(rng, 50.0f);
    const float f1 = worley_f1(p, ivec3(0), key).w;
    const double exact = brute_force_f1(p, ivec3(0), key);
    if (exact > 1.0) ++beyond_one;
    INFO("p = " << p.x << "," << p.y << "," << p.z);
    REQUIRE(f1 == Approx(exact).epsilon(0).margin(kF1VsBruteForce));
    REQUIRE(f1 <= std::sqrt(3.0f) + kF1AboveSqrt3);
  }
  // Points where F1 > 1 need the 5^3 fallback: the test must have met some (10 of 20000 here).
  CHECK(beyond_one > 0);
}

TEST_CASE("the fallback search is exact where the 27-cell search is not", "[fast][worley]") {
  // Search for points whose nearest feature point lies outside the 27 neighbours (only possible
  // when F1 > 1) and check worley_f1 against brute force there. Uniform points almost never need
  // it (none in 400000); points within 0.01 of a cell's corner do, now and then (10 in about
  // 200000): where the eight cells around the corner all have their feature points more than 1
  // away (each with probability 1 - pi/6), a cell two away may hold the nearest.
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> near_corner(0.99f, 1.0f);
  const uvec3 key = noise_key(5u, 0u);
  int found = 0;
  for (int n = 0; n < 400000 && found < 10; ++n) {
    const vec3 p = floor(random_point(rng, 200.0f)) + vec3(near_corner(rng), near_corner(rng), near_corner(rng));
    const ivec3 cell = ivec3(floor(p));
    const vec3 f = p - floor(p);
    float best27 = 1e30f;
    for (int k = -1; k <= 1; ++k)
      for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i) {
          const ivec3 o(i, j, k);
          const vec3 d = f - (vec3(o) + feature_offset(cell + o, ivec3(0), key));
          best27 = std::min(best27, dot(d, d));
        }
    const double exact = brute_force_f1(p, ivec3(0), key);
    if (std::sqrt(best27) > exact + kFallbackVsBruteForce) {
      ++found;
      CHECK(worley_f1(p, ivec3(0), key).w == Approx(exact).epsilon(0).margin(kFallbackVsBruteForce));
    }
  }
  CHECK(found == 10);
}

TEST_CASE("feature points are jittered uniformly and independently inside their cells", "[fast][worley]") {
  // Chi-square over 4^3 = 64 joint bins tests the three offsets together: a diagonal layout
  // (all offsets equal) would leave 60 of the 64 bins empty.
  const int n = 128000;
  std::vector<int> counts(64, 0);
  const uvec3 key = noise_key(9u, 0u);
  for (int k = 0; k < n; ++k) {
    const vec3 o = feature_offset(ivec3(k % 50 - 25, k / 50 % 50 - 25, k / 2500 - 25), ivec3(0), key);
    REQUIRE(o.x >= 0.0f);
    REQUIRE(o.x < 1.0f);
    counts[int(o.x * 4) + 4 * int(o.y * 4) + 16 * int(o.z * 4)]++;
  }
  double chi2 = 0;
  const double expected = n / 64.0;
  for (int c : counts) chi2 += (c - expected) * (c - expected) / expected;
  CHECK(chi2 < 63 + kChiSquareSigmas * std::sqrt(2.0 * 63));
}

TEST_CASE("periodic Worley noise tiles exactly for negative coordinates too", "[fast][worley]") {
  const ivec3 period(4, 6, 5);
  const uvec3 key = noise_key(2u, 0u);
  std::mt19937 rng(3);
  for (int n = 0; n < 2000; ++n) {
    const vec3 p = random_point(rng, 10.0f);
    const vec4 a = worley_f1(p, period, key);
    for (int axis = 0; axis < 3; ++axis) {
      for (int shift : {-2, -1, 1, 3}) {
        vec3 q = p;
        q[axis] += float(shift * period[axis]);
        const vec4 b = worley_f1(q, period, key);
        // Only the rounding of the shifted position (|q| < 30, ulp 2e-6) differs.
        REQUIRE(b.w == Approx(a.w).epsilon(0).margin(kTiling));
      }
    }
  }
  CHECK(wrap_cell(ivec3(-1, -7, 12), period) == ivec3(3, 5, 2));
}

TEST_CASE("a wrapped index is exact when the division's floored quotient is one off, as a GPU's may be",
          "[fast][worley]") {
  // GLSL lets float division err by 2.5 ulp (NVIDIA's does: 21.0 / 7.0 may floor to 2), so
  // wrap_axis's quotient can miss by one either way; wrap_remainder must still give the true
  // remainder in [0, period), which integer arithmetic gives here for comparison.
  for (int period = 1; period <= 20; ++period) {
    for (int c = -2000; c <= 2000; ++c) {
      const int exact = ((c % period) + period) % period;
      const int quotient = (c - exact) / period;
      for (int miss = -1; miss <= 1; ++miss) {
        INFO("period " << period << ", index " << c << ", quotient off by " << miss);
        REQUIRE(wrap_remainder(c, period, quotient + miss) == exact);
      }
      REQUIRE(wrap_axis(c, period) == exact);
    }
  }
}

TEST_CASE("a neighbour's wrapped index stepped from the wrapped cell equals its own floor division", "[fast][worley]") {
  // wrap_step replaces wrap_axis's division in the 27-cell searches, so it must give the same
  // integer for every index and period, negative indices, period 1 and 0 (unbounded) included.
  for (int period = 0; period <= 7; ++period) {
    for (int c = -50; c <= 50; ++c) {
      INFO("period " << period << ", index " << c);
      const ivec3 n = wrapped_neighbours(c, period);
      REQUIRE(n == ivec3(wrap_axis(c - 1, period), wrap_axis(c, period), wrap_axis(c + 1, period)));
      if (period > 0) REQUIRE((n.y >= 0 && n.y < period));
    }
  }
}

TEST_CASE("the Worley gradient matches finite differences away from cell borders", "[fast][worley]") {
  const uvec3 key = noise_key(4u, 0u);
  std::mt19937 rng(5);
  const float h = kWorleyStep;
  int compared = 0;
  for (int n = 0; n < 5000; ++n) {
    const vec3 p = random_point(rng, 8.0f);
    const vec4 g = worley_f1(p, ivec3(0), key);
    vec3 central;
    float gap;
    differences([&](vec3 q) { return static_cast<double>(worley_f1(q, ivec3(0), key).w); }, p, h, central, gap);
    // A smooth F1 = |p - f| has one-sided differences that differ by h |f''| <= h / F1; a
    // larger gap means a Voronoi border lies inside the stencil, where F1 has a kink.
    if (gap > kKinkGapFactor * h / g.w + kKinkGapRounding) continue;
    ++compared;
    // Central differences err by h^2 |f'''| / 6 ~ h^2 / F1^2, plus rounding 2 ulp(8) / (2h), plus
    // at most the gradient jump of a weak kink that the gap did not exclude (it measures it).
    const float tolerance = h * h / (g.w * g.w) + kCentralRounding + gap;
    REQUIRE(glm::length(vec3(g) - central) < tolerance);
  }
  CHECK(compared > 4000);
}

TEST_CASE("the gradient is the unit vector away from the nearest feature point", "[fast][worley]") {
  const uvec3 key = noise_key(4u, 0u);
  // In cell (0, 0, 0) the feature point is exactly representable (24-bit offsets below 1).
  const vec3 feature = feature_offset(ivec3(0), ivec3(0), key);
  const vec4 at_feature = worley_f1(feature, ivec3(0), key);
  CHECK(at_feature.w == Approx(0.0f).epsilon(0).margin(kAtFeature));
  CHECK(vec3(at_feature) == vec3(0.0f));  // defined as zero on the singular point
  const vec4 near = worley_f1(feature + vec3(0.01f, 0.0f, 0.0f), ivec3(0), key);
  CHECK(near.x == Approx(1.0f).epsilon(0).margin(kNearFeatureDirection));
  CHECK(length(vec3(near)) == Approx(1.0f).epsilon(0).margin(kNearFeatureLength));
}

TEST_CASE("inverted Worley fBm is normalised and its gradient matches finite differences", "[fast][worley]") {
  const FbmParams params{3.0f, 4, 2.0f, 0.5f, 17u, ivec3(0)};
  std::mt19937 rng(8);
  const float h = 2e-4f;
  int compared = 0;
  for (int n = 0; n < 3000; ++n) {
    const vec3 p = random_point(rng, 1.0f);
    const vec4 g = inverted_worley_fbm(p, params);
    REQUIRE(g.w <= 1.0f);
    REQUIRE(g.w >= 1.0f - std::sqrt(3.0f));
    vec3 central;
    float gap;
    differences([&](vec3 q) { return static_cast<double>(inverted_worley_fbm(q, params).w); }, p, h, central, gap);
    // Highest octave: frequency 24, so curvature up to 24^2 / (24 F1) per octave; skip kinks.
    if (gap > kFbmKinkGap) continue;
    ++compared;
    // Per octave k (frequency f_k = 3 2^k, weight a_k / sum a): truncation (h f_k / F1_k)^2 f_k,
    // rounding 1e-7 / h, and the measured jump of weak kinks.
    float tolerance = nephele::test::kFbmValueRounding / h + gap;
    float amplitude = 1.0f, frequency = params.frequency, norm = 0.0f, truncation = 0.0f;
    for (int k = 0; k < params.octaves; ++k) {
      const float f1 = std::max(worley_f1(p * frequency, ivec3(0), noise_key(params.seed, uint(k))).w, 1e-6f);
      truncation += amplitude * frequency * std::min(2.0f, 2.0f * (h * frequency / f1) * (h * frequency / f1));
      norm += amplitude;
      amplitude *= params.gain;
      frequency *= params.lacunarity;
    }
    tolerance += truncation / norm;
    REQUIRE(glm::length(vec3(g) - central) < tolerance);
  }
  CHECK(compared > 2000);
  const FbmParams none{3.0f, 0, 2.0f, 0.5f, 17u, ivec3(0)};
  CHECK(inverted_worley_fbm(vec3(0.1f), none) == vec4(0.0f));
}
