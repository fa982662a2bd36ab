// The warp's stepping rules on the CPU twin: orders of convergence on a smooth flow with a
// known solution, the geodesic step, tolerance proportionality, and the stable step limits.
#include <catch2/catch.hpp>

#include <cmath>
#include <complex>
#include <vector>

#include "cover/cover_parameters.hpp"
#include "cover/integrators.hpp"
#include "shader_math/shader_math.hpp"
#include "tolerances.hpp"

using namespace nephele;
using namespace nephele::glsl;
using glm::dvec3;
using test::kAdaptiveErrorFactor;
using test::kDoubleUlp;
using test::kUlp;
using test::kUnitLength;

namespace {

// Observed orders of convergence from 3 or 4 step counts: the slope of log error against log h
// differs from the order p by the next term of the error expansion (relative O(h)) and by the
// worst-error maximum switching between start points. The allowed deviations are empirical
// (set to what these step counts give with room), not derived: 0.1 for the first-order
// schemes, 0.2 for Heun, 0.3 for RK4.
constexpr double kFirstOrderSlack = 0.1;
constexpr double kHeunOrderSlack = 0.2;
constexpr double kRk4OrderSlack = 0.3;
// The errors that enter the slope must be truncation errors: at least 1e-5, ten times the float
// rounding of a unit vector after these runs (about 1e-6 as measured: empirical; the worst case,
// a few ulp per step over 800 steps, would be 1e-4, and a random walk of them 5e-6).
constexpr double kAboveRounding = 1e-5;
// The geodesic step along a great circle: 4 steps, each rounding its angle omega h (2^-24 of at
// most 1.7 x 2.5 = 4.25, 2.5e-7) and its sin, cos, cross product and normalisation (about 10 ulp
// of a unit vector, 6e-7): 4 x 8.5e-7 = 3.4e-6; 1e-5 leaves a factor 3.
constexpr double kGeodesicExact = 1e-5;
static_assert(kGeodesicExact >= 4 * (4.25 * kUlp + 10 * kUlp));
// Adaptive Bogacki-Shampine: the global error against the requested tolerance within
// kAdaptiveErrorFactor (tolerances.hpp). The slopes' deviations (0.2 from 1 for the error, 0.15
// from -1/3 for the work) from the three tolerances are empirical.
constexpr double kAdaptiveErrorSlopeSlack = 0.2;
constexpr double kAdaptiveWorkSlopeSlack = 0.15;
// Beyond the stable step a fixed-step scheme's answer is garbage: at least 0.1 rad from the exact
// solution (a threshold for "wrong", not a tolerance; the errors are of order 1).
constexpr double kWrongAnswer = 0.1;
// The adaptive scheme on the stiff rotation (tolerance 1e-5 per step, 50 rad in all): within
// 1e-3 rad, 100 times the per-step tolerance. Empirical (the global error of many sub-steps on a
// fast rotation is not derived here).
constexpr double kStiffAdaptive = 1e-3;
// The stability limits are stored to 4 significant digits (stability_limit: 2.785, 1.732), so
// they are at most 5e-4 from the true boundaries (2.78529..., sqrt(3)); |R| changes there by
// |dR/dz| x 5e-4: 1.51 x 5e-4 = 7.5e-4 for RK4 on the real axis, 0.43 x 5e-4 = 2.2e-4 for RK3 on
// the imaginary axis: 1e-3.
constexpr double kStoredLimit = 1e-3;
static_assert(kStoredLimit >= 1.51 * 5e-4);
// Euler's and Heun's limit 2 is exact and |R(-2)| = 1 exactly in double; the complex modulus
// (hypot) rounds by an ulp or two: 1e-12 is a generous guard (4500 ulp of 1).
constexpr double kExactLimit = 1e-12;
static_assert(kExactLimit >= 4 * kDoubleUlp);
// Just beyond the limit, |R| > 1: 0.01 beyond, 20 times the stored limits' rounding (5e-4).
constexpr double kBeyondLimit = 0.01;

// The zonal flow: the stream function without noise (potential octaves 0), phi = P sin(a lat),
// so v = -s P a cos(a lat) e_east. Points keep their latitude and turn about the axis at the
// angular speed u / cos(lat): the exact flow map is known.
struct ZonalFlow {
  CurlParams curl;
  double flow_time;

  explicit ZonalFlow(double time) : flow_time(time) {
    cover::CoverParameters p;
    p.potential.octaves = 0;
    p.prevailing = 1.0f;
    // The flow the step counts below were chosen for (errors between pre-asymptotic and rounding).
    p.curl_strength = 0.5f;
    p.mix_frequency = 2.5f;
    p.zonal_cells = 0;  // u = -s P m'(lat), the closed form below
    curl = cover::curl_params(p);
  }
  dvec3 exact(vec3 start) const {
    const double lat = std::asin(static_cast<double>(start.z));
    const double lon = std::atan2(static_cast<double>(start.y), static_cast<double>(start.x));
    const double a = curl.mix_frequency;
    const double u = -static_cast<double>(curl.strength) * curl.prevailing * a * std::cos(a * lat);
    const double turned = lon + flow_time * u / std::cos(lat);
    return dvec3(std::cos(lat) * std::cos(turned), std::cos(lat) * std::sin(turned), std::sin(lat));
  }
};

double distance(dvec3 a, dvec3 b) { return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)); }

// Start points away from the poles (where the zonal flow's rate of change grows without bound).
std::vector<vec3> starts() {
  std::vector<vec3> points;
  for (double lat_deg : {-55.0, -32.0, -8.0, 4.0, 21.0, 47.0, 58.0})
    for (double lon_deg : {-150.0, 20.0, 95.0}) {
      const double lat = lat_deg * M_PI / 180, lon = lon_deg * M_PI / 180;
      points.push_back(
          normalize(vec3(dvec3(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)))));
    }
  return points;
}

double worst_error(int integrator, const ZonalFlow& flow, int steps) {
  double worst = 0;
  for (const vec3 s : starts()) {
    const vec3 w = integrate_fixed(integrator, s, steps, static_cast<float>(flow.flow_time / steps), flow.curl);
    worst = std::max(worst, distance(dvec3(w), flow.exact(s)));
  }
  return worst;
}

// Least-squares slope of log(error) against log(x).
double slope(const std::vector<double>& x, const std::vector<double>& error) {
  double mx = 0, my = 0;
  for (size_t k = 0; k < x.size(); ++k) {
    mx += std::log(x[k]) / x.size();
    my += std::log(error[k]) / x.size();
  }
  double sxy = 0, sxx = 0;
  for (size_t k = 0; k < x.size(); ++k) {
    sxy += (std::log(x[k]) - mx) * (std::log(error[k]) - my);
    sxx += (std::log(x[k]) - mx) * (std::log(x[k]) - mx);
  }
  return sxy / sxx;
}

// Observed order: slope of log error against log h = log(T / K). The step counts keep the
// errors between the pre-asymptotic range and float rounding (about 1e-6 here).
double observed_order(int integrator, double flow_time, const std::vector<int>& steps) {
  const ZonalFlow flow(flow_time);
  std::vector<double> h, error;
  for (int k : steps) {
    h.push_back(flow_time / k);
    error.push_back(worst_error(integrator, flow, k));
    INFO("K = " << k << " error " << error.back());
    REQUIRE(error.back() > kAboveRounding);  // well above rounding, so the slope is the truncation's
  }
  return slope(h, error);
}

}  // namespace

TEST_CASE("forward Euler converges at first order on the smooth zonal flow", "[fast][integrators]") {
  const double order = observed_order(INTEGRATOR_EULER, 3.0, {100, 200, 400, 800});
  INFO("observed order " << order);
  CHECK(std::abs(order - 1.0) < kFirstOrderSlack);
}

TEST_CASE("Heun converges at second order on the smooth zonal flow", "[fast][integrators]") {
  const double order = observed_order(INTEGRATOR_HEUN, 3.0, {30, 60, 120});
  INFO("observed order " << order);
  CHECK(std::abs(order - 2.0) < kHeunOrderSlack);
}

TEST_CASE("classical RK4 converges at fourth order on the smooth zonal flow", "[fast][integrators]") {
  const double order = observed_order(INTEGRATOR_RK4, 3.0, {12, 24, 48});
  INFO("observed order " << order);
  CHECK(std::abs(order - 4.0) < kRk4OrderSlack);
}

TEST_CASE("geodesic Euler converges at first order on the smooth zonal flow", "[fast][integrators]") {
  const double order = observed_order(INTEGRATOR_GEODESIC, 3.0, {100, 200, 400, 800});
  INFO("observed order " << order);
  CHECK(std::abs(order - 1.0) < kFirstOrderSlack);
}

TEST_CASE("the geodesic step is exact along a great circle and stays on the sphere", "[fast][integrators]") {
  // A rotation about the axis k moves a point of the great circle orthogonal to k along that
  // circle at the constant speed omega: the geodesic step follows it exactly for any h.
  const vec3 axis = normalize(vec3(0.3f, -0.5f, 0.8f));
  const float omega = 1.7f;
  const auto rotation = [&](vec3 w) { return omega * cross(axis, w); };
  const vec3 start = normalize(cross(axis, vec3(1.0f, 0.0f, 0.0f)));
  for (float h : {0.01f, 0.3f, 1.0f, 2.5f}) {
    const int steps = 4;
    const vec3 w = integrate_fixed(INTEGRATOR_GEODESIC, start, steps, h, rotation);
    // Exact: Rodrigues' rotation of start by omega T about the axis (start is orthogonal to it).
    const double angle = static_cast<double>(omega) * h * steps;
    const dvec3 a(axis), s(start);
    const dvec3 exact = s * std::cos(angle) + glm::cross(a, s) * std::sin(angle);
    INFO("h = " << h);
    CHECK(distance(dvec3(w), exact) < kGeodesicExact);
    CHECK(std::abs(length(w) - 1.0f) < kUnitLength);
  }
}

TEST_CASE("the adaptive error is proportional to the tolerance on the smooth zonal flow", "[fast][integrators]") {
  // Bogacki-Shampine with local extrapolation and error per step: h ~ tol^(1/3), so the
  // third-order global error ~ (T / h) h^4 ~ tol, and the work grows like tol^(-1/3).
  const ZonalFlow flow(1.0);
  std::vector<double> tolerances, errors, work;
  for (float tolerance : {1e-3f, 1e-4f, 1e-5f}) {
    double worst = 0, attempts = 0;
    for (const vec3 s : starts()) {
      const vec4 r = integrate_adaptive(s, 1.0f, 0.1f, 1.0f, tolerance, 100000, flow.curl);
      REQUIRE(r.w > 0.0f);  // reached T
      worst = std::max(worst, distance(dvec3(vec3(r)), flow.exact(s)));
      attempts += r.w;
    }
    tolerances.push_back(tolerance);
    errors.push_back(worst);
    work.push_back(attempts);
    INFO("tolerance " << tolerance << " error " << worst);
    CHECK(worst < kAdaptiveErrorFactor * tolerance);
  }
  CHECK(std::abs(slope(tolerances, errors) - 1.0) < kAdaptiveErrorSlopeSlack);
  CHECK(std::abs(slope(tolerances, work) + 1.0 / 3.0) < kAdaptiveWorkSlopeSlack);
}

TEST_CASE("beyond the stable step Euler goes wrong while the adaptive scheme sub-steps", "[fast][integrators][stiff]") {
  // A fast solid-body rotation: the velocity gradient has eigenvalues +-i omega, the
  // stiffness number is h omega. At h omega = 5 the fixed-step schemes are far beyond their
  // limits; the adaptive scheme's error estimate sees it and takes smaller steps itself.
  const float omega = 50.0f, h = 0.1f;
  const int steps = 10;
  const vec3 axis(0.0f, 0.0f, 1.0f);
  const auto rotation = [&](vec3 w) { return omega * cross(axis, w); };
  const vec3 start = normalize(vec3(1.0f, 0.0f, 1.0f));
  const double angle = static_cast<double>(omega) * h * steps;
  const dvec3 exact(std::cos(angle) / std::sqrt(2.0), std::sin(angle) / std::sqrt(2.0), 1 / std::sqrt(2.0));
  for (auto integrator : {cover::Integrator::euler, cover::Integrator::heun, cover::Integrator::rk4}) {
    INFO(cover::integrator_name(integrator));
    CHECK(h * omega > cover::stability_limit(integrator));
    const vec3 w = integrate_fixed(static_cast<int>(integrator), start, steps, h, rotation);
    CHECK(std::abs(length(w) - 1.0f) < kUnitLength);  // projected: garbage, but on the sphere
    CHECK(distance(dvec3(w), exact) > kWrongAnswer);
  }
  const vec4 adaptive = integrate_adaptive(start, h * steps, h, h * steps, 1e-5f, 100000, rotation);
  INFO("attempted steps " << adaptive.w);
  CHECK(adaptive.w > 10.0f * steps);
  CHECK(distance(dvec3(vec3(adaptive)), exact) < kStiffAdaptive);
}

TEST_CASE("the adaptive scheme reports the texels that ran out of sub-steps", "[fast][integrators]") {
  const ZonalFlow flow(1.0);
  const vec3 start = starts()[3];
  const vec4 capped = integrate_adaptive(start, 1000.0f, 0.1f, 1000.0f, 1e-6f, 50, flow.curl);
  CHECK(capped.w == -50.0f);
  CHECK(std::abs(length(vec3(capped)) - 1.0f) < kUnitLength);
  const vec4 done = integrate_adaptive(start, 1.0f, 0.1f, 1.0f, 1e-6f, 100000, flow.curl);
  CHECK(done.w > 0.0f);
}

TEST_CASE("the stable limits are the stability intervals of each scheme", "[fast][integrators]") {
  // |R(z)| <= 1 at the limit on the real or imaginary axis, > 1 just beyond it.
  auto euler = [](std::complex<double> z) { return 1.0 + z; };
  auto heun = [](std::complex<double> z) { return 1.0 + z + z * z / 2.0; };
  auto rk3 = [](std::complex<double> z) { return 1.0 + z + z * z / 2.0 + z * z * z / 6.0; };
  auto rk4 = [](std::complex<double> z) { return 1.0 + z + z * z / 2.0 + z * z * z / 6.0 + z * z * z * z / 24.0; };
  const double e = cover::stability_limit(cover::Integrator::euler);
  CHECK(std::abs(euler({-e, 0})) <= 1.0 + kExactLimit);
  CHECK(std::abs(euler({-e - kBeyondLimit, 0})) > 1.0);
  const double h = cover::stability_limit(cover::Integrator::heun);
  CHECK(std::abs(heun({-h, 0})) <= 1.0 + kExactLimit);
  CHECK(std::abs(heun({-h - kBeyondLimit, 0})) > 1.0);
  const double r = cover::stability_limit(cover::Integrator::rk4);  // the real axis binds
  CHECK(std::abs(rk4({-r, 0})) <= 1.0 + kStoredLimit);
  CHECK(std::abs(rk4({-r - kBeyondLimit, 0})) > 1.0);
  CHECK(std::abs(rk4({0, r})) <= 1.0);
  const double a = cover::stability_limit(cover::Integrator::adaptive);  // the imaginary axis binds
  CHECK(std::abs(rk3({0, a})) <= 1.0 + kStoredLimit);
  CHECK(std::abs(rk3({0, a + kBeyondLimit})) > 1.0);
  CHECK(std::abs(rk3({-a, 0})) <= 1.0);
}
