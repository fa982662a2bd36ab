// The weather systems' shapes (shaders/lib/weather_systems.glsl, on the CPU) and the host's
// schedule of cyclones (src/cover/weather_systems.cpp).
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

#include "cover/moving_flow.hpp"
#include "cover/weather_systems.hpp"
#include "shader_math/shader_math.hpp"

using namespace nephele;
using glsl::vec2;
using glsl::vec3;

namespace {

constexpr double earth_radius_km = 6371.0;

// The angle between unit vectors, accurate for nearly equal ones too (acos of the dot is not).
double angle_between(vec3 a, vec3 b) {
  const glm::dvec3 da(a), db(b);
  return std::atan2(glm::length(glm::cross(da, db)), glm::dot(da, db));
}

// Signed angle east of b from a (longitude difference in (-pi, pi]).
double longitude_step(vec3 a, vec3 b) {
  const double d = std::atan2(b.y, b.x) - std::atan2(a.y, a.x);
  return std::remainder(d, 2.0 * M_PI);
}

}  // namespace

TEST_CASE("a comma cloud covers the cold front and the head and leaves the dry slot and the low clear",
          "[fast][systems]") {
  const float wrap = cover::cyclone_wrap(0.5);
  // On the cold front's axis, half way from its end to the join (-0.7, -3) .. (1, -0.6).
  CHECK(glsl::comma_cloud(vec2(0.15f, -1.8f), wrap, 0.0f) == 1.0f);
  // On the head's spiral half way round: r = |join| exp(-k wrap / 2), at theta_join + wrap / 2.
  const float r_join = std::hypot(1.0f, -0.6f), theta_join = std::atan2(-0.6f, 1.0f);
  const float k = std::log(r_join / 0.3f) / wrap;
  const float r = r_join * std::exp(-k * wrap / 2), theta = theta_join + wrap / 2;
  CHECK(glsl::comma_cloud(vec2(r * std::cos(theta), r * std::sin(theta)), wrap, 0.0f) == 1.0f);
  // Behind the cold front towards the low (the dry slot) and the low's centre: clear.
  CHECK(glsl::comma_cloud(vec2(-0.6f, -1.2f), wrap, 0.0f) == 0.0f);
  CHECK(glsl::comma_cloud(vec2(0.0f, 0.0f), wrap, 0.0f) == 0.0f);
  // Far from the system: clear. The edge noise moves the band across by 0.6 of its half width:
  // towards the broad front side the core stays, and half of it towards the narrow rear side
  // (0.3 of 0.7 half widths); all of it breaks the band there.
  CHECK(glsl::comma_cloud(vec2(3.5f, 3.5f), wrap, 1.0f) == 0.0f);
  CHECK(glsl::comma_cloud(vec2(0.15f, -1.8f), wrap, 1.0f) == 1.0f);
  CHECK(glsl::comma_cloud(vec2(0.15f, -1.8f), wrap, -0.5f) == 1.0f);
  CHECK(glsl::comma_cloud(vec2(0.15f, -1.8f), wrap, -1.0f) < 0.5f);
}

TEST_CASE("a band's edge is sharp: from all to nothing over 0.4 of its half width", "[fast][systems]") {
  CHECK(glsl::band_profile(0.0f, 1.0f) == 1.0f);
  CHECK(glsl::band_profile(0.6f, 1.0f) == 1.0f);
  CHECK(glsl::band_profile(-0.6f, 1.0f) == 1.0f);
  CHECK(glsl::band_profile(0.8f, 1.0f) == Approx(0.5f).margin(1e-6));
  CHECK(glsl::band_profile(1.0f, 1.0f) == 0.0f);
  CHECK(glsl::band_profile(-2.0f, 1.0f) == 0.0f);
}

TEST_CASE("cyclones live in the storm tracks with orthonormal frames whose pole axis points to their own pole",
          "[fast][systems]") {
  cover::CoverParameters p;
  for (double hours : {0.0, 1000.0, 55555.5, 236000.0}) {
    const glsl::WeatherSystems w = cover::weather_systems(p, hours);
    REQUIRE(w.cyclone_count > 0);
    for (int i = 0; i < w.cyclone_count; ++i) {
      const glsl::Cyclone& c = w.cyclones[i];
      const double latitude = std::asin(c.centre.z) * 180.0 / M_PI;
      INFO("hours " << hours << " cyclone " << i << " latitude " << latitude);
      // Genesis at 38 +- 6 degrees, then up to 10 degrees poleward.
      CHECK(std::abs(latitude) >= 32.0 - 1e-3);
      CHECK(std::abs(latitude) <= 54.0 + 1e-3);
      CHECK(glm::length(c.centre) == Approx(1.0f).margin(1e-6));
      CHECK(std::abs(glm::dot(c.centre, c.east)) < 1e-6f);
      CHECK(std::abs(glm::dot(c.centre, c.pole)) < 1e-6f);
      CHECK(std::abs(glm::dot(c.east, c.pole)) < 1e-6f);
      CHECK(c.pole.z * c.centre.z > 0.0f);  // towards the pole of its own hemisphere
      CHECK(c.strength >= 0.0f);
      CHECK(c.strength <= 1.0f);
    }
  }
}

TEST_CASE("on average the schedule keeps the asked number of cyclones alive per hemisphere", "[fast][systems]") {
  for (int n : {1, 6, 15}) {
    cover::CoverParameters p;
    p.cyclones = n;
    double sum = 0;
    const int samples = 400;
    for (int k = 0; k < samples; ++k) sum += cover::weather_systems(p, 37.0 * k).cyclone_count;
    // Genesis every lifetime / n hours: n alive at any moment, give or take the one whose
    // jittered genesis is due (so at most 2 (n + 1) = 32 = MAX_CYCLONES at the table's 15).
    INFO("n " << n << " mean alive " << sum / samples / 2);
    CHECK(std::abs(sum / samples / 2 - n) <= 0.5);
  }
  cover::CoverParameters none;
  none.cyclones = 0;
  CHECK(cover::weather_systems(none, 100.0).cyclone_count == 0);
}

TEST_CASE("a cyclone drifts east at its speed from one frame to the next, computed on its own", "[fast][systems]") {
  cover::CoverParameters p;
  const double t = 5000.0, dt = 6.0;
  const glsl::WeatherSystems a = cover::weather_systems(p, t), b = cover::weather_systems(p, t + dt);
  const double expected = cover::cyclone_speed_m_s * 3.6 * dt / earth_radius_km;  // radians along the track
  int matched = 0;
  for (int i = 0; i < a.cyclone_count; ++i) {
    // The same cyclone six hours on: the nearest centre of the later frame.
    double best = 1e9;
    int at = -1;
    for (int j = 0; j < b.cyclone_count; ++j)
      if (angle_between(a.cyclones[i].centre, b.cyclones[j].centre) < best)
        best = angle_between(a.cyclones[i].centre, b.cyclones[j].centre), at = j;
    if (at < 0 || best > 3 * expected) continue;  // died in between
    ++matched;
    // East at 12 m/s and poleward at 10 degrees a life: 259 km east, 56 km poleward.
    const double poleward = cover::cyclone_poleward_deg * M_PI / 180.0 * dt / cover::cyclone_lifetime_hours;
    CHECK(best == Approx(std::hypot(expected, poleward)).epsilon(0.02));
    CHECK(longitude_step(a.cyclones[i].centre, b.cyclones[at].centre) > 0.0);
  }
  CHECK(matched >= a.cyclone_count - 2);
  // Computed on its own: the same moment twice gives the same systems.
  const glsl::WeatherSystems again = cover::weather_systems(p, t);
  REQUIRE(again.cyclone_count == a.cyclone_count);
  for (int i = 0; i < a.cyclone_count; ++i) CHECK(again.cyclones[i].centre == a.cyclones[i].centre);
}

TEST_CASE("with --loop the cyclones repeat after the loop", "[fast][systems]") {
  cover::CoverParameters p;
  p.loop_hours = 240.0f;
  const glsl::WeatherSystems a = cover::weather_systems(p, 1000.0), b = cover::weather_systems(p, 1240.0);
  REQUIRE(a.cyclone_count == b.cyclone_count);
  for (int i = 0; i < a.cyclone_count; ++i) {
    CHECK(angle_between(a.cyclones[i].centre, b.cyclones[i].centre) < 1e-5);
    CHECK(a.cyclones[i].strength == Approx(b.cyclones[i].strength).margin(1e-6));
  }
}

TEST_CASE("a cyclone grows, winds up as it occludes and decays", "[fast][systems]") {
  CHECK(cover::cyclone_strength(0.0) == 0.0f);
  CHECK(cover::cyclone_strength(0.5) == 1.0f);
  CHECK(cover::cyclone_strength(1.0) == 0.0f);
  CHECK(cover::cyclone_wrap(0.0) == Approx(M_PI / 2));
  CHECK(cover::cyclone_wrap(1.0) == Approx(1.25 * M_PI));
  for (double a = 0.0; a < 1.0; a += 0.05) CHECK(cover::cyclone_wrap(a + 0.05) > cover::cyclone_wrap(a));
}

TEST_CASE("the ITCZ's clusters stay in its belt and follow the season", "[fast][systems]") {
  cover::CoverParameters p;
  const glsl::WeatherSystems annual = cover::weather_systems(p, 0.0);
  CHECK(annual.itcz_latitude == Approx(5.0 * M_PI / 180.0).margin(1e-6));
  p.month = 8;
  CHECK(cover::weather_systems(p, 0.0).itcz_latitude > annual.itcz_latitude);
  p.month = 2;
  CHECK(cover::weather_systems(p, 0.0).itcz_latitude < annual.itcz_latitude);
  // Along the ITCZ's line, a broken line: between a tenth and two thirds of it is in a cluster; 9
  // degrees off it (the belt's Gaussian below 2 %), none.
  const float line = annual.itcz_latitude;
  int inside = 0;
  const int n = 3600;
  for (int k = 0; k < n; ++k) {
    const float lon = 2.0f * float(M_PI) * k / n;
    const vec3 on(std::cos(line) * std::cos(lon), std::cos(line) * std::sin(lon), std::sin(line));
    if (glsl::itcz_clusters(on, line, line, annual.seed, 0.0f) > 0.5f) ++inside;
    const float off = line + 9.0f * float(M_PI) / 180.0f;
    const vec3 away(std::cos(off) * std::cos(lon), std::cos(off) * std::sin(lon), std::sin(off));
    CHECK(glsl::itcz_clusters(away, off, line, annual.seed, 0.0f) == 0.0f);
  }
  INFO("share of the line in clusters " << double(inside) / n);
  CHECK(inside > n / 10);
  CHECK(inside < 2 * n / 3);
  // The clusters' anvils: wider than the clusters (more of the line under them), none 9 degrees
  // off the line, and drawn out westward: of the line's stretches under an anvil but beside a
  // cluster, more lie west of their nearest cluster than east of it.
  std::vector<bool> cluster(n), anvil(n);
  int anvils = 0;
  for (int k = 0; k < n; ++k) {
    const float lon = 2.0f * float(M_PI) * k / n;
    const vec3 on(std::cos(line) * std::cos(lon), std::cos(line) * std::sin(lon), std::sin(line));
    cluster[k] = glsl::itcz_clusters(on, line, line, annual.seed, 0.0f) > 0.5f;
    anvil[k] = glsl::itcz_anvils(on, line, line, annual.seed, 0.0f) > 0.5f;
    anvils += anvil[k];
    const float off = line + 9.0f * float(M_PI) / 180.0f;
    const vec3 away(std::cos(off) * std::cos(lon), std::cos(off) * std::sin(lon), std::sin(off));
    CHECK(glsl::itcz_anvils(away, off, line, annual.seed, 0.0f) == 0.0f);
  }
  int west = 0, east = 0;
  for (int k = 0; k < n; ++k) {
    if (!anvil[k] || cluster[k]) continue;
    for (int step = 1; step < n / 36; ++step) {  // within 10 degrees
      if (cluster[(k + step) % n]) {             // the nearest cluster lies east: k is west of it
        ++west;
        break;
      }
      if (cluster[(k + n - step) % n]) {
        ++east;
        break;
      }
    }
  }
  INFO("share of the line under anvils " << double(anvils) / n << "; anvil beside a cluster: " << west << " west, "
                                         << east << " east");
  CHECK(anvils > inside);
  CHECK(west > east);
}

TEST_CASE("trade cumulus are many small separate clouds in the trades and none at the equator or the poles",
          "[fast][systems]") {
  const std::uint32_t seed = 12345u;
  // Along 18 degrees north: count the separate clouds (runs above 0.5) and their lengths.
  const float lat = 18.0f * float(M_PI) / 180.0f;
  const int n = 200000;
  int clouds = 0, run = 0, longest = 0;
  bool previous = false;
  for (int k = 0; k < n; ++k) {
    const float lon = 2.0f * float(M_PI) * k / n;
    const vec3 p(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat));
    const bool cloudy = glsl::trade_cumulus(p, lat, seed, 0.5f) > 0.5f;
    if (cloudy && !previous) ++clouds, run = 0;
    if (cloudy) longest = std::max(longest, ++run);
    previous = cloudy;
  }
  const double circle_km = 2 * M_PI * earth_radius_km * std::cos(lat);
  INFO("clouds " << clouds << ", longest " << longest * circle_km / n << " km");
  CHECK(clouds > 60);                      // many: one every few hundred km
  CHECK(longest * circle_km / n < 130.0);  // and small (120 km across at most)
  for (float at : {0.0f, 1.2f}) {
    const vec3 p(std::cos(at), 0.0f, std::sin(at));
    for (float edge : {-1.0f, 1.0f}) CHECK(glsl::trade_cumulus(p, at, seed, edge) == 0.0f);
  }
}

TEST_CASE("the moving flow's layer blend keeps the noise's mean and spread at every share", "[fast][systems]") {
  cover::CoverParameters p;
  const glsl::FbmParams older = cover::layer_density_params(p, 4, 0), younger = cover::layer_density_params(p, 5, 0);
  std::mt19937 rng(3);
  std::normal_distribution<float> g;
  std::vector<std::pair<float, float>> samples;
  for (int k = 0; k < 20000; ++k) {
    const vec3 n = glm::normalize(vec3(g(rng), g(rng), g(rng)));
    samples.push_back({glsl::cover_density(n, older), glsl::cover_density(n, younger)});
  }
  auto moments = [&](float share) {
    double sum = 0, sum2 = 0;
    for (const auto& [a, b] : samples) {
      const double v = glsl::noise_blend(a, b, share);
      sum += v, sum2 += v * v;
    }
    const double mean = sum / samples.size();
    return std::pair<double, double>(mean, std::sqrt(sum2 / samples.size() - mean * mean));
  };
  const auto [mean0, spread0] = moments(0.0f);
  // The documented constants describe the noise, to the seeds' differences: the lowest octave
  // has a few dozen cells on the sphere, whose mean varies by about 0.01 from seed to seed.
  CHECK(mean0 == Approx(glsl::NOISE_MEAN).epsilon(0.03));
  CHECK(spread0 == Approx(glsl::NOISE_SPREAD).epsilon(0.05));
  for (float share : {0.25f, 0.5f, 0.75f, 1.0f}) {
    const auto [mean, spread] = moments(share);
    INFO("share " << share << ": mean " << mean << ", spread " << spread << " against " << spread0);
    // The spread within 3 % (a linear blend would lose 29 % at 1/2), the mean within 1 %.
    CHECK(spread == Approx(spread0).epsilon(0.03));
    CHECK(mean == Approx(mean0).epsilon(0.01));
  }
}
