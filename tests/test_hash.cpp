// The integer hash: determinism, uniformity of the derived numbers, independent seeds.
#include <catch2/catch.hpp>

#include <cmath>

#include "shader_math/shader_math.hpp"

using namespace nephele::glsl;

namespace {

// hash_to_unit3 keeps 24 bits: the largest value, (2^24 - 1) / 2^24, is a float, so the check is
// exact (no tolerance).
constexpr double kExact = 0.0;
// Statistical checks allow 6 standard deviations. The sample mean and the correlations are sums
// of 1e5 independent terms, close to normal: a false failure 2e-9 (two-sided). The chi-square
// statistic is skewed: mean + 6 sd is exceeded with probability 1.3e-6 for 63 degrees of freedom
// (computed from the regularized incomplete gamma function). The seeds are fixed, so either way
// the tests are deterministic.
constexpr double kSigmas = 6.0;

}  // namespace

TEST_CASE("pcg3d is a pure function of its input", "[fast][hash]") {
  const uvec3 a = pcg3d(uvec3(1u, 2u, 3u));
  const uvec3 b = pcg3d(uvec3(1u, 2u, 3u));
  CHECK(a == b);
  CHECK(pcg3d(uvec3(1u, 2u, 4u)) != a);
}

TEST_CASE("hash_to_unit3 gives values below 1 with 24-bit resolution", "[fast][hash]") {
  CHECK(hash_to_unit3(uvec3(0u)).x == 0.0f);
  const vec3 top = hash_to_unit3(uvec3(0xFFFFFFFFu));
  CHECK(top.x < 1.0f);
  CHECK(top.x == Approx(1.0 - 1.0 / 16777216.0).epsilon(kExact));
}

// Chi-square test of uniformity: with B bins and n samples the statistic has mean B - 1 and
// standard deviation sqrt(2 (B - 1)); kSigmas of them (a false failure 1.3e-6 for B = 64).
static double chi_square_bound(int bins) { return (bins - 1) + kSigmas * std::sqrt(2.0 * (bins - 1)); }

TEST_CASE("hashed unit numbers of consecutive cells are uniform in each component", "[fast][hash]") {
  const int bins = 64, n = 200000;
  std::vector<int> counts[3] = {std::vector<int>(bins), std::vector<int>(bins), std::vector<int>(bins)};
  for (int k = 0; k < n; ++k) {
    const vec3 u = hash_to_unit3(pcg3d(uvec3(uint(k % 59), uint(k / 59 % 61), uint(k / 3599))));
    for (int c = 0; c < 3; ++c) counts[c][static_cast<int>(u[c] * bins)]++;
  }
  for (int c = 0; c < 3; ++c) {
    double chi2 = 0;
    const double expected = static_cast<double>(n) / bins;
    for (int b = 0; b < bins; ++b) chi2 += (counts[c][b] - expected) * (counts[c][b] - expected) / expected;
    INFO("component " << c);
    CHECK(chi2 < chi_square_bound(bins));
  }
}

TEST_CASE("hashed components are uncorrelated with each other and with neighbour cells", "[fast][hash]") {
  // Sample correlation of independent uniforms has standard deviation 1/sqrt(n).
  const int n = 100000;
  double sxy = 0, sxz = 0, sxn = 0, sx = 0;
  vec3 previous = hash_to_unit3(pcg3d(uvec3(0u, 7u, 9u)));
  for (int k = 1; k <= n; ++k) {
    const vec3 u = hash_to_unit3(pcg3d(uvec3(uint(k), 7u, 9u)));
    sx += u.x;
    sxy += (u.x - 0.5) * (u.y - 0.5);
    sxz += (u.x - 0.5) * (u.z - 0.5);
    sxn += (u.x - 0.5) * (previous.x - 0.5);
    previous = u;
  }
  const double variance = 1.0 / 12.0, bound = kSigmas / std::sqrt(static_cast<double>(n));
  CHECK(std::abs(sx / n - 0.5) < kSigmas * std::sqrt(variance / n));
  CHECK(std::abs(sxy / n / variance) < bound);
  CHECK(std::abs(sxz / n / variance) < bound);
  CHECK(std::abs(sxn / n / variance) < bound);
}

TEST_CASE("noise keys of different seeds and layers differ", "[fast][hash]") {
  CHECK(noise_key(1u, 0u) != noise_key(2u, 0u));
  CHECK(noise_key(1u, 0u) != noise_key(1u, 1u));
  CHECK(noise_key(0xFFFFFFFFu, 0u) != noise_key(0u, 0u));
}
