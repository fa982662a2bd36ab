// The circulation of the default flow: vortices concentrated in the storm tracks, cyclones
// marked by the cyclonic depth, and cloudier than anticyclones (docs/climate.md, "Circulation").
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "steady_cover.hpp"
#include "cover/cover_parameters.hpp"
#include "cover_texels.hpp"
#include "shader_math/shader_math.hpp"

using namespace nephele;
using namespace nephele::glsl;

namespace {

vec3 random_unit(std::mt19937& rng) {
  std::normal_distribution<float> g;
  return normalize(vec3(g(rng), g(rng), g(rng)));
}

void tangent_basis(vec3 n, vec3& e1, vec3& e2) {
  const vec3 helper = std::abs(n.z) < 0.9f ? vec3(0, 0, 1) : vec3(1, 0, 0);
  e1 = normalize(cross(helper, n));
  e2 = cross(n, e1);
}

// Relative vorticity (dv2/dx1 - dv1/dx2 in the tangent basis e1, e2 = n x e1, counter-clockwise
// seen from outside positive) by central differences over arcs of h radians.
double vorticity(vec3 n, const CurlParams& c) {
  vec3 e1, e2;
  tangent_basis(n, e1, e2);
  const float h = 2.0e-3f;
  auto v = [&](vec3 p) { return curl_velocity(normalize(p), c); };
  const double dv2_dx1 = (dot(v(n + h * e1), e2) - dot(v(n - h * e1), e2)) / (2.0 * h);
  const double dv1_dx2 = (dot(v(n + h * e2), e1) - dot(v(n - h * e2), e1)) / (2.0 * h);
  return dv2_dx1 - dv1_dx2;
}

// Pearson correlation.
double correlation(const std::vector<double>& a, const std::vector<double>& b) {
  double ma = 0, mb = 0;
  for (size_t k = 0; k < a.size(); ++k) ma += a[k], mb += b[k];
  ma /= a.size();
  mb /= b.size();
  double sab = 0, saa = 0, sbb = 0;
  for (size_t k = 0; k < a.size(); ++k) {
    sab += (a[k] - ma) * (b[k] - mb);
    saa += (a[k] - ma) * (a[k] - ma);
    sbb += (b[k] - mb) * (b[k] - mb);
  }
  return sab / std::sqrt(saa * sbb);
}

// rms of the flow's speed without its zonal bands (prevailing 0) at random points whose
// latitude (degrees) lies in [low, high] in either hemisphere.
double rms_speed(const CurlParams& c, double low, double high, std::mt19937& rng) {
  double sum = 0;
  int count = 0;
  while (count < 3000) {
    const vec3 n = random_unit(rng);
    const double latitude = std::abs(std::asin(double(n.z))) * 180.0 / M_PI;
    if (latitude < low || latitude > high) continue;
    const vec3 v = curl_velocity(n, c);
    sum += dot(v, v);
    ++count;
  }
  return std::sqrt(sum / count);
}

}  // namespace

TEST_CASE("the flow's vortices are concentrated in the storm tracks by the envelope's ratio", "[fast][curl][climate]") {
  // Without the zonal bands the speed scales with the envelope A where dA/dlat = 0: A = 1 at
  // 50 degrees, 1 - 0.6 (1 - 0.004) = 0.402 at the equator. The band mix of the potentials
  // differs between 45-55 and 0-10 degrees, so the ratio with the focus is compared with the
  // ratio without it over the same sampled points: it should grow by 1 / 0.402 = 2.49, less the
  // variation of A inside the bands (A >= 0.94 in 45-55, <= 0.41 in 0-10); sampling 3000 points
  // a band leaves a few percent, so [2.1, 2.8] tests the factor.
  for (uint32_t seed : {1u, 7u}) {
    cover::CoverParameters p = test::steady_cover();
    p.seed = seed;
    CurlParams focused = cover::curl_params(p);
    focused.prevailing = 0.0f;
    CurlParams uniform = focused;
    uniform.storm_tracks = 0.0f;
    std::mt19937 a(seed), b(seed), c(seed + 100), d(seed + 100);
    const double tracks_focused = rms_speed(focused, 45, 55, a), tracks_uniform = rms_speed(uniform, 45, 55, b);
    const double tropics_focused = rms_speed(focused, 0, 10, c), tropics_uniform = rms_speed(uniform, 0, 10, d);
    const double gain = (tracks_focused / tropics_focused) / (tracks_uniform / tropics_uniform);
    INFO("seed " << seed << ": storm tracks / tropics " << tracks_focused / tropics_focused << " focused, "
                 << tracks_uniform / tropics_uniform << " uniform; gain " << gain);
    CHECK(gain > 2.1);
    CHECK(gain < 2.8);
  }
}

TEST_CASE("the cyclonic depth marks cyclonic vorticity in both hemispheres", "[fast][curl][climate]") {
  // Around a feature point of w1 (north) or w2 (south) the flow turns with the Coriolis
  // parameter's sign, so the cyclonic vorticity zeta sign(lat) is high where the depth c is.
  // The relation is not one to one (zeta is the Laplacian of the stream function, c the
  // function itself): the correlation is asked to be clearly positive, > 0.3, in each hemisphere.
  cover::CoverParameters p = test::steady_cover();
  const CurlParams c = cover::curl_params(p);
  std::mt19937 rng(5);
  std::vector<double> depth[2], cyclonic[2];
  while (depth[0].size() < 3000 || depth[1].size() < 3000) {
    const vec3 n = random_unit(rng);
    if (std::abs(n.z) < 0.26f) continue;  // beyond 15 degrees, where the Coriolis sign is clear
    const int hemisphere = n.z > 0 ? 0 : 1;
    depth[hemisphere].push_back(curl_flow_shifted(n, c, vec3(0.0f)).w);
    cyclonic[hemisphere].push_back(vorticity(n, c) * (n.z > 0 ? 1.0 : -1.0));
  }
  for (int hemisphere : {0, 1}) {
    const double r = correlation(depth[hemisphere], cyclonic[hemisphere]);
    INFO((hemisphere == 0 ? "north" : "south") << ": correlation of depth and cyclonic vorticity " << r);
    CHECK(r > 0.3);
  }
}

TEST_CASE("cyclones are cloudier than anticyclones, and the cyclone cloudiness makes them so", "[pass][climate]") {
  // The cloudy fraction (cover > 0) of the texels in the highest third of the cyclonic vorticity
  // against that of the lowest third (beyond 15 degrees). The warped noise alone leaves them
  // close (measured 0.005 apart at k = 0 with the flow of s = 0.2, 0.05 with s = 0.1); with the
  // default k = 0.5 the cyclones must be clearly cloudier: more than 0.1 apart (measured 0.122;
  // 0.17 with s = 0.1, whose weaker vortices stir the noise less), and 0.08 more than without.
  auto gap = [](float cloudiness) {
    cover::CoverParameters p = test::steady_cover();
    p.size = 48;
    p.curl_size = 48;
    p.cyclone_cloudiness = cloudiness;
    // The flow's vortices alone: the weather systems' comma clouds are placed on their own, not
    // on the flow's lows, and would dilute the measure.
    p.cyclones = 0;
    p.itcz = p.trade_cumulus = p.cirrus = 0.0f;
    const CurlParams c = cover::curl_params(p);
    std::vector<std::pair<double, float>> texels;  // (cyclonic vorticity, cover)
    for (const test::CoverTexel& t : test::cover_texels(p)) {
      if (std::abs(t.direction.z) < 0.26f) continue;
      texels.push_back({vorticity(t.direction, c) * (t.direction.z > 0 ? 1.0 : -1.0), t.cover});
    }
    std::sort(texels.begin(), texels.end());
    const size_t third = texels.size() / 3;
    double low = 0, high = 0;
    for (size_t k = 0; k < third; ++k) low += texels[k].second > 0, high += texels[texels.size() - 1 - k].second > 0;
    return (high - low) / third;
  };
  const double with = gap(cover::CoverParameters{}.cyclone_cloudiness), without = gap(0.0f);
  INFO("cloudy fraction of cyclones minus anticyclones: " << with << " with the default cloudiness, " << without
                                                          << " without");
  CHECK(with > 0.1);
  CHECK(with > without + 0.08);
}

TEST_CASE("the storm tracks follow the season of --month, as the latitude profile does", "[fast][curl][climate]") {
  // The annual mean keeps its envelope to the bit.
  CHECK(cover::storm_track_shift(0) == 0.0);
  cover::CoverParameters p = test::steady_cover();
  CHECK(cover::curl_params(p).storm_track_shift == 0.0f);
  // August: the northern track at 50 + seasonal_shift_deg(50, 8), about 3 degrees north; the
  // southern one (the other root of A(z - s)'s peak, z - s = -sin 50) moves north by about as
  // much; February the other way.
  const auto envelope = [](double latitude_deg, double shift) {
    return double(storm_track_envelope(float(std::sin(latitude_deg * M_PI / 180.0) - shift), 0.6f).x);
  };
  const auto peak = [&](double from, double to, double shift) {
    double best = from, best_value = -1;
    for (double lat = from; lat <= to; lat += 0.01)
      if (envelope(lat, shift) > best_value) best_value = envelope(lat, shift), best = lat;
    return best;
  };
  for (int month : {8, 2}) {
    const double s = cover::storm_track_shift(month);
    const double expected = cover::seasonal_shift_deg(50.0, month);
    INFO("month " << month << ": s " << s << ", the profile's storm-track shift " << expected << " degrees");
    CHECK(std::abs(expected) > 2.9);
    CHECK(peak(30, 70, s) == Approx(50.0 + expected).margin(0.02));
    CHECK(peak(-70, -30, s) - (-50.0) == Approx(expected).margin(0.25 * std::abs(expected)));
  }
  // The flow itself: its cyclonic depth is A(z - s) times a part that does not depend on the
  // month, so August's over the annual mean's is A(z - s) / A(z) at every point (float rounding
  // of the two products: a few ulp of the larger).
  p.month = 8;
  const CurlParams august = cover::curl_params(p);
  p.month = 0;
  const CurlParams mean = cover::curl_params(p);
  REQUIRE(august.storm_track_shift == float(cover::storm_track_shift(8)));
  std::mt19937 rng(5);
  for (int k = 0; k < 500; ++k) {
    const vec3 n = random_unit(rng);
    const float c_august = curl_flow_shifted(n, august, vec3(0.0f)).w;
    const float c_mean = curl_flow_shifted(n, mean, vec3(0.0f)).w;
    const float a_august = storm_track_envelope(n.z - august.storm_track_shift, august.storm_tracks).x;
    const float a_mean = storm_track_envelope(n.z, mean.storm_tracks).x;
    INFO("point " << k << " z " << n.z);
    CHECK(std::abs(c_august * a_mean - c_mean * a_august) <=
          8.0f / 16777216.0f * std::max(std::abs(c_august * a_mean), std::abs(c_mean * a_august)) + 1e-30f);
  }
}
