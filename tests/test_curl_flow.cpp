// The curl flow: tangent, divergence-free, the formula of the stream function, the zonal winds.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "cover/cover_parameters.hpp"
#include "curl_bounds.hpp"
#include "shader_math/shader_math.hpp"
#include "tolerances.hpp"

using namespace nephele::glsl;
using nephele::test::kFbmValueRounding;
using nephele::test::kTangentRelative;

namespace {

// The midpoint rule's flux error is O(ds) per Voronoi border crossed (where v jumps), so the
// relative flux is below C / M for M samples; C = 20 is empirical (it depends on how many borders
// a loop crosses and how large the jumps are against the mean speed, not derived).
constexpr double kFluxTimesSamples = 20.0;
// Points whose one-sided differences disagree by more than this straddle a Voronoi border and
// are skipped: a choice (empirical, it keeps more than 1000 of the 2000 points), not a bound.
constexpr double kStreamKinkGap = 0.05;
// Zonal flow without noise (defaults s = 0.5, P = 0.5, a = 2.5, so |u| <= s P a = 0.625): the
// latitude from portable_asin errs by kPortableAsin (5.2e-7), which moves u = -s P a cos(a lat)
// by s P a^2 x that = 8.1e-7; the float directions n and east (half an ulp per component) and
// the cross product's few ulp of 0.625 add about 5e-7: 1.3e-6 in all; 1e-5 leaves a factor 7.
constexpr float kZonalWind = 1.0e-5f;
static_assert(kZonalWind >= 0.5 * 0.5 * 2.5 * 2.5 * nephele::test::kPortableAsin + 8 * 0.625 * nephele::test::kUlp);
// At a pole n = (0, 0, +-1): the latitude term is dropped and v.z = s (n.x g.y - n.y g.x) is
// exactly zero (products with zero, fused or not). Exact; the margin only guards the check.
constexpr float kPoleVertical = 1.0e-6f;

vec3 random_unit(std::mt19937& rng) {
  std::normal_distribution<float> g;
  return normalize(vec3(g(rng), g(rng), g(rng)));
}

CurlParams default_curl(uint32_t seed = 1) {
  nephele::cover::CoverParameters p;
  p.seed = seed;
  return nephele::cover::curl_params(p);
}

// Two unit vectors spanning the tangent plane at n.
void tangent_basis(vec3 n, vec3& e1, vec3& e2) {
  const vec3 helper = std::abs(n.z) < 0.9f ? vec3(0, 0, 1) : vec3(1, 0, 0);
  e1 = normalize(cross(helper, n));
  e2 = cross(n, e1);
}

// The zonal profile's latitude derivative Z'(lat) as docs/climate.md writes it: for `cells`
// 1..3, 3 cos(lat) times (1 - sin^2 lat / sin^2(90 k / cells) deg) over k = 1 .. cells - 1;
// cells 0: m'(lat) = a cos(a lat).
double zonal_derivative(double lat, int cells, double a) {
  if (cells == 0) return a * std::cos(a * lat);
  double product = 3.0 * std::cos(lat);
  for (int k = 1; k < cells; ++k)
    product *= 1.0 - std::pow(std::sin(lat), 2) / std::pow(std::sin(M_PI / 2 * k / cells), 2);
  return product;
}

// Z itself for three cells (the integral of 3 (1 - 4 z^2)(1 - 4 z^2 / 3) dz) or m for cells 0.
double zonal_profile(double z, int cells, double a) {
  if (cells == 0) return std::sin(a * std::asin(z));
  REQUIRE(cells == 3);
  return 3 * z - 16.0 / 3.0 * z * z * z + 16.0 / 5.0 * std::pow(z, 5);
}

// The storm-track envelope as docs/climate.md writes it: 1 - f (1 - exp(-((z^2 - sin^2 50deg) / 0.25)^2)).
double envelope(double z, double focus) {
  const double track = std::sin(50.0 * M_PI / 180.0);
  const double u = (z * z - track * track) / 0.25;
  return 1.0 - focus * (1.0 - std::exp(-u * u));
}

// The stream function written out independently of curl_velocity, from fBm values only.
double stream_function(vec3 p, const CurlParams& c) {
  const double w1 = smooth_worley_fbm(p, c.potential_north, c.smoothing).w;
  const double w2 = smooth_worley_fbm(p, c.potential_south, c.smoothing).w;
  const double z = std::clamp(static_cast<double>(p.z), -1.0, 1.0);
  const double m = std::sin(c.mix_frequency * std::asin(z));
  return c.strength * (c.prevailing * zonal_profile(z, c.zonal_cells, c.mix_frequency) +
                       envelope(z, c.storm_tracks) * (-w1 * (1 + m) / 2 + w2 * (1 - m) / 2));
}

}  // namespace

TEST_CASE("curl vectors are tangent to the sphere", "[fast][curl]") {
  const CurlParams c = default_curl();
  std::mt19937 rng(1);
  for (int k = 0; k < 5000; ++k) {
    const vec3 n = random_unit(rng);
    const vec3 v = curl_velocity(n, c);
    // cross(n, g) . n vanishes up to float rounding of |g|.
    REQUIRE(std::abs(dot(v, n)) <= kTangentRelative * (1.0f + length(v)));
  }
}

TEST_CASE("the curl field is divergence-free: its flux through closed loops vanishes", "[fast][curl]") {
  // Flux of n x grad phi through a loop = the change of phi around it = 0 (phi is continuous,
  // though its gradient jumps at Voronoi borders). The midpoint rule errs by O(ds) per border
  // crossed, so the relative flux falls like 1/M with M samples.
  const CurlParams c = default_curl();
  std::mt19937 rng(2);
  for (int loop = 0; loop < 20; ++loop) {
    const vec3 centre = random_unit(rng);
    vec3 e1, e2;
    tangent_basis(centre, e1, e2);
    const double radius = 0.05 + 0.1 * loop / 20.0;
    double previous_relative = 1.0;
    for (int samples : {500, 5000}) {
      double flux = 0, magnitude = 0;
      const double ds = 2 * M_PI * std::sin(radius) / samples;
      for (int k = 0; k < samples; ++k) {
        const double theta = 2 * M_PI * (k + 0.5) / samples;
        const vec3 radial = static_cast<float>(std::cos(theta)) * e1 + static_cast<float>(std::sin(theta)) * e2;
        const vec3 q = static_cast<float>(std::cos(radius)) * centre + static_cast<float>(std::sin(radius)) * radial;
        const vec3 outward =
            -static_cast<float>(std::sin(radius)) * centre + static_cast<float>(std::cos(radius)) * radial;
        const vec3 v = curl_velocity(q, c);
        flux += dot(v, outward) * ds;
        magnitude += length(v) * ds;
      }
      const double relative = std::abs(flux) / magnitude;
      INFO("loop " << loop << " samples " << samples << " relative flux " << relative);
      CHECK(relative < kFluxTimesSamples / samples);
      previous_relative = relative;
    }
    (void)previous_relative;
  }
}

TEST_CASE("curl_velocity equals s n x grad phi of the documented stream function", "[fast][curl]") {
  // grad phi by central differences of the stream function written out in the test; points
  // whose stencil straddles a Voronoi border (one-sided differences disagree) are skipped.
  const CurlParams c = default_curl(5);
  std::mt19937 rng(3);
  const float h = 1e-3f;
  int compared = 0;
  for (int k = 0; k < 2000; ++k) {
    const vec3 n = random_unit(rng);
    if (std::abs(n.z) > 0.999f) continue;
    dvec3 gradient;
    double gap = 0;
    const double f0 = stream_function(n, c);
    for (int a = 0; a < 3; ++a) {
      vec3 e(0.0f);
      e[a] = h;
      const double plus = stream_function(n + e, c), minus = stream_function(n - e, c);
      gradient[a] = (plus - minus) / (2 * h);
      gap = std::max(gap, std::abs((plus - f0) - (f0 - minus)) / h);
    }
    if (gap > kStreamKinkGap) continue;
    ++compared;
    const vec3 expected = vec3(glm::cross(dvec3(n), gradient));
    const vec3 actual = curl_velocity(n, c);
    // Truncation: central differences of |p - feature| err by (h f_k / F1_k)^2 per octave;
    // rounding: phi is evaluated to ~1e-7 (kFbmValueRounding), twice, divided by 2h.
    const float tolerance =
        kFbmValueRounding / h + static_cast<float>(gap) +
        nephele::test::curl_octave_bound(n, c, [&](float f, float f1) { return 2.0f * (h * f / f1) * (h * f / f1); });
    REQUIRE(length(actual - expected) < tolerance);
  }
  CHECK(compared > 1000);
}

TEST_CASE("the storm-track envelope is 1 at 50 degrees, 1 - f at the equator, and its derivative is dA/dz",
          "[fast][curl]") {
  // Values: float exp and products, a few ulp of 1. Derivative: the central difference with
  // h = 1e-3 errs by h^2 |A^(3)| / 6, below 3.3e-4 (|A^(3)| < 2000 for f = 1: three factors
  // 4 z u / sigma of at most 16 each), plus rounding 2 ulp / 2h = 1.2e-4: 1e-3 bounds both.
  constexpr float kValue = 1.0e-6f, kDerivative = 1.0e-3f;
  const float track = std::sin(50.0f * float(M_PI) / 180.0f);
  for (float focus : {0.0f, 0.6f, 1.0f}) {
    INFO("focus " << focus);
    CHECK(std::abs(storm_track_envelope(0.0f, focus).x - envelope(0.0, focus)) < kValue);
    CHECK(envelope(0.0, focus) == Approx(1.0 - focus).margin(0.01));  // g(0) = exp(-5.5) = 0.004
    CHECK(std::abs(storm_track_envelope(track, focus).x - 1.0f) < kValue);
    CHECK(std::abs(storm_track_envelope(-track, focus).x - 1.0f) < kValue);
    for (float z = -0.995f; z < 1.0f; z += 0.0625f) {
      const double h = 1e-3;
      const double numeric = (envelope(z + h, focus) - envelope(z - h, focus)) / (2 * h);
      CHECK(std::abs(storm_track_envelope(z, focus).x - envelope(z, focus)) < kValue);
      CHECK(std::abs(storm_track_envelope(z, focus).y - numeric) < kDerivative);
    }
  }
}

TEST_CASE("the cyclonic depth is the vortex part of the stream function with the sign of the Coriolis parameter",
          "[fast][curl]") {
  // c = A (w1 (1 + m)/2 + w2 (1 - m)/2), written out here from the fBm values.
  const CurlParams c = default_curl(4);
  std::mt19937 rng(8);
  for (int k = 0; k < 500; ++k) {
    const vec3 n = random_unit(rng);
    const double w1 = smooth_worley_fbm(n, c.potential_north, c.smoothing).w;
    const double w2 = smooth_worley_fbm(n, c.potential_south, c.smoothing).w;
    const double m = std::sin(c.mix_frequency * std::asin(std::clamp(static_cast<double>(n.z), -1.0, 1.0)));
    const double expected = envelope(n.z, c.storm_tracks) * (w1 * (1 + m) / 2 + w2 * (1 - m) / 2);
    // float sums of values below 1 (a few ulp) and m from portable_asin (kPortableAsin times a).
    REQUIRE(std::abs(curl_flow_shifted(n, c, vec3(0.0f)).w - expected) < 1.0e-5);
  }
}

TEST_CASE("without noise the flow is the zonal wind u = -s P Z'(lat) of its cells", "[fast][curl]") {
  CurlParams c = default_curl();
  c.potential_north.octaves = 0;
  c.potential_south.octaves = 0;
  for (int cells : {0, 1, 2, 3}) {
    c.zonal_cells = cells;
    for (double latitude_deg : {-80.0, -45.0, -20.0, 0.0, 10.0, 36.0, 60.0, 85.0}) {
      for (double longitude_deg : {-170.0, 0.0, 33.0}) {
        const double lat = latitude_deg * M_PI / 180, lon = longitude_deg * M_PI / 180;
        const vec3 n(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat));
        const vec3 east(-std::sin(lon), std::cos(lon), 0.0);
        const double u = -c.strength * c.prevailing * zonal_derivative(lat, cells, c.mix_frequency);
        const vec3 v = curl_velocity(n, c);
        INFO("cells " << cells << " lat " << latitude_deg << " lon " << longitude_deg);
        CHECK(dot(v, east) == Approx(u).epsilon(0).margin(kZonalWind));
        CHECK(length(v - static_cast<float>(u) * east) < kZonalWind);
      }
    }
  }
  // The default three cells, P > 0: trade easterlies (u < 0) below 30 degrees, westerlies from
  // 30 to 60 and polar easterlies beyond, in both hemispheres.
  c.zonal_cells = 3;
  for (double sign : {1.0, -1.0})
    for (auto [latitude_deg, easterly] : {std::pair{15.0, true}, {45.0, false}, {75.0, true}}) {
      const double lat = sign * latitude_deg * M_PI / 180;
      const float u = curl_velocity(vec3(std::cos(lat), 0.0, std::sin(lat)), c).y;  // east at lon 0 is +y
      INFO("lat " << sign * latitude_deg << ": u " << u);
      CHECK((u < 0.0f) == easterly);
    }
}

TEST_CASE("the curl field is finite at the poles", "[fast][curl][extreme]") {
  const CurlParams c = default_curl();
  for (const vec3 pole : {vec3(0, 0, 1), vec3(0, 0, -1)}) {
    const vec3 v = curl_velocity(pole, c);
    CHECK(std::isfinite(v.x));
    CHECK(std::isfinite(v.y));
    CHECK(std::isfinite(v.z));
    CHECK(std::abs(v.z) < kPoleVertical);
  }
}

TEST_CASE("the default flow is continuous through the poles where a = 2.5 whirls", "[fast][curl][poles]") {
  // Points at angular distance rho from a pole on opposite sides (longitudes 0 and 180 deg).
  // A continuous field gives velocities that agree as rho -> 0, within rho times its Lipschitz
  // bound; with a = 2.5 the zonal term keeps the speed s (P - w) a |cos(2.5 x 90 deg)| right
  // up to the pole in opposite directions (a whirl), the cause of the pole-line artefacts.
  auto gap = [](const CurlParams& c, float pole, float rho) {
    const vec3 a(std::sin(rho), 0.0f, pole * std::cos(rho));
    const vec3 b(-std::sin(rho), 0.0f, pole * std::cos(rho));
    return length(curl_velocity(a, c) - curl_velocity(b, c));
  };
  CurlParams smooth = default_curl();
  REQUIRE(smooth.mix_frequency == 3.0f);
  CurlParams whirl = smooth;
  whirl.mix_frequency = 2.5f;
  whirl.zonal_cells = 0;    // the zonal winds follow m: P m' stays finite at the pole
  whirl.prevailing = 3.0f;  // P - w >= 3 - (1 + 0.3 ln 27) = 1.0: the whirl cannot cancel
  for (float pole : {1.0f, -1.0f}) {
    const float coarse = gap(smooth, pole, 1e-2f), fine = gap(smooth, pole, 1e-4f);
    INFO("pole " << pole << ": a = 3 gaps " << coarse << ", " << fine << "; a = 2.5 " << gap(whirl, pole, 1e-4f));
    CHECK(fine <= 0.02f * coarse + 1e-6f);  // shrinks with rho (100 times), up to rounding
    // The whirl: 2 s (P - w) 2.5 |cos 225 deg| >= 2 s x 1.0 x 1.77 = 3.5 s.
    CHECK(gap(whirl, pole, 1e-4f) > 3.0f * whirl.strength);
  }
}
