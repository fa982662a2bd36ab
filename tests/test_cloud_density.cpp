// Cloud densities per type and the clear-sky atmosphere (CPU twins of the render shaders).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include "shader_math/shader_math.hpp"
#include "tolerances.hpp"

using namespace nephele::glsl;
using nephele::test::kUlp;

namespace {

// Densities are monotone (in the coverage and the detail noise) in exact arithmetic;
// in float the two sides share the profile factors bit for bit (same h) and only the rounding of
// the threshold factors and their product (a few roundings of values <= 1, 6e-8 each) can
// reverse the order, where both sides saturate or nearly coincide. 1e-6 (16.8 ulp) is a loose
// bound of that, not counted operation by operation (partly empirical).
constexpr float kDensityRounding = 1.0e-6f;
static_assert(kDensityRounding >= 8 * kUlp);
// Phase functions integrated by the midpoint rule over 200000 float nu. The midpoint rule errs by
// h^2/24 x 2 pi (p'(1) - p'(-1)), 5.6e-9 for Henyey-Greenstein g = 0.8 (p'(1) = 215), far less
// for Rayleigh. The float nu = -1 + 2 (i + 0.5) / n is off by the division's rounding of a value
// up to 2 (2^-23 = 1.2e-7; the subtraction is exact or rounds below that), which moves the integral by up to 2 pi (p(1)
// - p(-1)) x that, 2.7e-6 for g = 0.8 (p(1) = 3.58), and evaluating p in float adds a few roundings (5 x 2^-24
// relative): 3e-6 in all (1.3e-6 measured). 2e-3 is about 700x looser (kept as set), for HG and the cloud phase (0.7 HG
// 0.8 + 0.3 HG -0.3, smaller).
constexpr double kPhaseIntegral = 2e-3;
static_assert(kPhaseIntegral >= 2 * M_PI * 3.58 * 2 * kUlp + 5 * kUlp);
// Rayleigh, 3/(16 pi) (1 + nu^2): the float constant (one rounding, 2^-24 relative), about 3
// roundings in the evaluation, and the nu offsets (|p'| <= 0.12: 2 pi x 0.24 x 1.2e-7 = 1.8e-7,
// in the worst case; they cancel between the two symmetric halves): 4 x 2^-24 + 1.8e-7 = 4.2e-7
// (9e-9 measured); 1e-6 leaves a factor 2.4.
constexpr double kRayleighIntegral = 1e-6;
static_assert(kRayleighIntegral >= 4 * kUlp + 2 * M_PI * 0.24 * 2 * kUlp);
// The vertical transmittance's relative error, derived in the test: the midpoint rule's 2.4% of
// the optical depth (0.27 in blue) is 0.65% of the transmittance (0.12% measured in blue).
constexpr double kTransmittanceRelative = 6.5e-3;
static_assert(kTransmittanceRelative >= 0.024 * 0.27);
// Chi-square over 32 bins allows 6 standard deviations: exceeded with probability 5.8e-6 for 31
// degrees of freedom (the seed is fixed, so the test is deterministic).
constexpr double kChiSquareSigmas = 6.0;

}  // namespace

TEST_CASE("cloud densities vanish without coverage or outside their layer and stay within 0 and 1", "[fast][density]") {
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int type = CLOUD_CIRRUS; type <= CLOUD_FOG; ++type) {
    INFO("type " << type);
    for (int k = 0; k < 2000; ++k) {
      const float h = u(rng), c = u(rng), shape = u(rng), detail = u(rng);
      const float d = cloud_density(type, h, c, shape, detail);
      REQUIRE(d >= 0.0f);
      REQUIRE(d <= 1.0f);
      REQUIRE(cloud_density(type, h, 0.0f, shape, detail) == 0.0f);
      REQUIRE(cloud_density(type, -0.01f, c, shape, detail) == 0.0f);
      REQUIRE(cloud_density(type, 1.01f, c, shape, detail) == 0.0f);
    }
  }
}

TEST_CASE("more coverage never thins a heaped cloud", "[fast][density]") {
  std::mt19937 rng(2);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int k = 0; k < 5000; ++k) {
    const float h = u(rng), shape = u(rng), detail = u(rng), c = u(rng);
    const float more = std::min(1.0f, c + 0.1f);
    for (int type : {CLOUD_CIRROCUMULUS, CLOUD_STRATOCUMULUS})
      REQUIRE(cloud_density(type, h, more, shape, detail) >=
              cloud_density(type, h, c, shape, detail) - kDensityRounding);
  }
}

TEST_CASE("a sheet covers the share c of the sky, nothing at c = 0 and everything at c = 1", "[fast][density]") {
  // The shape noise is uniform (the volume is rank-equalised): the sheet's mean over it is the
  // integral of sheet_amount over [0, 1], which the symmetric ramp about 1 - c makes c itself.
  // Midpoint rule over 20000 shapes: the ramp's second derivative is at most 6 / w^2 (w >= 0.02
  // here), so the rule errs by at most 6 / w^2 / 24 h^2 = 1.6e-6 (h = 5e-5) plus float rounding.
  const int n = 20000;
  for (float c : {0.01f, 0.05f, 0.15f, 0.3f, 0.5f, 0.7f, 0.9f, 0.99f}) {
    double mean = 0;
    for (int k = 0; k < n; ++k) mean += sheet_amount(c, (k + 0.5f) / n) / n;
    INFO("c " << c);
    CHECK(mean == Approx(c).margin(1e-5));
  }
  for (int k = 0; k <= 100; ++k) {
    const float shape = k / 100.0f;
    CHECK(sheet_amount(0.0f, shape) == 0.0f);
    if (shape > 0.0f) CHECK(sheet_amount(1.0f, shape) == 1.0f);
    // More coverage never thins the sheet.
    for (float c = 0.0f; c < 1.0f; c += 0.05f) CHECK(sheet_amount(c + 0.05f, shape) >= sheet_amount(c, shape));
  }
}

TEST_CASE("the sea of fog is full below its undulating top and ends within the edge above it", "[fast][density]") {
  // Its top lies at 1 - 0.15 shape of the layer; the edge, 0.05 thick, ends there.
  for (float shape : {0.0f, 0.3f, 1.0f}) {
    INFO("shape " << shape);
    const float top = 1.0f - FOG_TOP_UNDULATION * shape;
    // Below the edge: c (0.85 + 0.15 detail), whatever the height.
    for (float h : {0.0f, 0.4f, top - FOG_TOP_EDGE})
      CHECK(cloud_density(CLOUD_FOG, h, 0.8f, shape, 0.5f) ==
            Approx(0.8f * 0.925f).epsilon(0).margin(kDensityRounding));
    // Halfway up the edge the smoothstep is 1/2; at and above the top nothing.
    CHECK(cloud_density(CLOUD_FOG, top - 0.5f * FOG_TOP_EDGE, 1.0f, shape, 1.0f) ==
          Approx(0.5f).epsilon(0).margin(kDensityRounding));
    CHECK(cloud_density(CLOUD_FOG, top, 1.0f, shape, 1.0f) == 0.0f);
    if (top < 1.0f) CHECK(cloud_density(CLOUD_FOG, 0.5f * (top + 1.0f), 1.0f, shape, 1.0f) == 0.0f);
  }
  // A larger shape value lowers the top: the density at a height never grows with it.
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int k = 0; k < 2000; ++k) {
    const float h = u(rng), shape = u(rng), more = std::min(1.0f, shape + 0.1f);
    REQUIRE(cloud_density(CLOUD_FOG, h, 1.0f, more, 0.5f) <=
            cloud_density(CLOUD_FOG, h, 1.0f, shape, 0.5f) + kDensityRounding);
  }
}

TEST_CASE("the Hermite step is the cubic smoothstep", "[fast][density]") {
  CHECK(hermite_step(0.0f, 1.0f, 0.5f) == 0.5f);
  CHECK(hermite_step(0.0f, 1.0f, 0.25f) == Approx(0.15625f));
  CHECK(hermite_step(2.0f, 3.0f, 1.0f) == 0.0f);
}

TEST_CASE("phase functions integrate to one over the sphere", "[fast][atmosphere]") {
  // Midpoint rule in nu = cos(angle): integral of p over the sphere = 2 pi int p dnu.
  const int n = 200000;
  double hg = 0, rayleigh = 0, cloud = 0;
  for (int i = 0; i < n; ++i) {
    const float nu = -1.0f + 2.0f * (i + 0.5f) / n;
    const double dnu = 2.0 / n;
    hg += 2 * M_PI * henyey_greenstein(nu, 0.8f) * dnu;
    rayleigh += 2 * M_PI * rayleigh_phase(nu) * dnu;
    cloud += 2 * M_PI * cloud_phase(nu, 1.0f) * dnu;
  }
  CHECK(hg == Approx(1.0).epsilon(kPhaseIntegral));
  CHECK(rayleigh == Approx(1.0).epsilon(kRayleighIntegral));
  CHECK(cloud == Approx(1.0).epsilon(kPhaseIntegral));
}

TEST_CASE("vertical transmittance matches the scale-height integral and vanishes below the horizon",
          "[fast][atmosphere]") {
  const float radius = 6371000.0f;
  const vec3 sea_level(0.0f, 0.0f, radius);
  // Straight up, the optical depth is beta_R H_R + beta_M H_M (to within e^{-100 km/H}) plus the
  // ozone's peak absorption times its tent's 15 km. The
  // midpoint rule errs by (h/H)^2/24 of the depth it integrates; with s = L t^2 and 16 steps the
  // step at three Rayleigh scale heights (24 km) is 6.1 km: 2.4% of tau (0.27 in blue), so the
  // transmittance is within 0.65%.
  const vec3 t = transmittance_to_space(sea_level, vec3(0, 0, 1), radius);
  const vec3 beta = rayleigh_scattering() * RAYLEIGH_SCALE_HEIGHT + vec3(MIE_EXTINCTION * MIE_SCALE_HEIGHT) +
                    ozone_absorption() * 15000.0f;
  CHECK(t.x == Approx(std::exp(-beta.x)).epsilon(kTransmittanceRelative));
  CHECK(t.y == Approx(std::exp(-beta.y)).epsilon(kTransmittanceRelative));
  CHECK(t.z == Approx(std::exp(-beta.z)).epsilon(kTransmittanceRelative));
  CHECK(transmittance_to_space(sea_level, normalize(vec3(1, 0, -0.1f)), radius) == vec3(0.0f));
  // Sun just above the horizon: redder light (blue attenuated more).
  const vec3 low_sun = transmittance_to_space(sea_level, normalize(vec3(1, 0, 0.05f)), radius);
  CHECK(low_sun.z < low_sun.x);
}

TEST_CASE("ray-shell intervals cover exactly the part of the ray inside the layer", "[fast][atmosphere]") {
  const vec3 centre(0.0f, 0.0f, -1000.0f);
  // The non-empty intervals of a result, in order.
  auto pieces = [](vec4 r) {
    std::vector<vec2> out;
    if (r.x < r.y) out.emplace_back(r.x, r.y);
    if (r.z < r.w) out.emplace_back(r.z, r.w);
    return out;
  };
  // Straight up from inside the inner sphere: one interval from r_in to r_out.
  const auto up = pieces(ray_shell(vec3(0.0f), vec3(0, 0, 1), centre, 1500.0f, 2000.0f, 1e9f));
  REQUIRE(up.size() == 1);
  CHECK(up[0].x == Approx(500.0f));
  CHECK(up[0].y == Approx(1000.0f));
  // Inside the shell looking down: from 0 to the inner sphere.
  const auto down = pieces(ray_shell(vec3(0.0f), vec3(0, 0, -1), vec3(0.0f, 0.0f, -1800.0f), 1500.0f, 2000.0f, 1e9f));
  REQUIRE(down.size() == 2);  // down to the inner sphere, and again beyond it on the far side
  CHECK(down[0].x == 0.0f);
  CHECK(down[0].y == Approx(300.0f));
  CHECK(down[1].x == Approx(3300.0f));
  CHECK(down[1].y == Approx(3800.0f));
  // A limit cuts the interval.
  const auto cut = pieces(ray_shell(vec3(0.0f), vec3(0, 0, 1), centre, 1500.0f, 2000.0f, 700.0f));
  REQUIRE(cut.size() == 1);
  CHECK(cut[0].y == Approx(700.0f));
}

TEST_CASE("every density grows with the detail noise so its value at detail 1 bounds it", "[fast][density]") {
  // The renderer skips the detail lookup where the bound is zero; this is what makes it exact.
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int type = CLOUD_CIRRUS; type <= CLOUD_FOG; ++type) {
    for (int k = 0; k < 5000; ++k) {
      const float h = u(rng), c = u(rng), shape = u(rng), detail = u(rng);
      REQUIRE(cloud_density(type, h, c, shape, detail) <= cloud_density(type, h, c, shape, 1.0f) + kDensityRounding);
    }
  }
}

TEST_CASE("mixing two uniform noises and applying uniform_from_mix gives a uniform value", "[fast][density]") {
  // Chi-square over 32 bins of 100000 samples: mean 31, standard deviation 7.9; kChiSquareSigmas
  // of them bound it.
  std::mt19937 rng(4);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<int> counts(32, 0);
  const int n = 100000;
  for (int k = 0; k < n; ++k) {
    const float v = uniform_from_mix(mix(u(rng), u(rng), 0.4f), 0.4f);
    REQUIRE(v >= 0.0f);
    REQUIRE(v <= 1.0f);
    counts[std::min(31, int(v * 32))]++;
  }
  double chi2 = 0;
  for (int c : counts) chi2 += (c - n / 32.0) * (c - n / 32.0) / (n / 32.0);
  CHECK(chi2 < 31 + kChiSquareSigmas * std::sqrt(62.0));
  CHECK(uniform_from_mix(0.0f, 0.4f) == 0.0f);
  CHECK(uniform_from_mix(1.0f, 0.4f) == 1.0f);
  CHECK(uniform_from_mix(0.5f, 0.4f) == Approx(0.5f));
}
