// The sea's sun glint (shaders/lib/sun_glint.glsl) on the CPU twin, against closed forms: the
// Fresnel reflectance of water, the slope density's normalisation, the BRDF's reciprocity, its
// peak at the mirror direction and the reflectance it sums to.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "shader_math/shader_math.hpp"

using namespace nephele;

namespace {
constexpr double kPi = 3.14159265358979323846;

glsl::vec3 direction(double zenith, double azimuth) {
  return glsl::vec3(float(std::sin(zenith) * std::cos(azimuth)), float(std::sin(zenith) * std::sin(azimuth)),
                    float(std::cos(zenith)));
}
}  // namespace

TEST_CASE("water reflects ((n - 1)/(n + 1))^2 at normal incidence and everything at grazing incidence",
          "[fast][sun_glint]") {
  const double n = 1.334, normal = (n - 1) * (n - 1) / ((n + 1) * (n + 1));  // 0.02048
  CHECK(glsl::water_fresnel(1.0f) == Approx(normal).epsilon(1e-5));
  CHECK(glsl::water_fresnel(0.0f) == Approx(1.0).epsilon(1e-6));
  // Brewster's angle tan(theta_B) = n: the p reflectance vanishes, R = rs^2 / 2 there.
  const double brewster = std::atan(n), ci = std::cos(brewster),
               ct = std::sqrt(1 - std::pow(std::sin(brewster) / n, 2));
  const double rs = (ci - n * ct) / (ci + n * ct);
  CHECK(glsl::water_fresnel(float(ci)) == Approx(0.5 * rs * rs).epsilon(1e-4));
  float previous = 0.0f;
  for (float c = 1.0f; c >= 0.0f; c -= 0.01f) {  // more reflection towards grazing
    const float r = glsl::water_fresnel(c);
    if (r < previous - 1e-6f) FAIL_CHECK("not monotone at " << c);
    previous = r;
  }
}

TEST_CASE("the sea's slope density integrates to 1 over all slopes", "[fast][sun_glint]") {
  for (float wind : {0.0f, 5.0f, 15.0f}) {
    const double variance = glsl::sea_slope_variance(wind);
    // Isotropic: the integral over the slope plane is int_0^inf p(t^2) 2 pi t dt, midpoint rule on
    // t up to 10 standard deviations (the tail beyond is exp(-100)).
    double sum = 0;
    const int n = 20000;
    const double top = 10 * std::sqrt(variance), dt = top / n;
    for (int i = 0; i < n; ++i) {
      const double t = (i + 0.5) * dt;
      sum += glsl::sea_slope_density(float(t * t), float(variance)) * 2 * kPi * t * dt;
    }
    INFO("wind " << wind);
    CHECK(sum == Approx(1.0).epsilon(1e-4));
  }
  CHECK(glsl::sea_slope_variance(7.0f) == Approx(0.003 + 0.00512 * 7).epsilon(1e-6));  // Cox and Munk 1954
}

TEST_CASE("the glint BRDF is reciprocal, peaks in the mirror direction and reflects the facets' Fresnel share",
          "[fast][sun_glint]") {
  const glsl::vec3 up(0.0f, 0.0f, 1.0f);
  const float wind = 5.0f;
  const glsl::vec3 sun = direction(0.5, 0.3), view = direction(0.8, 2.0);
  CHECK(glsl::sun_glint_brdf(up, view, sun, wind) == Approx(glsl::sun_glint_brdf(up, sun, view, wind)).epsilon(1e-5));
  // With the sun overhead the glint peaks straight down (every factor is symmetric about the
  // vertical and the slope density falls away from it). With the sun at 0.5 rad it peaks in
  // the mirror's azimuth, a little beyond the mirror's zenith (1/mu and the Fresnel factor grow
  // outwards; measured 0.05 rad at 5 m/s): within one standard deviation of the facets' tilt,
  // sigma = 0.17 rad, on the far side.
  const glsl::vec3 zenith_sun(0.0f, 0.0f, 1.0f);
  const float straight_down = glsl::sun_glint_brdf(up, up, zenith_sun, wind);
  for (double z : {0.01, 0.05, 0.2})
    CHECK(glsl::sun_glint_brdf(up, direction(z, 1.0), zenith_sun, wind) < straight_down);
  const double sigma = std::sqrt(glsl::sea_slope_variance(wind));
  double best = -1, best_zenith = 0;
  for (double z = 0.1; z <= 1.2; z += 1e-4) {
    const double f = glsl::sun_glint_brdf(up, direction(z, 0.3 + kPi), sun, wind);
    if (f > best) best = f, best_zenith = z;
  }
  CHECK(best_zenith > 0.5);
  CHECK(best_zenith < 0.5 + sigma);
  CHECK(glsl::sun_glint_brdf(up, direction(best_zenith, 0.3 + kPi + 0.05), sun, wind) ==
        Approx(glsl::sun_glint_brdf(up, direction(best_zenith, 0.3 + kPi - 0.05), sun, wind)).epsilon(1e-4));
  CHECK(glsl::sun_glint_brdf(up, direction(best_zenith, 0.3 + kPi + 0.05), sun, wind) < best);
  CHECK(glsl::sun_glint_brdf(up, direction(1.7, 0.0), sun, wind) == 0.0f);  // view below the horizon
  // Sun overhead: int f mu d(omega) over the view hemisphere is the facets' mean Fresnel
  // reflectance, int rho p dz (the Jacobian of view to slope cancels the 1/(4 mu mu0 cos^4)); the
  // facets that matter tilt by a few degrees, where rho stays within 0.2 % of rho(0) = 0.02048.
  // Midpoint rule in zenith and azimuth; the part of the slopes past 80 degrees of view is
  // below 1e-9.
  const glsl::vec3 overhead(0.0f, 0.0f, 1.0f);
  double reflectance = 0;
  const int nz = 4000, na = 64;
  const double top = 80 * kPi / 180, dz = top / nz, da = 2 * kPi / na;
  for (int i = 0; i < nz; ++i) {
    const double z = (i + 0.5) * dz;
    for (int j = 0; j < na; ++j)
      reflectance +=
          glsl::sun_glint_brdf(up, direction(z, (j + 0.5) * da), overhead, wind) * std::cos(z) * std::sin(z) * dz * da;
  }
  CHECK(reflectance == Approx(0.02048).epsilon(5e-3));
}

TEST_CASE("the sea's wind varies from place to place about its mean, calm in places, as a Rayleigh speed",
          "[fast][sun_glint]") {
  // Points over the whole sphere: the first octave's 400 km cells number about 3200 on the
  // Earth, so the sample's mean wanders by the speed's deviation (0.52 of the mean for Rayleigh)
  // over sqrt(3200): 1 %.
  std::mt19937 random(5);
  std::normal_distribution<double> normal;
  const double mean_wind = 7.0, radius = 6.371e6;
  const int n = 20000;
  double sum = 0;
  int calm = 0;
  for (int k = 0; k < n; ++k) {
    const glm::dvec3 p = radius * glm::normalize(glm::dvec3(normal(random), normal(random), normal(random)));
    const double u = glsl::sea_wind_speed(glsl::vec3(p), float(mean_wind));
    REQUIRE(u >= 0.0);
    sum += u;
    calm += u < 0.5 * mean_wind;
  }
  const double mean = sum / n, calm_share = double(calm) / n;
  INFO("mean " << mean << " m/s, share below half the mean " << calm_share);
  // The components' deviation is Perlin's analytic one, so E[u^2] = 4 / pi mean^2 holds; the mean
  // itself is Rayleigh's (the asked mean) for Gaussian components and at most sqrt(E[u^2]) =
  // 1.128 times it (Jensen) for any others: Perlin sums are lighter-tailed than Gaussian, so
  // between the two, with the sample's 1 % either side.
  CHECK(mean > 0.97 * mean_wind);
  CHECK(mean < 1.128 * 1.01 * mean_wind);
  // Rayleigh: P(u < m / 2) = 1 - exp(-pi / 16) = 0.178; calm patches exist but are a minority.
  CHECK(calm_share > 0.05);
  CHECK(calm_share < 0.3);
}

TEST_CASE("the sea's wind changes little over a kilometre, a hundredth of its shortest wavelength",
          "[fast][sun_glint]") {
  const glm::dvec3 a = 6.371e6 * glm::normalize(glm::dvec3(0.3, -0.4, 0.8));
  const glm::dvec3 east = glm::normalize(glm::cross(glm::dvec3(0, 0, 1), a));
  const float u0 = glsl::sea_wind_speed(glsl::vec3(a), 7.0f);
  // 1 km on, a hundredth of the 100 km octave: the speed moves by at most its gradient times 1 km.
  // Each octave's noise changes by at most about 2 PERLIN_BOUND per lattice cell; summed with the
  // normalisation 7 / (0.31 x 1.25) = 18 m/s per unit, the bound is a few tenths of a m/s per km.
  const float u1 = glsl::sea_wind_speed(glsl::vec3(a + 1000.0 * east), 7.0f);
  CHECK(std::abs(u1 - u0) < 0.5f);
}
