// The cumulus and alto forms of Webanck et al. 2018 (shaders/lib/webanck_forms.glsl, CPU twin):
// the formulas against values computed by hand, and the distributions of the fields G3 and W3
// against what their maps to [0, 1] predict.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "gl_support.hpp"
#include "render/cloud_renderer.hpp"
#include "shader_math/shader_math.hpp"
#include "tolerances.hpp"

using namespace nephele::glsl;
using nephele::test::kUlp;

namespace {

// The forms chain at most 12 float operations on values in [0, 2]: 12 roundings of 2^-23.
constexpr double kFormRounding = 12 * 2 * kUlp;
// Abramowitz and Stegun 7.1.26 approximates erf within 1.5e-7; Phi halves that; the float
// evaluation adds about 10 roundings of values below 1.
constexpr double kNormalCdf = 0.75e-7 + 10 * kUlp;

// F1 of one jittered feature point per cell at uniformly random points, by an independent Monte
// Carlo (27 neighbours, std::mt19937).
std::vector<double> monte_carlo_f1(int n) {
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> f1;
  for (int k = 0; k < n; ++k) {
    const double x = u(rng), y = u(rng), z = u(rng);
    double best = 1e9;
    for (int i = -1; i <= 1; ++i)
      for (int j = -1; j <= 1; ++j)
        for (int l = -1; l <= 1; ++l) {
          const double dx = i + u(rng) - x, dy = j + u(rng) - y, dz = l + u(rng) - z;
          best = std::min(best, dx * dx + dy * dy + dz * dz);
        }
    f1.push_back(std::sqrt(best));
  }
  return f1;
}

// Statistics of n samples.
struct Moments {
  double mean = 0, variance = 0;
};
Moments moments(const std::vector<double>& x) {
  Moments m;
  for (double v : x) m.mean += v;
  m.mean /= x.size();
  for (double v : x) m.variance += (v - m.mean) * (v - m.mean);
  m.variance /= x.size() - 1;
  return m;
}

// Random points in a cube of `cells` base cells per side at frequency f: far enough apart on
// average (a sample per 50 cells) that the samples are close to independent.
std::vector<vec3> sample_points(int n, float frequency, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 100.0f / frequency);
  std::vector<vec3> points(n);
  for (auto& p : points) p = vec3(u(rng), u(rng), u(rng));
  return points;
}

}  // namespace

TEST_CASE("cumulus phi, delta and density follow Webanck's formulas (hand-computed values)", "[fast][webanck]") {
  // H(0.45, 0.65, 0.55) = 0.5; k1 = H(0.1, 0.9, 0.5)^2 = 0.25; k2 = 0.75 + 0.25 x 0.4 = 0.85;
  // phi = 2 x 0.85 x 0.5 x 0.5 = 0.425.
  CHECK(cumulus_phi(0.55f, 0.5f, 0.5f, 0.4f, 0.0f) == Approx(0.425).epsilon(0).margin(kFormRounding));
  // n4 <= 0.1: k1 = 0, k2 = 1 whatever n5; n2 >= 0.65: H = 1: phi = 2 n3.
  CHECK(cumulus_phi(0.7f, 0.3f, 0.05f, 0.0f, 0.0f) == Approx(0.6).epsilon(0).margin(kFormRounding));
  // n4 >= 0.9: k1 = 1, k2 = n5.
  CHECK(cumulus_phi(0.7f, 0.3f, 0.95f, 0.2f, 0.0f) == Approx(0.12).epsilon(0).margin(kFormRounding));
  // n2 at or below 0.45: nothing; a shift of -0.1 moves the window to [0.35, 0.55].
  CHECK(cumulus_phi(0.45f, 1.0f, 0.0f, 1.0f, 0.0f) == 0.0f);
  CHECK(cumulus_phi(0.45f, 0.5f, 0.5f, 0.4f, -0.1f) == Approx(0.425).epsilon(0).margin(kFormRounding));
  // delta = 0.77 (0.3 + 0.5 x 0.4 + 0.25 x 0.4 + 0.5 x 0.2) = 0.77 x 0.7 = 0.539.
  CHECK(cumulus_delta(0.7f, 0.6f, 0.4f, 0.2f) == Approx(0.539).epsilon(0).margin(kFormRounding));
  // delta = 0.77 (0.1 + 0.05 + 0.05 + 0.05) = 0.1925; density 0.425 - 0.1925 = 0.2325.
  CHECK(cumulus_form(vec4(0.55f, 0.5f, 0.5f, 0.4f), vec4(0.9f, 0.9f, 0.2f, 0.1f), 0.0f) ==
        Approx(0.2325).epsilon(0).margin(kFormRounding));
  CHECK(cumulus_form(vec4(0.55f, 0.5f, 0.5f, 0.4f), vec4(0.7f, 0.6f, 0.4f, 0.2f), 0.0f) == 0.0f);
}

TEST_CASE("alto phi, delta and density follow Webanck's formulas, k = 1 a uniform sheet", "[fast][webanck]") {
  // H(0.43, 1, 0.715) = 0.5: phi = 0.25 + 0.75 x 0.5 = 0.625; delta = 0.75 (0.3 + 0.25 x 0.2)
  // = 0.2625; density 0.3625.
  CHECK(alto_phi(0.25f, 0.715f) == Approx(0.625).epsilon(0).margin(kFormRounding));
  CHECK(alto_delta(0.25f, 0.4f, 0.8f) == Approx(0.2625).epsilon(0).margin(kFormRounding));
  CHECK(alto_form(0.25f, vec3(0.715f, 0.4f, 0.8f)) == Approx(0.3625).epsilon(0).margin(kFormRounding));
  // k = 1 (altostratus): density 1 wherever; k = 0 (altocumulus): H(0.43, 1, n1) - delta.
  for (float n : {0.0f, 0.3f, 0.9f}) CHECK(alto_form(1.0f, vec3(n, 1.0f - n, n)) == 1.0f);
  CHECK(alto_form(0.0f, vec3(0.43f, 0.0f, 1.0f)) == 0.0f);
  // H(0.43, 1, 1) = 1, delta = 0.75 x 0.2 + 0.25 x 0.5 = 0.275.
  CHECK(alto_form(0.0f, vec3(1.0f, 0.2f, 0.5f)) == Approx(0.725).epsilon(0).margin(kFormRounding));
}

TEST_CASE("the normal CDF behind G3 matches tabulated values", "[fast][webanck]") {
  CHECK(normal_cdf(0.0f) == Approx(0.5).epsilon(0).margin(kNormalCdf));
  CHECK(normal_cdf(1.0f) == Approx(0.8413447461).epsilon(0).margin(kNormalCdf));
  CHECK(normal_cdf(-1.0f) == Approx(0.1586552539).epsilon(0).margin(kNormalCdf));
  CHECK(normal_cdf(1.959964f) == Approx(0.975).epsilon(0).margin(kNormalCdf + 1e-7));
  CHECK(normal_cdf(-3.0f) == Approx(0.0013498980).epsilon(0).margin(kNormalCdf));
}

TEST_CASE("p_n is metres over 108 km in the frame whose x runs along the wind", "[fast][webanck]") {
  // Wind towards the north: x = north, y = west (left of the wind), z up.
  const vec3 pn = webanck_position(vec3(108000.0f, 216000.0f, 1080.0f), vec2(0.0f, 1.0f));
  CHECK(pn.x == Approx(2.0).epsilon(0).margin(4 * kUlp));
  CHECK(pn.y == Approx(-1.0).epsilon(0).margin(4 * kUlp));
  CHECK(pn.z == Approx(0.01).epsilon(0).margin(4 * kUlp));
}

TEST_CASE("G3 and W3 of one octave are the mapped gradient and complemented Worley noise", "[fast][webanck]") {
  const vec3 x(0.0123f, 0.0456f, 0.0078f);
  const float f = 37.0f;
  const uint seed = 5u;
  const float perlin = perlin_noise(x * f, ivec3(0), noise_key(seed, 0u));
  CHECK(webanck_g3(1, 0.52f, 2.02f, f, x, seed) ==
        Approx(normal_cdf(perlin / PERLIN_OCTAVE_SIGMA)).epsilon(0).margin(4 * kUlp));
  const float f1 = worley_f1(x * f, ivec3(0), noise_key(seed, 0u)).w;
  CHECK(webanck_w3(1, 0.33f, 3.0f, f, x, seed) == Approx(1.0f - f1 / std::sqrt(3.0f)).epsilon(0).margin(4 * kUlp));
  // Every octave of gradient noise is 0 on the lattice: G3 = Phi(0) = 1/2 at the origin.
  CHECK(webanck_g3(8, 0.52f, 2.02f, 15.0f, vec3(0.0f), seed) == Approx(0.5).epsilon(0).margin(kNormalCdf));
}

TEST_CASE("the derived deviation of one octave of gradient noise matches its samples", "[fast][webanck]") {
  // 2 A B^2 with A = 535/9009, B = 181/231 (docs/layers.md): 35054270/480729249.
  const double derived = 2.0 * (535.0 / 9009.0) * (181.0 / 231.0) * (181.0 / 231.0);
  CHECK(derived == Approx(35054270.0 / 480729249.0).epsilon(0).margin(1e-15));
  CHECK(double(PERLIN_OCTAVE_SIGMA) * PERLIN_OCTAVE_SIGMA == Approx(derived).epsilon(0).margin(4 * kUlp));
  std::vector<double> values;
  for (const vec3& p : sample_points(40000, 1.0f, 3)) values.push_back(perlin_noise(p, ivec3(0), noise_key(9u, 0u)));
  const Moments m = moments(values);
  // Standard errors of n = 40000 near-independent samples: of the mean sigma / sqrt n (0.0014),
  // of the variance sigma^2 sqrt((kurtosis - 1) / n) with kurtosis below 5 (0.00073); 5 of each.
  CHECK(m.mean == Approx(0.0).epsilon(0).margin(5 * 0.27 / 200));
  CHECK(m.variance == Approx(derived).epsilon(0).margin(5 * derived * std::sqrt(4.0 / 40000)));
}

TEST_CASE("G3 histogram: values within 0..1, mean 1/2, standardised octave mean of unit variance, near uniform",
          "[fast][webanck]") {
  const int n = 20000;
  const auto points = sample_points(n, 15.0f, 4);
  std::vector<double> g3, standardised;
  std::array<int, 10> deciles{};
  const float sigma = octave_mean_sigma(8, 0.52f, PERLIN_OCTAVE_SIGMA);
  // sigma_m = sigma_1 sqrt(sum a^2) / sum a, 0.5649637 of sigma_1 for 8 octaves of 0.52.
  CHECK(sigma == Approx(0.27003508 * 0.5649637).epsilon(0).margin(16 * kUlp));
  for (const vec3& p : points) {
    const float v = webanck_g3(8, 0.52f, 2.02f, 15.0f, p, 21u);
    REQUIRE(v >= 0.0f);
    REQUIRE(v <= 1.0f);
    g3.push_back(v);
    const FbmParams fbm = webanck_octaves(8, 0.52f, 2.02f, 15.0f, 21u);
    standardised.push_back(perlin_fbm_mean(p, fbm) / sigma);
    ++deciles[std::min(9, int(v * 10))];
  }
  // Mean 1/2 by symmetry (g and -g are equally likely): 5 standard errors of 0.2887 / sqrt n.
  CHECK(moments(g3).mean == Approx(0.5).epsilon(0).margin(5 * 0.2887 / std::sqrt(double(n))));
  // The standardised mean has variance 1 exactly (independent octaves): 5 standard errors,
  // sqrt((kurtosis - 1) / n) with kurtosis below 5.
  CHECK(moments(standardised).variance == Approx(1.0).epsilon(0).margin(5 * std::sqrt(4.0 / n)));
  // Uniform if the octave mean were normal; it is not quite (one octave of gradient noise has
  // bounded support and kurtosis below 3): each decile holds 10 % within 2 % (measured: 0.6 %
  // at most; empirical bound, docs/layers.md).
  for (int d = 0; d < 10; ++d) {
    INFO("decile " << d);
    CHECK(deciles[d] / double(n) == Approx(0.1).epsilon(0).margin(0.02));
  }
}

TEST_CASE("W3 histogram: values within 0..1, mean and variance as the complemented Worley octaves predict",
          "[fast][webanck]") {
  const std::vector<double> f1 = monte_carlo_f1(40000);
  const Moments f = moments(f1);
  // W3 = 1 - sum a_k F1_k / (sqrt 3 sum a): mean 1 - E[F1] / sqrt 3, variance
  // Var[F1] / 3 x sum a^2 / (sum a)^2 = Var[F1] / 3 x 0.51585 for 4 octaves of 0.33.
  const double expected_mean = 1.0 - f.mean / std::sqrt(3.0);
  const double expected_variance = f.variance / 3.0 * 0.5158512;
  const int n = 20000;
  std::vector<double> w3;
  for (const vec3& p : sample_points(n, 160.0f, 5)) {
    const float v = webanck_w3(4, 0.33f, 3.0f, 160.0f, p, 17u);
    REQUIRE(v >= 0.0f);
    REQUIRE(v <= 1.0f);
    w3.push_back(v);
  }
  const Moments m = moments(w3);
  const double sd = std::sqrt(expected_variance);
  // 5 standard errors of both estimates (the Monte Carlo one is the smaller); variance with a
  // kurtosis below 5.
  CHECK(m.mean == Approx(expected_mean).epsilon(0).margin(5 * sd / std::sqrt(double(n))));
  CHECK(m.variance == Approx(expected_variance).epsilon(0).margin(5 * expected_variance * std::sqrt(4.0 / n)));
}

TEST_CASE("the baked G3 and W3 of the noise volume have the exact fields' distributions", "[webanck][render]") {
  nephele::test::test_context();
  const nephele::render::NoiseVolume volume(64, 1);
  const auto texels = volume.level0();
  const size_t n = texels.size() / 4;
  std::array<int, 10> deciles{};
  std::vector<double> w3;
  for (size_t k = 0; k < n; ++k) {
    ++deciles[std::min(9, int(normal_cdf(texels[4 * k + 2]) * 10))];
    w3.push_back(texels[4 * k + 3]);
  }
  // The host standardises the G3 channel, so normal_cdf of it is near uniform as the exact G3 is
  // (its deciles are within 2 %, the same bound as the exact field's test; 3 octaves of a
  // 16-cell volume are near normal too).
  for (int d = 0; d < 10; ++d) {
    INFO("decile " << d);
    CHECK(deciles[d] / double(n) == Approx(0.1).epsilon(0).margin(0.02));
  }
  // W3's mean, 1 - E[F1] / sqrt 3, whatever the octaves. The volume holds only 4^3 cells of
  // octave 0 (weight 1 / 1.33, deviation of 1 - F1 / sqrt 3 about 0.1): the volume's mean is off
  // by about 0.075 / sqrt 64 = 0.009 at one standard error; 5 of them (measured: 0.0024).
  const double expected = 1.0 - moments(monte_carlo_f1(40000)).mean / std::sqrt(3.0);
  CHECK(moments(w3).mean == Approx(expected).epsilon(0).margin(5 * 0.075 / 8));
}
