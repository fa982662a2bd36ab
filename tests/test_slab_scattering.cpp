// The light of a plane-parallel cloud slab (shaders/lib/slab_scattering.glsl) on the CPU twin:
// the delta-Eddington reflectance against a Monte Carlo of photons in a Henyey-Greenstein slab,
// its closed form at mu0 = 2/3, and the linear source that gives a marched slab that reflectance
// from above and that diffuse transmittance from below.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include "shader_math/shader_math.hpp"

using namespace nephele;

namespace {
constexpr double kPi = 3.14159265358979323846;

// The share of `photons` entering a conservatively scattering slab of optical thickness tau at
// cosine mu0 that leave it through its top: each photon flies exponential free paths and scatters
// by the Henyey-Greenstein phase function of asymmetry g (its inverse cumulative distribution).
double monte_carlo_reflectance(double tau, double mu0, double g, int photons, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  int reflected = 0;
  for (int n = 0; n < photons; ++n) {
    double depth = 0, down = mu0;  // optical depth below the top; direction cosine, > 0 downwards
    for (;;) {
      depth += -std::log(1.0 - uniform(rng)) * down;
      if (depth < 0) {
        ++reflected;
        break;
      }
      if (depth > tau) break;
      const double s = (1 - g * g) / (1 - g + 2 * g * uniform(rng));
      const double cos_theta = (1 + g * g - s * s) / (2 * g);
      const double sin_theta = std::sqrt(std::max(0.0, 1 - cos_theta * cos_theta));
      const double sin_down = std::sqrt(std::max(0.0, 1 - down * down));
      down = down * cos_theta + sin_down * sin_theta * std::cos(2 * kPi * uniform(rng));
    }
  }
  return double(reflected) / photons;
}

// The radiance of the source J(t) = max(x + y t, 0) (with the single scattering) seen straight
// down (.x) and straight up from below (.y): midpoint sums over 20000 layers (error far below 1e-6).
std::pair<double, double> marched_slab(double tau, double mu0, double phase_down, double phase_up) {
  const glsl::vec2 source = glsl::slab_source(float(tau), float(mu0), float(phase_down), float(phase_up));
  const int layers = 20000;
  const double dt = tau / layers;
  double top = 0, bottom = 0;
  for (int k = 0; k < layers; ++k) {
    const double t = (k + 0.5) * dt;
    const double j = glsl::slab_source_at(source, float(t));
    const double sun = std::exp(-t / mu0);
    top += (j + phase_down * sun) * std::exp(-t) * dt;
    bottom += (j + phase_up * sun) * std::exp(-(tau - t)) * dt;
  }
  return {top, bottom};
}
}  // namespace

TEST_CASE("the delta-Eddington slab reflects what photons in a Henyey-Greenstein slab do", "[fast][slab]") {
  // 20000 photons: the Monte Carlo's standard error is at most 0.5 / sqrt(20000) = 0.0035; four of
  // them plus the approximation's own error, which Joseph, Wiscombe and Weinman (1976) give as a
  // few hundredths for a high sun and larger for a low one, where delta-Eddington reflects too
  // little. Measured: within 0.016 for mu0 >= 0.5 and 0.06 at 0.3.
  const double g = 0.85;
  const int photons = 20000;
  const double sigma4 = 4 * 0.5 / std::sqrt(double(photons));
  unsigned seed = 1;
  for (double tau : {1.0, 4.0, 16.0, 64.0}) {
    for (double mu0 : {0.3, 0.5, 2.0 / 3.0, 1.0}) {
      const double exact = monte_carlo_reflectance(tau, mu0, g, photons, seed++);
      const double approximate = glsl::slab_reflectance(float(tau), float(mu0));
      INFO("tau " << tau << ", mu0 " << mu0 << ": Monte Carlo " << exact << ", delta-Eddington " << approximate);
      if (mu0 >= 0.5) {
        CHECK(std::abs(approximate - exact) <= 0.02 + sigma4);
      } else {
        CHECK(approximate <= exact + sigma4);
        CHECK(approximate >= exact - 0.07 - sigma4);
      }
    }
  }
}

TEST_CASE("at mu0 = 2/3 the slab reflects (1 - g) tau / (4/3 + (1 - g) tau), from 0 to all of the light",
          "[fast][slab]") {
  // There the direct beam's term (1/2 - 3/4 mu0) vanishes, leaving the two-stream closed form.
  for (double tau : {0.0, 0.5, 3.6, 23.0, 100.0, 1.0e4}) {
    const double expected = 0.15 * tau / (4.0 / 3.0 + 0.15 * tau);
    CHECK(glsl::slab_reflectance(float(tau), 2.0f / 3.0f) == Approx(expected).margin(1e-6));
  }
  // More cloud reflects more, at any sun; none reflects more than all.
  for (double mu0 : {0.05, 0.3, 0.7, 1.0}) {
    double previous = -1;
    for (double tau = 0; tau <= 200; tau += 0.5) {
      const double r = glsl::slab_reflectance(float(tau), float(mu0));
      CHECK(r > previous - 1e-7);
      CHECK(r <= 1.0);
      previous = r;
    }
  }
  // What is neither reflected nor passed on directly passes diffuse: never a negative share.
  for (double tau : {0.1, 1.0, 10.0, 100.0})
    for (double mu0 : {0.05, 0.5, 1.0})
      CHECK(1 - glsl::slab_reflectance(float(tau), float(mu0)) -
                glsl::slab_direct_transmittance(float(tau), float(mu0)) >=
            -1e-6);
}

TEST_CASE("the slab's source makes the marched slab reflect R mu0 / pi and pass T mu0 / pi", "[fast][slab]") {
  // The conditions slab_source solves for, checked by integrating its J over the depth with the
  // single scattering of the view's phase values: exact but for float rounding (1e-5 of the sun's
  // light). Where the line through both would turn negative at the base (a low sun on a thin
  // slab), J falls to 0 there instead: the view from above stays exact, the one from below is
  // brighter than the diffuse transmittance's.
  int fallen = 0, risen = 0;
  for (double tau : {0.5, 1.0, 2.0, 8.0, 32.0}) {
    for (double mu0 : {0.3, 0.7, 1.0}) {
      for (double phase_up : {0.06, 0.6}) {
        const double phase_down = 0.02;
        const glsl::vec2 source = glsl::slab_source(float(tau), float(mu0), float(phase_down), float(phase_up));
        INFO("tau " << tau << ", mu0 " << mu0 << ": J = " << source.x << " + " << source.y << " t");
        CHECK(source.x + source.y * tau >= -1e-6);
        CHECK(source.x >= 0);
        const auto [top, bottom] = marched_slab(tau, mu0, phase_down, phase_up);
        const double reflectance = glsl::slab_reflectance(float(tau), float(mu0));
        const double diffuse = 1 - reflectance - glsl::slab_direct_transmittance(float(tau), float(mu0));
        // Where the view's single scattering alone is brighter (a thin slab under a high sun: the
        // view's phase function has a backward lobe), that stays and J is 0.
        const glsl::vec2 single =
            glsl::slab_single_scattering(float(tau), float(mu0), float(phase_down), float(phase_up));
        CHECK(top == Approx(std::max(reflectance * mu0 / kPi, double(single.x))).margin(1e-5));
        const bool falls_to_zero = std::abs(source.x + source.y * tau) < 1e-6;
        const bool rises_from_zero = source.x == 0 && source.y > 0;
        if (falls_to_zero) ++fallen;
        if (rises_from_zero) ++risen;
        if (falls_to_zero)
          CHECK(bottom >= diffuse * mu0 / kPi - 1e-5);
        else if (rises_from_zero)
          CHECK(bottom <= diffuse * mu0 / kPi + 1e-5);
        else
          CHECK(bottom == Approx(std::max(diffuse * mu0 / kPi, double(single.y))).margin(1e-5));
      }
    }
  }
  // Thin slabs (here 9 fall to 0 at the base and 6 rise from 0 at the top, of the 30) take a
  // line through 0; decks of tau 8 and more meet both conditions (checked above).
  CHECK(fallen + risen > 0);
  // A thin slab (tau 0.1): the view from above still exact, J constant.
  const glsl::vec2 thin = glsl::slab_source(0.1f, 0.8f, 0.01f, 0.6f);
  CHECK(thin.y == 0.0f);
  CHECK(marched_slab(0.1, 0.8, 0.01, 0.6).first == Approx(glsl::slab_reflectance(0.1f, 0.8f) * 0.8 / kPi).margin(1e-6));
  // No sun, no light.
  CHECK(glsl::slab_source(8.0f, -0.1f, 0.05f, 0.6f).x == 0.0f);
}

TEST_CASE("the source's moment difference tau - 2 + (2 + tau) exp(-tau) is accurate on both sides of tau 1",
          "[fast][slab]") {
  for (double tau : {0.01, 0.1, 0.5, 0.999, 1.0, 1.001, 3.0, 30.0}) {
    const double exact = tau - 2 + (2 + tau) * std::exp(-tau);  // double: cancels to 1e-16 / 1.7e-7 at 0.01
    CHECK(glsl::slab_moment_difference(float(tau)) == Approx(exact).epsilon(2e-4));
  }
}

TEST_CASE("a slab lit by a uniform sky looks from above as bright as the share of the sky's light it reflects",
          "[fast][slab]") {
  // Seen straight down, the uniform source J gives J (1 - exp(-tau)); the slab reflects
  // 1 - 1 / (1 + 0.1125 tau) of the diffuse light falling on it, which a Lambertian top returns
  // as that share of the sky's radiance.
  for (double tau : {1.0e-5, 0.01, 1.0, 10.0, 300.0}) {
    const double reflected = 1 - 1 / (1 + 0.1125 * tau);
    CHECK(glsl::slab_sky_source(float(tau)) * (1 - std::exp(-tau)) == Approx(reflected).epsilon(1e-4).margin(1e-9));
  }
}
