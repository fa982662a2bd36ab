// The weather systems' shapes (shaders/lib/weather_systems.glsl, on the CPU) and the host's
// schedule of cyclones (src/cover/weather_systems.cpp).
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <random>
#include <vector>

#include "cover/latitude_profile.hpp"
#include "cover/moving_flow.hpp"
#include "cover/surface_bias.hpp"
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

// The point of the ITCZ's meandering line (mean latitude `line`, its `waves`) at longitude
// `lon`; its latitude is taken at the mean line's point of that longitude (the meander depends on
// the longitude alone).
vec3 on_itcz_line(float line, float lon, const glsl::LineWaves& waves) {
  const vec3 mean(std::cos(line) * std::cos(lon), std::cos(line) * std::sin(lon), std::sin(line));
  const float lat = glsl::itcz_line_latitude(mean, line, waves);
  return vec3(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat));
}

// The ITCZ's systems and band at the unit direction p for air that has not moved (its origin is p).
vec2 itcz_here(vec3 p, float latitude, float line, const glsl::LineWaves& waves, std::uint32_t seed, float edge) {
  return glsl::itcz_systems(p, glsl::itcz_line_band(p, line, waves, edge, seed), latitude, line, waves, seed, edge);
}

// The same without the superclusters' band: the systems' own cloud (and anvils).
vec2 systems_alone(vec3 p, float latitude, float line, const glsl::LineWaves& waves, std::uint32_t seed) {
  return glsl::itcz_systems(p, 0.0f, latitude, line, waves, seed, 0.0f);
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

TEST_CASE("fronts reach the subtropics but not the deep tropics: all their cloud from 22 degrees, none within 12",
          "[fast][systems]") {
  const auto at = [](float latitude_deg) {
    const float lat = latitude_deg * float(M_PI) / 180.0f;
    return glsl::frontal_reach(vec3(std::cos(lat), 0.0f, std::sin(lat)));
  };
  for (float lat : {22.0f, 30.0f, 60.0f, -22.0f, -45.0f}) CHECK(at(lat) == 1.0f);
  for (float lat : {12.0f, 5.0f, 0.0f, -12.0f}) CHECK(at(lat) == 0.0f);
  float previous = 0.0f;
  for (int k = 0; k <= 100; ++k) {
    const float reach = at(12.0f + 0.1f * k);
    CHECK(reach >= previous);
    CHECK(at(-12.0f - 0.1f * k) == reach);
    previous = reach;
  }
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

namespace {

// The share of the mature cyclones (strength 1) of one hemisphere whose centre lies in
// 0-180 E, over `moments` moments 37 hours apart.
double mature_share_east(const cover::CoverParameters& p, bool north, int moments, int* count) {
  int east = 0;
  *count = 0;
  for (int k = 0; k < moments; ++k) {
    const glsl::WeatherSystems w = cover::weather_systems(p, 37.0 * k);
    for (int i = 0; i < w.cyclone_count; ++i) {
      const glsl::Cyclone& c = w.cyclones[i];
      if ((c.centre.z > 0.0f) != north || c.strength < 1.0f) continue;
      ++*count;
      east += c.centre.y > 0.0f;
    }
  }
  return double(east) / *count;
}

}  // namespace

TEST_CASE("with a land mask the cyclones mature over the ocean and without one at any longitude",
          "[fast][systems][surface]") {
  // A planet whose northern half is land west of Greenwich and ocean east of it; the south is ocean.
  cover::SurfaceMask mask{cover::surface_bias_columns, cover::surface_bias_rows, {}, "half"};
  for (int j = 0; j < mask.rows; ++j)
    for (int i = 0; i < mask.columns; ++i) mask.land.push_back(j < mask.rows / 2 && i < mask.columns / 2 ? 1.0f : 0.0f);
  // A track's mature life spans about 30 degrees of longitude (13-43 degrees east of its genesis
  // at 40 N), so the ocean's share of a track is 1 on 150 degrees of genesis longitudes, 0 on
  // 150 and a ramp between on each 30-degree coast (widened by the 5-degree core). Kept with
  // probability w, the mature centres lie over the ocean with E[w^2] / E[w] = 160 / 165 = 0.97
  // (eight refusals in a row: (1 - 165 / 360)^8 < 1 %).
  CHECK(cover::mature_ocean_share(mask, 40.0, 30.0) == 1.0);
  CHECK(cover::mature_ocean_share(mask, 40.0, -120.0) == 0.0);
  CHECK(cover::mature_ocean_share(mask, -40.0, -120.0) == 1.0);
  cover::CoverParameters p;
  int count = 0;
  const double bare_north = mature_share_east(p, true, 600, &count);
  INFO("no mask: " << bare_north << " of " << count << " in the east");
  // About 1500 mature cyclones, each counted in about 1.5 moments: a binomial of 0.5 spreads by
  // 0.016; 0.1 is six of that.
  CHECK(std::abs(bare_north - 0.5) < 0.1);
  p.surface = std::make_shared<const cover::SurfaceMask>(mask);
  const double masked_north = mature_share_east(p, true, 600, &count);
  INFO("mask: " << masked_north << " of " << count << " in the east (the ocean)");
  CHECK(masked_north > 0.9);
  // The south is all ocean: its cyclones are placed as without a mask.
  const double masked_south = mature_share_east(p, false, 600, &count);
  CHECK(std::abs(masked_south - 0.5) < 0.1);
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

namespace {

// A planet with one tropical continent: land from 0 to 60 E between 35 S and 35 N, ocean elsewhere.
std::shared_ptr<const cover::SurfaceMask> tropical_continent() {
  cover::SurfaceMask mask{cover::surface_bias_columns, cover::surface_bias_rows, {}, "continent"};
  for (int j = 0; j < mask.rows; ++j)
    for (int i = 0; i < mask.columns; ++i) {
      const double lat = 90.0 - (j + 0.5) * 180.0 / mask.rows, lon = -180.0 + (i + 0.5) * 360.0 / mask.columns;
      mask.land.push_back(std::abs(lat) < 35.0 && lon > 0.0 && lon < 60.0 ? 1.0f : 0.0f);
    }
  return std::make_shared<const cover::SurfaceMask>(mask);
}

// A planet of ocean alone: a map, so that the SPCZ is drawn, without monsoons.
std::shared_ptr<const cover::SurfaceMask> ocean_planet() {
  cover::SurfaceMask mask{cover::surface_bias_columns, cover::surface_bias_rows, {}, "ocean"};
  mask.land.assign(static_cast<size_t>(mask.rows) * mask.columns, 0.0f);
  return std::make_shared<const cover::SurfaceMask>(mask);
}

// The unit direction of (latitude, longitude), radians.
vec3 direction_of(double lat, double lon) {
  return vec3(float(std::cos(lat) * std::cos(lon)), float(std::cos(lat) * std::sin(lon)), float(std::sin(lat)));
}

// The monsoons' shift of the ITCZ's line at longitude `lon` (radians), radians of latitude.
double monsoon_shift(const glsl::WeatherSystems& w, double lon) {
  const vec3 at(std::cos(lon), std::sin(lon), 0.0f);
  return glsl::line_waves(at, w.itcz_waves).z / std::cos(w.itcz_latitude);
}

}  // namespace

TEST_CASE("over a tropical continent the ITCZ follows the sun further than over the ocean", "[fast][systems]") {
  const double degree = M_PI / 180.0;
  cover::CoverParameters p;
  // Without a land mask, no monsoons at all.
  for (int month : {0, 2, 8}) {
    p.month = month;
    const glsl::WeatherSystems bare = cover::weather_systems(p, 0.0);
    CHECK(bare.itcz_waves.monsoon_mean == 0.0f);
    CHECK(bare.itcz_waves.monsoon_reach == 0.0f);
    for (int k = 0; k < glsl::MONSOON_WAVES; ++k) CHECK(glm::length(bare.itcz_waves.monsoon[k]) == 0.0f);
  }
  p.surface = tropical_continent();
  // Over the continent's middle (30 E) the line moves to monsoon_land_deg into the summer
  // hemisphere, to the equator in the annual mean: every sample of the land's share there is land,
  // so the target is the whole step from the ocean's line. The waves (Lanczos-smoothed, 10 of them)
  // keep the plateau of a continent 6700 km wide within a degree, and over the far ocean (150 W to
  // 150 E) nothing within half a degree: the truncation does not ring there.
  struct Season {
    int month;
    double land_deg;
  };
  for (const Season s : {Season{8, 15.0}, Season{2, -15.0}, Season{0, 0.0}}) {
    p.month = s.month;
    const glsl::WeatherSystems w = cover::weather_systems(p, 0.0);
    const double ocean_deg = w.itcz_latitude / degree;
    INFO("month " << s.month << ": the ocean's line " << ocean_deg << " deg, over the continent "
                  << ocean_deg + monsoon_shift(w, 30.0 * degree) / degree);
    CHECK(cover::monsoon_target(*p.surface, s.month, w.itcz_latitude, 30.0 * degree) / degree ==
          Approx(s.land_deg - ocean_deg).margin(1e-9));
    CHECK(std::abs(ocean_deg + monsoon_shift(w, 30.0 * degree) / degree - s.land_deg) < 1.0);
    double largest = 0.0;
    for (int k = 0; k < 3600; ++k) {
      const double lon = 2.0 * M_PI * k / 3600;
      const double shift = monsoon_shift(w, lon);
      largest = std::max(largest, std::abs(shift));
      const double east = std::remainder(lon / degree, 360.0);
      if (east > 150.0 || east < -150.0) CHECK(std::abs(shift) < 0.5 * degree);
    }
    // The reach bounds the shift everywhere (the systems' searches rely on it).
    CHECK(largest <= w.itcz_waves.monsoon_reach);
    CHECK(w.itcz_waves.monsoon_reach < largest + 0.02);
  }
}

TEST_CASE("in August the ITCZ's systems over a continent lie north of the ocean's and in February far south",
          "[fast][systems]") {
  // The systems' cloud's mean latitude over the continent (20-40 E) against over the ocean (150 W
  // to 150 E), from a scan of latitudes: the line's shift there, 5 degrees north in August
  // (15 N against 10 N) and 15 south in February (15 S against the equator), within the
  // systems' scatter about their line (a presence 4 degrees wide, and few systems per band).
  const double degree = M_PI / 180.0;
  cover::CoverParameters p;
  p.surface = tropical_continent();
  p.spcz = 0.0f;  // an Earth's feature, and over this planet's ocean (150 W to 150 E) it would pull the mean south
  for (const auto& [month, shift_deg] : {std::pair{8, 5.0}, std::pair{2, -15.0}}) {
    p.month = month;
    const glsl::WeatherSystems w = cover::weather_systems(p, 0.0);
    const auto mean_latitude = [&](double from_deg, double to_deg) {
      double weight = 0.0, sum = 0.0;
      for (int i = 0; i < 40; ++i) {
        const double lon = (from_deg + (to_deg - from_deg) * (i + 0.5) / 40) * degree;
        for (int j = 0; j < 300; ++j) {
          const double lat = (-30.0 + 60.0 * (j + 0.5) / 300) * degree;
          const vec3 at(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat));
          const float cloud = itcz_here(at, float(lat), w.itcz_latitude, w.itcz_waves, w.seed, 0.0f).x;
          weight += cloud;
          sum += cloud * lat / degree;
        }
      }
      return sum / weight;
    };
    const double land = mean_latitude(20.0, 40.0), ocean = mean_latitude(150.0, 210.0);
    INFO("month " << month << ": the systems' mean latitude " << land << " over the continent, " << ocean
                  << " over the ocean");
    CHECK(std::abs(land - ocean - shift_deg) < 2.5);
  }
}

TEST_CASE("the SPCZ's line runs from the Solomon Islands past Samoa and Tonga to the Cook Islands and 25 S 120 W",
          "[fast][systems]") {
  const double degree = M_PI / 180.0;
  const auto line_deg = [&](double lon_deg) {
    return glsl::spcz_latitude(glsl::spcz_along(direction_of(0.0, lon_deg * degree)), 0.0f) / degree;
  };
  // Places on the zone (Vincent 1994; docs/climate.md, "The SPCZ"): Honiara (9.4 S, 160 E), midway
  // between Samoa (13.8 S, 172 W) and Tonga (21 S, 175 W), Rarotonga (21.2 S, 159.8 W), each within
  // 2 degrees (the band's half width 1.7 degrees, its systems' presence 4), and its end.
  INFO("the line at 160 E " << line_deg(160.0) << ", 173.5 W " << line_deg(-173.5) << ", 159.8 W " << line_deg(-159.8));
  CHECK(std::abs(line_deg(160.0) + 9.4) < 2.0);
  CHECK(std::abs(line_deg(-173.5) + 17.4) < 2.0);
  CHECK(std::abs(line_deg(-159.8) + 21.2) < 2.0);
  CHECK(line_deg(-120.0) == Approx(-25.0).margin(1e-4));
  // Along it: 0 at 150 E, 1 at 120 W, by longitude; held beyond its ends.
  CHECK(glsl::spcz_along(direction_of(-0.2, 150.0 * degree)) == Approx(0.0).margin(1e-6));
  CHECK(glsl::spcz_along(direction_of(-0.4, -120.0 * degree)) == Approx(1.0).margin(1e-6));
  CHECK(glsl::spcz_along(direction_of(0.0, 180.0 * degree)) == Approx(1.0 / 3.0).margin(1e-6));
  CHECK(line_deg(100.0) == Approx(-6.0).margin(1e-4));
  // Its extent: none west of 139 E (s -0.12) or east of 120 W, whole from 154.5 E to 156 W.
  CHECK(glsl::spcz_extent(-0.12f) == 0.0f);
  CHECK(glsl::spcz_extent(1.0f) == 0.0f);
  CHECK(glsl::spcz_extent(0.05f) == 1.0f);
  CHECK(glsl::spcz_extent(0.6f) == 1.0f);
  // Its strength: none without a map (its line is the Earth's); with one, --spcz times 1 in
  // February, 0.5 in August and 0.75 in the annual mean; its line 4.1 degrees north of the annual
  // one in August (the profile's shift at 15 S) and as far south in February.
  cover::CoverParameters p;
  p.month = 2;
  CHECK(cover::weather_systems(p, 0.0).itcz_waves.spcz == 0.0f);
  p.surface = ocean_planet();
  p.spcz = 0.8f;
  const glsl::WeatherSystems february = cover::weather_systems(p, 0.0);
  p.month = 8;
  const glsl::WeatherSystems august = cover::weather_systems(p, 0.0);
  p.month = 0;
  const glsl::WeatherSystems annual = cover::weather_systems(p, 0.0);
  CHECK(february.itcz_waves.spcz == Approx(0.8).margin(1e-6));
  CHECK(august.itcz_waves.spcz == Approx(0.8 * 0.5).margin(1e-6));
  CHECK(annual.itcz_waves.spcz == Approx(0.8 * 0.75).margin(1e-6));
  CHECK(annual.itcz_waves.spcz_shift == 0.0f);
  CHECK(august.itcz_waves.spcz_shift / degree == Approx(cover::seasonal_shift_deg(-15.0, 8)).margin(1e-5));
  CHECK(august.itcz_waves.spcz_shift / degree > 4.0);
  CHECK(february.itcz_waves.spcz_shift == Approx(-august.itcz_waves.spcz_shift).margin(1e-6));
}

TEST_CASE("along the SPCZ a band of deep cloud in February, none beyond its reach, and half as many systems in August",
          "[fast][systems]") {
  const double degree = M_PI / 180.0;
  cover::CoverParameters p;
  p.surface = ocean_planet();
  p.month = 2;
  const glsl::WeatherSystems w = cover::weather_systems(p, 0.0);
  const glsl::LineWaves& waves = w.itcz_waves;
  // On the meandering line over its whole extent (s 0.05 to 0.6, 155 E to 156 W), in band_profile's
  // flat middle: where the superclusters are active the band's deep cloud is SPCZ_LINE_DEPTH times
  // the strength (1 in February) and the systems' cloud at least 0.6 of it (itcz_beads), over 1/2;
  // outside them SPCZ_BAND_DORMANT of that, and 1/2 or less between the systems. Beyond its reach
  // south of the line, nothing (the ITCZ lies north of it).
  const int n = 1800;
  int active = 0, dormant = 0, deep_active = 0, banded_active = 0, banded_dormant = 0;
  for (int k = 0; k < n; ++k) {
    const float s = 0.05f + 0.55f * (k + 0.5f) / n;
    const double lon = glsl::SPCZ_LONGITUDES.x + s * (glsl::SPCZ_LONGITUDES.y - glsl::SPCZ_LONGITUDES.x);
    const vec3 sums = glsl::line_waves(direction_of(0.0, lon), waves);
    const double line = glsl::spcz_latitude(s, waves.spcz_shift) + glsl::ITCZ_MEANDER * glsl::line_meander(sums);
    const vec3 on = direction_of(line, lon);
    const float band = glsl::itcz_line_band(on, w.itcz_latitude, waves, 0.0f, w.seed);
    const float activity = glsl::supercluster_activity(sums);
    if (activity == 1.0f) {
      ++active;
      banded_active += band == Approx(glsl::SPCZ_LINE_DEPTH).margin(1e-3);
      deep_active += itcz_here(on, float(line), w.itcz_latitude, waves, w.seed, 0.0f).x > 0.5f;
    }
    if (activity == 0.0f) {
      ++dormant;
      banded_dormant += band == Approx(glsl::SPCZ_BAND_DORMANT * glsl::SPCZ_LINE_DEPTH).margin(1e-3);
    }
    const double off = line - glsl::SPCZ_REACH - glsl::ITCZ_MEANDER * glsl::LINE_MEANDER_LIMIT;
    const glsl::vec2 away = itcz_here(direction_of(off, lon), float(off), w.itcz_latitude, waves, w.seed, 0.0f);
    CHECK(away.x == 0.0f);
    CHECK(away.y == 0.0f);
  }
  INFO(active << " of " << n << " places in active superclusters, " << banded_active << " under the whole band and "
              << deep_active << " in deep cloud; " << dormant << " outside them, " << banded_dormant
              << " under half the band");
  CHECK(active > n / 10);
  CHECK(dormant > n / 10);
  CHECK(banded_active == active);
  CHECK(deep_active == active);
  CHECK(banded_dormant == dormant);
  // The systems' share of places over the South Pacific (130 E to 110 W, 45 S to 0), the SPCZ's
  // part of it (with the SPCZ less without): in August its strength is half February's, over a
  // line as long within the cosine of its latitude (8.2 degrees further north: 1.04 times longer),
  // so that the shares' ratio is 0.5 x 1.04, within the grid's sampling of the bump and the
  // overlap with the ITCZ's share near the warm pool (0.06).
  const auto spcz_share = [&](int month) {
    cover::CoverParameters q = p;
    q.month = month;
    const glsl::WeatherSystems with = cover::weather_systems(q, 0.0);
    q.spcz = 0.0f;
    const glsl::WeatherSystems without = cover::weather_systems(q, 0.0);
    const glsl::vec3 presence = glsl::itcz_presence(glsl::ITCZ_SYSTEMS_TABLE, with.itcz_latitude);
    double sum = 0.0;
    for (int i = 0; i < 240; ++i)
      for (int j = 0; j < 90; ++j) {
        const double lon = (130.0 + 120.0 * (i + 0.5) / 240) * degree, lat = -45.0 * (j + 0.5) / 90 * degree;
        const vec3 at = direction_of(lat, lon);
        sum += std::cos(lat) * (glsl::waved_presence(at, presence, with.itcz_waves, 0.0f) -
                                glsl::waved_presence(at, presence, without.itcz_waves, 0.0f));
      }
    return sum;
  };
  const double ratio = spcz_share(8) / spcz_share(2);
  INFO("August's SPCZ systems' share against February's " << ratio);
  CHECK(std::abs(ratio - 0.5 * std::cos(-17.0 * degree + 4.1 * degree) / std::cos(-17.0 * degree - 4.1 * degree)) <
        0.06);
}

TEST_CASE("the ITCZ's clusters stay in its belt and follow the season", "[fast][systems]") {
  cover::CoverParameters p;
  const glsl::WeatherSystems annual = cover::weather_systems(p, 0.0);
  CHECK(annual.itcz_latitude == Approx(5.0 * M_PI / 180.0).margin(1e-6));
  p.month = 8;
  CHECK(cover::weather_systems(p, 0.0).itcz_latitude > annual.itcz_latitude);
  p.month = 2;
  CHECK(cover::weather_systems(p, 0.0).itcz_latitude < annual.itcz_latitude);
  // Along the ITCZ's meandering line, a broken line: between a twentieth (the superclusters hold
  // most of the systems, and a third of the line lies outside them) and two thirds of it is in a
  // cluster (the systems' own cloud, without the superclusters' band); beyond the systems' reach
  // off its mean latitude, none.
  const float line = annual.itcz_latitude;
  int inside = 0;
  const int n = 3600;
  for (int k = 0; k < n; ++k) {
    const float lon = 2.0f * float(M_PI) * k / n;
    const vec3 on = on_itcz_line(line, lon, annual.itcz_waves);
    if (systems_alone(on, line, line, annual.itcz_waves, annual.seed).x > 0.5f) ++inside;
    const float off = line + (k % 2 ? 1.0f : -1.0f) * glsl::ITCZ_REACH;
    const vec3 away(std::cos(off) * std::cos(lon), std::cos(off) * std::sin(lon), std::sin(off));
    CHECK(itcz_here(away, off, line, annual.itcz_waves, annual.seed, 0.0f).x == 0.0f);
  }
  INFO("share of the line in clusters " << double(inside) / n);
  CHECK(inside > n / 20);
  CHECK(inside < 2 * n / 3);
  // Systems of many sizes along the line (its chords through them, 11 km a step): single towers
  // and small clusters under 150 km, mesoscale systems over 500 km, and more of the small than of
  // the large (equal areas per interval of size: the small ones are many).
  {
    const double step_km = 2.0 * M_PI * 6371.0 * std::cos(line) / n;
    std::vector<double> chords;
    int start = -1;
    for (int k = 0; k <= n; ++k) {
      const float lon = 2.0f * float(M_PI) * (k % n) / n;
      const vec3 on = on_itcz_line(line, lon, annual.itcz_waves);
      const bool cloudy = k < n && systems_alone(on, line, line, annual.itcz_waves, annual.seed).x > 0.5f;
      if (cloudy && start < 0) start = k;
      if (!cloudy && start >= 0) chords.push_back((k - start) * step_km), start = -1;
    }
    const auto count = [&](double from, double to) {
      return std::count_if(chords.begin(), chords.end(), [&](double c) { return c >= from && c < to; });
    };
    INFO(chords.size() << " systems on the line: " << count(0, 150) << " under 150 km, " << count(500, 1e9)
                       << " over 500 km");
    CHECK(count(0, 150) > 0);
    CHECK(count(500, 1e9) > 0);
    CHECK(count(0, 250) > count(500, 1e9));
  }
  // The clusters' anvils: wider than the clusters (more of the line under them), none beyond the
  // reach, and drawn out westward: of the line's stretches under an anvil but beside a
  // cluster, more lie west of their nearest cluster than east of it.
  // (The superclusters' band covers the line inside them: the anvils' side is counted outside.)
  const glsl::LineWaves& waves = annual.itcz_waves;
  std::vector<bool> cluster(n), anvil(n), banded(n);
  int anvils = 0;
  for (int k = 0; k < n; ++k) {
    const float lon = 2.0f * float(M_PI) * k / n;
    const vec3 on = on_itcz_line(line, lon, annual.itcz_waves);
    cluster[k] = itcz_here(on, line, line, annual.itcz_waves, annual.seed, 0.0f).x > 0.5f;
    anvil[k] = itcz_here(on, line, line, annual.itcz_waves, annual.seed, 0.0f).y > 0.5f;
    anvils += anvil[k];
    banded[k] = glsl::supercluster_activity(glsl::line_waves(on, waves)) > 0.0f;
    const float off = line + (k % 2 ? 1.0f : -1.0f) * glsl::ITCZ_REACH;
    const vec3 away(std::cos(off) * std::cos(lon), std::cos(off) * std::sin(lon), std::sin(off));
    CHECK(itcz_here(away, off, line, annual.itcz_waves, annual.seed, 0.0f).y == 0.0f);
  }
  int west = 0, east = 0;
  for (int k = 0; k < n; ++k) {
    if (!anvil[k] || cluster[k] || banded[k]) continue;
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

TEST_CASE("the ITCZ meanders by about 1.5 degrees and its systems gather in superclusters thousands of km long",
          "[fast][systems]") {
  cover::CoverParameters parameters;
  const float line = cover::weather_systems(parameters, 0.0).itcz_latitude;
  std::mt19937 random(3);
  std::uniform_real_distribution<double> hours(0.0, 1.0e5);
  const int n = 3600;
  const double circle_km = 2.0 * M_PI * earth_radius_km * std::cos(line);
  double active_runs_km = 0;
  int active_runs = 0;
  std::array<double, 2> clouds_in{}, points_in{};  // systems' cloud on the line: outside, inside superclusters
  int band_inside = 0, inside = 0, band_outside = 0, outside = 0;
  for (std::uint32_t cover_seed = 1; cover_seed <= 4; ++cover_seed) {
    parameters.seed = cover_seed;
    const glsl::WeatherSystems systems = cover::weather_systems(parameters, hours(random));
    const glsl::LineWaves& waves = systems.itcz_waves;
    const std::uint32_t seed = systems.seed;
    // The waves are orthogonal around a latitude circle (wavenumbers 6-10 sampled 3600 times): each
    // sum has mean 0 and root mean square 1 there to float rounding.
    glm::dvec2 sum(0.0), square(0.0);
    double meander_square = 0;
    std::vector<float> activity(n);
    for (int k = 0; k < n; ++k) {
      const float lon = 2.0f * float(M_PI) * k / n;
      const vec3 mean(std::cos(line) * std::cos(lon), std::cos(line) * std::sin(lon), std::sin(line));
      const vec3 sums = glsl::line_waves(mean, waves);
      const glm::dvec2 both(sums.x, sums.y);
      sum += both;
      square += both * both;
      const double meander = glsl::itcz_line_latitude(mean, line, waves) - line;
      meander_square += meander * meander;
      activity[k] = glsl::supercluster_activity(sums);
      // On the meandering line the presence is the bump's top: all places filled inside a
      // supercluster, ITCZ_DORMANT of them outside, a blend between.
      const vec3 on = on_itcz_line(line, lon, waves);
      const vec3 presence = glsl::convective_presence_of(line, 0.07f, 1.0f);
      CHECK(glsl::waved_presence(on, presence, waves, 0.0f) ==
            Approx(glm::mix(glsl::ITCZ_DORMANT, 1.0f, activity[k])).margin(2e-3));
      const vec2 cloud = itcz_here(on, glsl::itcz_line_latitude(mean, line, waves), line, waves, seed, 0.0f);
      if (activity[k] > 0.99f || activity[k] < 0.01f) {
        const bool in = activity[k] > 0.99f;
        clouds_in[in] += cloud.x > 0.5f;
        points_in[in] += 1;
        (in ? band_inside : band_outside) += cloud.y > 0.5f;
        (in ? inside : outside) += 1;
      }
    }
    INFO("seed " << cover_seed << ": sums' means " << sum.x / n << ", " << sum.y / n << ", root mean squares "
                 << std::sqrt(square.x / n) << ", " << std::sqrt(square.y / n));
    CHECK(std::abs(sum.x / n) < 1e-4);
    CHECK(std::abs(sum.y / n) < 1e-4);
    CHECK(std::sqrt(square.x / n) == Approx(1.0).margin(1e-4));
    CHECK(std::sqrt(square.y / n) == Approx(1.0).margin(1e-4));
    // The meander's root mean square is ITCZ_MEANDER, less the clamp's share beyond 2.5 (under 1 %).
    const double meander_rms = std::sqrt(meander_square / n);
    CHECK(meander_rms <= glsl::ITCZ_MEANDER * (1 + 1e-4));
    CHECK(meander_rms >= 0.97 * glsl::ITCZ_MEANDER);
    // The superclusters' stretches (activity over 1/2, a sum over -0.3).
    for (int k = 0, start = -1; k < 2 * n; ++k) {
      const bool on = activity[k % n] > 0.5f;
      if (on && start < 0 && k > 0 && activity[(k - 1) % n] <= 0.5f) start = k;
      if (!on && start >= 0) {
        if (start < n) active_runs_km += (k - start) * circle_km / n, ++active_runs;
        start = -1;
      }
    }
  }
  // Rice's formula: a Gaussian sum of waves 6-10 of equal power crosses a level u at a rate
  // sqrt(mean m^2) exp(-u^2 / 2) / pi a radian, sqrt(66) = 8.12: 15.5 times around at u = -0.3,
  // so 7.8 stretches above it, holding 0.618 of the circle of 39850 km: 3170 km each on average.
  const double mean_run_km = active_runs_km / active_runs;
  INFO(active_runs << " superclusters, " << mean_run_km << " km long on average");
  CHECK(mean_run_km > 2000);
  CHECK(mean_run_km < 4000);
  // The mesoscale systems fill every place inside a supercluster and a fifth outside, by the
  // activity at their points, up to a cell (800 km) from where the line is sampled, and the towers
  // half the places on the mean line wherever: more than twice as much of the line lies in a
  // system inside.
  const double share_in = clouds_in[1] / points_in[1], share_out = clouds_in[0] / points_in[0];
  INFO("share of the line in systems inside superclusters " << share_in << ", outside " << share_out);
  CHECK(share_in > 2 * share_out);
  // Inside, the band covers the whole line; outside only the anvils do.
  INFO("under the band or an anvil inside " << band_inside << " of " << inside << ", outside " << band_outside << " of "
                                            << outside);
  CHECK(band_inside == inside);
  CHECK(band_outside < outside / 2);
}

TEST_CASE("the ITCZ's band swells and narrows along the line and is deepest around its systems", "[fast][systems]") {
  // Across the line the band (band_profile) is 1/2 at 0.8 of its width, ITCZ_LINE_WIDTH times the
  // swelling in [0.35, 1.35]: inside the superclusters its half-width at 1/2 lies within 0.28 and
  // 1.08 of ITCZ_LINE_WIDTH (the edge's shift 0 here), and spreads over most of that range.
  cover::CoverParameters parameters;
  const float line = cover::weather_systems(parameters, 0.0).itcz_latitude;
  const int n = 3600;
  std::vector<double> widths;
  double worst_mismatch = 0;  // |half-width / width - 0.8 swelling|
  for (std::uint32_t cover_seed = 1; cover_seed <= 4; ++cover_seed) {
    parameters.seed = cover_seed;
    const glsl::WeatherSystems systems = cover::weather_systems(parameters, 1000.0 * cover_seed);
    const glsl::LineWaves& waves = systems.itcz_waves;
    for (int k = 0; k < n; ++k) {
      const float lon = 2.0f * float(M_PI) * k / n;
      const vec3 mean(std::cos(line) * std::cos(lon), std::cos(line) * std::sin(lon), std::sin(line));
      if (glsl::supercluster_activity(glsl::line_waves(mean, waves)) < 0.999f) continue;
      const float centre = glsl::itcz_line_latitude(mean, line, waves);
      // The band's extent north of the meandering line, where it is above 1/2, in steps of 1e-4 rad.
      double half_width = 0;
      for (int j = 0; j < 1000; ++j) {
        const float lat = centre + 1.0e-4f * j;
        const vec3 p(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat));
        if (glsl::itcz_line_band(p, line, waves, 0.0f, systems.seed) < 0.5f * glsl::ITCZ_LINE_DEPTH) break;
        half_width = 1.0e-4 * j;
      }
      widths.push_back(half_width / glsl::ITCZ_LINE_WIDTH);
      const float swell = glsl::itcz_swell(mean, systems.seed);
      worst_mismatch = std::max(worst_mismatch, std::abs(half_width / glsl::ITCZ_LINE_WIDTH - 0.8 * swell));
    }
  }
  std::sort(widths.begin(), widths.end());
  const double tenth = widths[widths.size() / 10], ninetieth = widths[widths.size() * 9 / 10];
  INFO(widths.size() << " longitudes inside superclusters: half-widths " << widths.front() << " to " << widths.back()
                     << " of the line's width, deciles " << tenth << " and " << ninetieth
                     << "; the largest mismatch with 0.8 of the swelling " << worst_mismatch);
  REQUIRE(widths.size() > 1000);
  // The band's offset is measured in the sine of the latitude over the mean line's cosine, which
  // differs from the meandering line's by tan(line) times its shift (the meander's and monsoons',
  // up to about 0.1 rad): 2 %, plus the scan's steps of 1e-4 rad (0.0023 of the width).
  CHECK(widths.front() >= 0.8 * 0.35 * 0.98 - 0.003);
  CHECK(widths.back() <= 0.8 * 1.35 * 1.02 + 0.003);
  CHECK(ninetieth > 1.4 * tenth);
  // The half-width is 0.8 of the swelling's width at the longitude, within the same: the swelling
  // is a function of the place along the line, the same at every latitude (its noise taken at the
  // equator), so the band's edge follows it without islands.
  CHECK(worst_mismatch <= 0.02 * 0.8 * 1.35 + 0.003);
  for (int k = 0; k < 360; ++k) {
    const float lon = float(M_PI) * k / 180.0f;
    const auto at = [&](float lat) {
      return vec3(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat));
    };
    CHECK(glsl::itcz_swell(at(0.3f), 5u) == Approx(glsl::itcz_swell(at(0.0f), 5u)).margin(1e-5));
    CHECK(glsl::itcz_swell(at(-0.2f), 5u) == Approx(glsl::itcz_swell(at(0.0f), 5u)).margin(1e-5));
  }
  // The band's depth: full within 1.2 radii of the nearest mesoscale system, ITCZ_BEAD_GAP of it
  // from 2.5 radii, falling in between.
  CHECK(glsl::itcz_beads(0.0f) == 1.0f);
  CHECK(glsl::itcz_beads(glsl::ITCZ_BEAD_REACH.x) == 1.0f);
  CHECK(glsl::itcz_beads(glsl::ITCZ_BEAD_REACH.y) == Approx(glsl::ITCZ_BEAD_GAP).margin(1e-6));
  CHECK(glsl::itcz_beads(1.0e30f) == Approx(glsl::ITCZ_BEAD_GAP).margin(1e-6));
  for (int k = 1; k < 40; ++k) CHECK(glsl::itcz_beads(0.1f * k) <= glsl::itcz_beads(0.1f * (k - 1)));
}

TEST_CASE("the ITCZ's meander moves west with the easterly waves and its superclusters east", "[fast][systems]") {
  // A day on, the meander found at a longitude lies 8 m/s x 86400 s = 691 km (6.2 degrees) further
  // west and the superclusters' envelope 1037 km (9.3 degrees) further east, to float rounding: the
  // waves of any moment follow from the seed and the time alone.
  cover::CoverParameters p;
  const glsl::WeatherSystems before = cover::weather_systems(p, 1000.0), after = cover::weather_systems(p, 1024.0);
  // (The speeds are the equator's: angular speeds v / R.)
  const double line = before.itcz_latitude, metres_per_radian = 6371.0e3;
  const double west = cover::itcz_meander_speed_m_s * 86400.0 / metres_per_radian,
               east = cover::supercluster_speed_m_s * 86400.0 / metres_per_radian;
  for (int k = 0; k < 360; ++k) {
    const double lon = 2.0 * M_PI * k / 360;
    const auto sums = [&](const glsl::WeatherSystems& w, double longitude) {
      const vec3 at(std::cos(line) * std::cos(longitude), std::cos(line) * std::sin(longitude), std::sin(line));
      return glsl::line_waves(at, w.itcz_waves);
    };
    CHECK(sums(after, lon + west).x == Approx(sums(before, lon).x).margin(1e-4));
    CHECK(sums(after, lon + east).y == Approx(sums(before, lon).y).margin(1e-4));
  }
}

TEST_CASE("as the ITCZ's waves move, its systems grow and fade instead of appearing whole", "[fast][systems]") {
  // Along the line over two days in steps of 10 minutes: a system that appeared whole would take
  // the points of its chord from beyond the cloud's reach (1.8 radii) to inside its core (below 1)
  // in one step (29 of the line's 720 points over these two days with a growth of 1e-6). Growing,
  // its radius rises by the share's change over SYSTEM_GROWTH a step, at most about 0.24 where the
  // envelope is steepest, so only points within that share of a radius of a new system's centre
  // can: at most a couple.
  cover::CoverParameters p;
  const float line = cover::weather_systems(p, 0.0).itcz_latitude;
  const int points = 720, steps = 288;
  std::vector<float> previous(points);
  int appeared = 0, grew = 0;
  for (int step = 0; step <= steps; ++step) {
    const glsl::WeatherSystems w = cover::weather_systems(p, 5000.0 + step / 6.0);
    for (int k = 0; k < points; ++k) {
      const float lon = 2.0f * float(M_PI) * k / points;
      const vec3 on = on_itcz_line(line, lon, w.itcz_waves);
      const float d = glsl::convective_distances(on, glsl::ITCZ_CELLS, w.seed, glsl::ITCZ_LAYER, glsl::ITCZ_RADII,
                                                 glsl::convective_presence_of(line, 0.07f, glsl::ITCZ_FILLED),
                                                 w.itcz_waves, glsl::NO_ANVIL, glsl::NEIGHBOUR_CELLS)
                          .x;
      if (step > 0 && previous[k] > 1.8f && d < 1.0f) ++appeared;
      if (step > 0 && previous[k] < 1.0f && d < 0.9f * previous[k]) ++grew;
      previous[k] = d;
    }
  }
  INFO(appeared << " points taken into a system's core from beyond its reach in one step, " << grew
                << " steps of a core growing by over a tenth");
  CHECK(appeared <= 2);
}

TEST_CASE("a convective system's search finds every system whose cloud reaches the point", "[fast][systems]") {
  // Against every lattice point of the 5 x 5 x 5 cells around the point's (all within 1.5 cells):
  // where the nearest system or anvil within the cloud's reach (1 + the noise's largest shift, 0.8
  // radii for the systems, 0.3 for the anvils) lies there, the search of 27 cells (the systems,
  // radii up to 0.5, and the towers, radii up to 0.27, with their anvils of up to 0.98 cells) finds
  // it at the same distance: no system or anvil is cut by the search.
  const std::uint32_t seed = 7u;
  const vec3 presence = glsl::convective_presence_of(0.1f, 0.07f, 1.0f);
  const glsl::LineWaves waves = glsl::line_waves_of(seed, 0.1f);
  std::mt19937 random(5);
  std::uniform_real_distribution<float> longitude(-3.14f, 3.14f), latitude(-0.1f, 0.3f);
  int reached = 0, anvils_reached = 0;
  for (int k = 0; k < 4000; ++k) {
    const float lat = latitude(random), lon = longitude(random);
    const vec3 p(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat));
    for (const bool towers : {false, true}) {
      const float frequency = towers ? glsl::ITCZ_TOWER_CELLS : glsl::ITCZ_CELLS;
      const vec2 radii = towers ? glsl::ITCZ_TOWER_RADII : glsl::ITCZ_RADII;
      const vec3 anvil = towers ? glsl::TOWER_ANVIL : glsl::SYSTEM_ANVIL;
      const vec2 found = glsl::convective_distances(p, frequency, seed, glsl::ITCZ_LAYER, radii, presence, waves, anvil,
                                                    glsl::NEIGHBOUR_CELLS);
      const vec3 scaled = p * frequency, base = glm::floor(scaled);
      const glsl::ivec3 cell(base);
      const glsl::uvec3 key = glsl::noise_key(seed, glsl::ITCZ_LAYER),
                        size_key = glsl::noise_key(seed, glsl::ITCZ_LAYER + 1u);
      vec2 all(1.0e30f);
      for (int z = -2; z <= 2; ++z)
        for (int y = -2; y <= 2; ++y)
          for (int x = -2; x <= 2; ++x) {
            const glsl::ivec3 offset(x, y, z);
            const vec3 feature = glsl::wrapped_feature_offset(cell + offset, key);
            const vec3 to_point = vec3(offset) + feature - (scaled - base);
            const vec3 h = glsl::hash_to_unit3(glsl::pcg3d(glsl::uvec3(cell + offset) ^ size_key));
            // The presence at the system's point, the direction of its lattice position.
            const float here =
                glsl::waved_presence(glm::normalize(vec3(cell + offset) + feature), presence, waves, h.y);
            if (h.y >= here) continue;
            const float r = glsl::equal_area_radius(h.x, radii.x, radii.y) * glsl::system_growth(here - h.y, waves);
            all.x = std::min(all.x, glm::length(to_point) / r);
            const vec3 east = glsl::local_east(p);
            const float along = -glm::dot(to_point, east);
            const vec3 across = -to_point - along * east;
            const float lagged = (along + anvil.z * r) / anvil.y;
            all.y = std::min(all.y, std::sqrt(lagged * lagged + glm::dot(across, across)) / (anvil.x * r));
          }
      if (all.x < 1.0f + glsl::CORE_EDGE_REACH) {
        ++reached;
        CHECK(found.x == all.x);
      }
      if (all.y < 1.0f + glsl::ANVIL_EDGE_REACH) {
        ++anvils_reached;
        CHECK(found.y == all.y);
      }
    }
  }
  INFO("points a system's cloud can reach: " << reached << ", an anvil's: " << anvils_reached);
  CHECK(reached > 400);
  CHECK(anvils_reached > 400);
}

TEST_CASE("the ITCZ's cell tables hold each cell a search from the sphere reaches once", "[fast][systems]") {
  // Every entry names a cell of its table whose index is the entry (a bijection of the tables'
  // entries onto their cells), and every cell that a 27-cell search from a unit vector reaches
  // has an entry: the lattice positions of the sphere lie within [-n, n] per axis for n cells
  // per radius.
  for (int index = 0; index < glsl::ITCZ_TABLE_CELLS; ++index) {
    const glsl::ivec4 cell = glsl::itcz_table_cell(index);
    REQUIRE(cell.w + glsl::convective_table_index(glsl::itcz_lattice_cells(cell.w), glsl::ivec3(cell)) == index);
  }
  for (const int table : {glsl::ITCZ_SYSTEMS_TABLE, glsl::ITCZ_TOWERS_TABLE}) {
    const float n = glsl::itcz_lattice_cells(table);
    const int side = glsl::convective_table_side(n), cells = side * side * side;
    CHECK(side == 2 * int(n) + 3);
    CHECK(table + cells == (table == glsl::ITCZ_SYSTEMS_TABLE ? glsl::ITCZ_TOWERS_TABLE : glsl::ITCZ_TABLE_CELLS));
    // The extreme cells: a point at +1 (its cell n, its neighbour n + 1) and at -1 (cell -n, -n - 1).
    CHECK(glsl::convective_table_index(n, glsl::ivec3(int(n) + 1)) == cells - 1);
    CHECK(glsl::convective_table_index(n, glsl::ivec3(-int(n) - 1)) == 0);
  }
  // And from random unit vectors, each neighbour's entry lies in its own table.
  std::mt19937 random(3);
  std::normal_distribution<float> normal;
  for (int k = 0; k < 20000; ++k) {
    const vec3 p = glm::normalize(vec3(normal(random), normal(random), normal(random)));
    for (const int table : {glsl::ITCZ_SYSTEMS_TABLE, glsl::ITCZ_TOWERS_TABLE}) {
      const float n = glsl::itcz_lattice_cells(table);
      const glsl::ivec3 cell(glm::floor(p * n));
      const int side = glsl::convective_table_side(n);
      for (int c = 0; c < glsl::NEIGHBOUR_CELLS; ++c) {
        const int index = glsl::convective_table_index(n, cell + glsl::neighbour_offset(c));
        REQUIRE(index >= 0);
        REQUIRE(index < side * side * side);
      }
    }
  }
}

TEST_CASE("convective systems' radii cover equal areas in each logarithmic interval of size", "[fast][systems]") {
  // The radii of uniform hashes (midpoints of 100000 equal steps) between 0.2 and 0.55: the area
  // sum_r r^2 below the range's geometric mean equals the sum above it, as an r^-3 density gives
  // (each half of ln r carries half the area); the midpoint rule's error is of order 1e-10.
  const float r_min = 0.2f, r_max = 0.55f, middle = std::sqrt(r_min * r_max);
  double below = 0, above = 0;
  const int n = 100000;
  for (int k = 0; k < n; ++k) {
    const float r = glsl::equal_area_radius((k + 0.5f) / n, r_min, r_max);
    REQUIRE(r >= r_min * (1 - 1e-6f));
    REQUIRE(r <= r_max * (1 + 1e-6f));
    (r < middle ? below : above) += double(r) * r;
  }
  INFO("area below the geometric mean " << below << ", above " << above);
  CHECK(below == Approx(above).epsilon(1e-3));
  // The extremes: u = 0 gives r_min, u -> 1 gives r_max.
  CHECK(glsl::equal_area_radius(0.0f, r_min, r_max) == Approx(r_min).epsilon(1e-6));
  CHECK(glsl::equal_area_radius(1.0f, r_min, r_max) == Approx(r_max).epsilon(1e-5));
}

namespace {

// The unit direction at geocentric latitude and longitude (radians).
vec3 direction_at(double latitude, double longitude) {
  return vec3(std::cos(latitude) * std::cos(longitude), std::cos(latitude) * std::sin(longitude), std::sin(latitude));
}

// The runs of a pattern above 1/2 along a great or small circle sampled at n points: the cloudy
// runs' and the clear gaps' lengths in km (the runs cut by the circle's start left out).
struct Runs {
  std::vector<double> clouds, gaps;
};
template <typename Pattern, typename Along>
void add_runs(Runs& runs, Pattern pattern, Along along, double circle_km, int n) {
  bool previous = pattern(along(0.0)) > 0.5f, first = true;
  int run = 1;
  for (int k = 1; k < n; ++k) {
    const bool cloudy = pattern(along(2.0 * M_PI * k / n)) > 0.5f;
    if (cloudy == previous) {
      ++run;
      continue;
    }
    if (!first) (previous ? runs.clouds : runs.gaps).push_back(run * circle_km / n);
    first = false;
    previous = cloudy;
    run = 1;
  }
}
double median_of(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}
double mean_of(const std::vector<double>& v) {
  double sum = 0;
  for (double x : v) sum += x;
  return v.empty() ? 0.0 : sum / double(v.size());
}

}  // namespace

TEST_CASE("gravel is many small separate clumps, and the trades' cumulus none at the equator or the poles",
          "[fast][systems]") {
  const std::uint32_t seed = 12345u;
  // Along 18 degrees north: count the separate clumps (runs above 0.5) and their lengths.
  const double lat = 18.0 * M_PI / 180.0;
  Runs runs;
  add_runs(
      runs, [&](vec3 p) { return glsl::gravel_clumps(p, seed, 0.5f, 0.0f, glsl::NEAR_CELLS); },
      [&](double lon) { return direction_at(lat, lon); }, 2 * M_PI * earth_radius_km * std::cos(lat), 200000);
  // A clump's disc is at most 2 x 0.45 cells of 106 km across, 1.15 times that with the edge
  // here (0.3 x 0.5 of a radius): 110 km; two overlapping ones 220 km.
  const double longest = *std::max_element(runs.clouds.begin(), runs.clouds.end());
  // How many a circle crosses: a line through balls placed at random, n a unit volume, meets
  // n pi E[r_h^2] of them a unit length, r_h the radius where the cloud is 1/2: here, with the
  // edge moving the outline out by 0.15 and the rim's smoothstep halfway at 1 - GRAVEL_RIM / 2,
  // r_h = (1.15 - GRAVEL_RIM / 2) r. The radii, of density r^-3 on [0.2, 0.38] cells, have
  // E[r^2] = ln(0.38 / 0.2) / ((0.2^-2 - 0.38^-2) / 2) = 0.0710 cells^2; n is 0.9 a cell; the
  // circle 2 pi cos(18 deg) x 60 cells long. Overlapping clumps count once, so somewhat fewer.
  const double half_radius = 1.15 - 0.5 * glsl::GRAVEL_RIM;
  const double expected = 0.9 * M_PI * half_radius * half_radius * 0.0710 * 2 * M_PI * std::cos(lat) * 60.0;
  INFO("clumps " << runs.clouds.size() << " (expected " << expected << "), median " << median_of(runs.clouds)
                 << " km, longest " << longest << " km");
  CHECK(runs.clouds.size() > 0.75 * expected);
  CHECK(runs.clouds.size() < 1.1 * expected);
  CHECK(runs.clouds.size() > 36);         // many: one every 1000 km or less
  CHECK(median_of(runs.clouds) < 110.0);  // and small
  CHECK(longest < 220.0);
  for (float at : {0.0f, 1.2f}) {
    const vec3 p(std::cos(at), 0.0f, std::sin(at));
    for (float edge : {-1.0f, 1.0f})
      CHECK(glsl::trade_cumulus(p, at, seed, edge, glsl::trade_regimes(p, seed, 2), 0.0f) == 0.0f);
  }
}

TEST_CASE("the trades' four patterns each hold about a quarter of the trades and their weights sum to one",
          "[fast][systems]") {
  // Each pattern is a quadrant of two independent Perlin fields split at their median 0 (the noise
  // is symmetric), so each holds a quarter in expectation. The fields' regions are about a fifth of
  // a radius across, some 300 of them in the trades' belt: a pattern's share of one seed's belt
  // spreads by about sqrt(0.25 x 0.75 / 300) x 2 (neighbouring points correlate) = 0.05, and the
  // mean of eight seeds by 0.018; 0.06 is over three of those.
  double share[4] = {0, 0, 0, 0};
  int blended = 0, n = 0;
  for (std::uint32_t seed = 1; seed <= 8; ++seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    for (int k = 0; k < 4000; ++k, ++n) {
      const vec3 p = direction_at(std::asin(uniform(rng) - 0.5), 2 * M_PI * uniform(rng));  // within 30 degrees
      const glsl::vec4 w = glsl::trade_regimes(p, seed, 2);
      for (int i = 0; i < 4; ++i) {
        REQUIRE(w[i] >= 0.0f);
        share[i] += w[i];
      }
      REQUIRE(w.x + w.y + w.z + w.w == Approx(1.0f).margin(1e-6));
      const float latitude = std::asin(p.z), belt = glsl::trade_cumulus_belt(latitude);
      CHECK(glsl::organised_trades(w, latitude, 1.0f) == Approx(belt * (1.0f - w.x)).margin(1e-6));
      CHECK(glsl::organised_trades(w, latitude, 0.5f) == Approx(0.5f * belt * (1.0f - w.x)).margin(1e-6));
      CHECK(glsl::organised_trades(w, latitude, 0.0f) == 0.0f);
      if (std::max(std::max(w.x, w.y), std::max(w.z, w.w)) < 0.9f) ++blended;
    }
  }
  for (int i = 0; i < 4; ++i) {
    INFO("pattern " << i << " share " << share[i] / n);
    CHECK(std::abs(share[i] / n - 0.25) < 0.06);
  }
  // The patterns hold regions, with blends between them: about a fifth of the points (the fields'
  // values within the blend of 0 for either field: 2 x 0.06 / (0.27 sqrt(2 pi)) = 0.18 each).
  INFO("blended " << double(blended) / n);
  CHECK(double(blended) / n > 0.1);
  CHECK(double(blended) / n < 0.35);
}

TEST_CASE("flowers are bouquets well apart and fish are bands far longer than wide", "[fast][systems]") {
  Runs flowers_east, fish_east, fish_north;
  for (std::uint32_t seed = 1; seed <= 4; ++seed) {
    const auto flower = [&](vec3 p) { return glsl::flower_clumps(p, seed, 0.0f, 0.0f, glsl::NEIGHBOUR_CELLS).x; };
    const auto fish = [&](vec3 p) { return glsl::fish_clumps(p, seed, 0.0f, 0.0f, glsl::NEAR_CELLS); };
    for (double degrees : {12.0, 18.0, 24.0}) {
      const double lat = degrees * M_PI / 180.0, circle = 2 * M_PI * earth_radius_km * std::cos(lat);
      const auto east = [&](double lon) { return direction_at(lat, lon); };
      add_runs(flowers_east, flower, east, circle, 100000);
      add_runs(fish_east, fish, east, circle, 100000);
    }
    // Along meridians, within 30 degrees of the equator.
    for (double lon : {0.3, 1.9, 3.5, 5.0}) {
      const auto north = [&](double t) { return direction_at(t, lon); };
      add_runs(
          fish_north, [&](vec3 p) { return std::abs(p.z) < 0.5f ? fish(p) : 0.0f; }, north, 2 * M_PI * earth_radius_km,
          100000);
    }
  }
  // Flowers' outlines: discs on the sphere (surface_disc_clouds), n = 2 x FLOWER_SHELL of them a cell^2 of
  // 228 km (FLOWER_CELLS a radius) with radii of density r^-3 on FLOWER_RADII, above a half out to
  // r_h = (1 - FLOWER_RIM / 2) r (rimmed_cloud), lobed by the warp. A line enters n E[2 r_h] of them
  // a cell of its length, fewer where discs overlap and more where a lobe splits one, and the
  // discs cover x = n pi E[r_h^2] of it where none overlap, 1 - exp(-x) where their centres fall
  // independently (one feature point a cell lies between the two). A disc crossed at an offset
  // uniform in [0, r_h] has the median chord 1.73 r_h; overlaps only lengthen chords, so their
  // median lies above the smallest disc's. And the sea between them is clear for more than the
  // smallest bouquet's width (Stevens et al. 2020: 50-200 km across, well apart).
  const double flower_cell_km = earth_radius_km / glsl::FLOWER_CELLS;
  const double a = glsl::FLOWER_RADII.x, b = glsl::FLOWER_RADII.y, half = 1.0 - 0.5 * glsl::FLOWER_RIM;
  const double norm = 0.5 * (1.0 / (a * a) - 1.0 / (b * b));  // the integral of r^-3 over the radii
  const double mean_r = (1.0 / a - 1.0 / b) / norm, mean_r2 = std::log(b / a) / norm;
  const double n = 2.0 * glsl::FLOWER_SHELL;
  const double rate = n * 2.0 * half * mean_r / flower_cell_km;  // discs entered a km
  const double x = n * M_PI * half * half * mean_r2;
  double cloudy_km = 0.0, clear_km = 0.0;
  for (double c : flowers_east.clouds) cloudy_km += c;
  for (double g : flowers_east.gaps) clear_km += g;
  const double share = cloudy_km / (cloudy_km + clear_km);
  const double entered = double(flowers_east.clouds.size()) / (cloudy_km + clear_km);
  INFO("flowers " << flowers_east.clouds.size() << ": median " << median_of(flowers_east.clouds) << " km, median gap "
                  << median_of(flowers_east.gaps) << " km, share " << share << " (" << 1.0 - std::exp(-x) << " to " << x
                  << "), entered " << entered * 1000.0 << " per 1000 km (" << rate * 1000.0 << ")");
  CHECK(flowers_east.clouds.size() > 500);
  CHECK(std::abs(entered / rate - 1.0) < 0.15);
  CHECK(share > 0.9 * (1.0 - std::exp(-x)));
  CHECK(share < 1.1 * x);
  CHECK(median_of(flowers_east.clouds) > 1.73 * half * a * flower_cell_km);
  CHECK(median_of(flowers_east.clouds) < 2 * half * b * flower_cell_km);
  CHECK(median_of(flowers_east.gaps) > 2 * a * flower_cell_km);
  // Fish: the lattice stretched fourfold north-south draws the clumps out east-west; the warp
  // bends them, so that chords along the wind are at least twice those across it on average, and
  // the longest reach 600 km and more.
  const double fish_max = *std::max_element(fish_east.clouds.begin(), fish_east.clouds.end());
  INFO("fish along the wind: mean " << mean_of(fish_east.clouds) << " km, longest " << fish_max << " km; across: mean "
                                    << mean_of(fish_north.clouds) << " km");
  CHECK(fish_east.clouds.size() > 40);
  CHECK(fish_north.clouds.size() > 40);
  CHECK(mean_of(fish_east.clouds) > 2.0 * mean_of(fish_north.clouds));
  CHECK(fish_max > 600.0);
}

namespace {

// The widths in km over which a pattern rises from 0.1 to 0.9 into its clumps along a circle
// sampled at n points (rises that reach 0.9; their last sample at or below 0.1 to their first at or
// above 0.9).
template <typename Pattern, typename Along>
std::vector<double> rise_widths(Pattern pattern, Along along, double circle_km, int n) {
  std::vector<double> widths;
  int last_low = -1;
  bool inside = false;
  for (int k = 0; k < n; ++k) {
    const float v = pattern(along(2.0 * M_PI * k / n));
    if (v <= 0.1f) {
      last_low = k;
      inside = false;
    } else if (v >= 0.9f && !inside) {
      inside = true;
      if (last_low >= 0) widths.push_back((k - last_low) * circle_km / n);
    }
  }
  return widths;
}

}  // namespace

TEST_CASE("gravel's and fish's clumps fade over their rims and flowers end sharply", "[fast][systems]") {
  // Soft where the cloud is thin, sharp where thick (issue 30): gravel's broken shallow cumulus
  // thin out over the outer GRAVEL_RIM of a clump, fish over FISH_RIM, while flowers' stratiform
  // sheets end within FLOWER_RIM. A smoothstep rises from 0.1 to 0.9 over 0.61 of its span, and a
  // circle crossing a disc obliquely or off its centre (the sphere cuts the lattice's 3D discs)
  // only widens it, so gravel's rises (radii from 0.2 cells of 106 km) are at least
  // 0.61 x 0.7 x 0.2 x 106 = 9.0 km, more than a 1024 cover's texels at the faces' corners, while a
  // flower's radial rise is at most 0.61 x 0.15 x 0.38 x 228 = 7.9 km (cells of 228 km, FLOWER_CELLS
  // a radius; the warp stretches it by up to about a half), under a texel of a 1024 cover.
  std::vector<double> gravel, flowers;
  for (std::uint32_t seed = 1; seed <= 3; ++seed) {
    for (double degrees : {12.0, 18.0, 24.0}) {
      const double lat = degrees * M_PI / 180.0, circle = 2 * M_PI * earth_radius_km * std::cos(lat);
      const auto east = [&](double lon) { return direction_at(lat, lon); };
      const auto g = rise_widths([&](vec3 p) { return glsl::gravel_clumps(p, seed, 0.0f, 0.0f, glsl::NEAR_CELLS); },
                                 east, circle, 200000);
      const auto f =
          rise_widths([&](vec3 p) { return glsl::flower_clumps(p, seed, 0.0f, 0.0f, glsl::NEIGHBOUR_CELLS).x; }, east,
                      circle, 200000);
      gravel.insert(gravel.end(), g.begin(), g.end());
      flowers.insert(flowers.end(), f.begin(), f.end());
    }
  }
  const double step_km = 2 * M_PI * earth_radius_km / 200000;  // the samples' spacing, at most
  const double gravel_least = *std::min_element(gravel.begin(), gravel.end());
  INFO("gravel rises " << gravel.size() << ": median " << median_of(gravel) << " km, least " << gravel_least
                       << " km; flowers " << flowers.size() << ": median " << median_of(flowers) << " km");
  REQUIRE(gravel.size() > 100);
  REQUIRE(flowers.size() > 100);
  CHECK(gravel_least >= 0.61 * glsl::GRAVEL_RIM * 0.2 * 106.0 - 2 * step_km);
  CHECK(median_of(flowers) <= 1.5 * 0.61 * glsl::FLOWER_RIM * 0.38 * earth_radius_km / glsl::FLOWER_CELLS);
  // The rims' widths in km at the lattices' mean radii, gravel's 0.29 cells of 106 km against the
  // flowers' 0.3 cells: 2.1 times the flowers' (which the warp widens by up to a half).
  const double rim_ratio =
      (glsl::GRAVEL_RIM * 0.29 * 106.0) / (glsl::FLOWER_RIM * 0.3 * earth_radius_km / glsl::FLOWER_CELLS);
  CHECK(median_of(gravel) > rim_ratio / 1.5 * median_of(flowers));
  // The rims' profile: full inside 1 - rim, none beyond 1, halfway at 1 - rim / 2 (a smoothstep).
  for (float rim : {glsl::GRAVEL_RIM, glsl::FISH_RIM, glsl::FLOWER_RIM}) {
    CHECK(glsl::rimmed_cloud(1.0f - rim, 0.0f, 0.3f, rim) == 1.0f);
    CHECK(glsl::rimmed_cloud(1.0f, 0.0f, 0.3f, rim) == 0.0f);
    CHECK(glsl::rimmed_cloud(1.0f - 0.5f * rim, 0.0f, 0.3f, rim) == Approx(0.5f).margin(1e-6));
  }
  CHECK(glsl::FLOWER_RIM < glsl::FISH_RIM);
  CHECK(glsl::FISH_RIM < glsl::GRAVEL_RIM);
}

TEST_CASE("a trade clump's rim is never narrower than the cover's texel and its own where texels are finer",
          "[fast][systems]") {
  // resolved_rim: a texel of 2 / size radians is texel_arc x 28 / r of a flower's radius of r cells
  // (FLOWER_CELLS = 28 a radius): for the lattice's mean 0.3 cells 0.36 at 512 per face, 0.18 at
  // 1024, 0.046 at 4096 (under the flowers' own 0.15, which then holds), the whole radius from 128;
  // for the smallest bouquet (0.22) 0.50 at 512 and the largest (0.38) 0.29: one texel in km
  // whatever the bouquet's size.
  const vec2 radii = glsl::FLOWER_RADII;
  const float cells = glsl::FLOWER_CELLS;
  CHECK(glsl::resolved_rim(glsl::FLOWER_RIM, cells, 0.3f, 0.0f) == glsl::FLOWER_RIM);
  CHECK(glsl::resolved_rim(glsl::FLOWER_RIM, cells, 0.3f, 2.0f / 4096) == glsl::FLOWER_RIM);
  CHECK(glsl::resolved_rim(glsl::FLOWER_RIM, cells, 0.3f, 2.0f / 512) == Approx(2.0 / 512 * cells / 0.3).epsilon(1e-5));
  CHECK(glsl::resolved_rim(glsl::FLOWER_RIM, cells, 0.3f, 2.0f / 1024) ==
        Approx(2.0 / 1024 * cells / 0.3).epsilon(1e-5));
  CHECK(glsl::resolved_rim(glsl::FLOWER_RIM, cells, 0.3f, 2.0f / 128) == 1.0f);
  for (float radius : {radii.x, radii.y})
    CHECK(glsl::resolved_rim(glsl::FLOWER_RIM, cells, radius, 2.0f / 512) * radius / cells ==
          Approx(2.0 / 512).epsilon(1e-5));
  CHECK(glsl::resolved_rim(glsl::GRAVEL_RIM, 60.0f, 0.29f, 2.0f / 1024) == glsl::GRAVEL_RIM);
  // Drawn at 512 per face, each flower rises from 0.1 to 0.9 over 0.61 (a smoothstep's middle) of
  // its rim, a texel of 25 km whatever its radius (15 km), where their own rims rise within 7.9 km
  // (the test above); the outlines' warp squeezes that by at most 1 + 0.006 x 80 x 3.5 (its amount
  // and cells, flower_clumps, times the Perlin noise's steepest slope, 3.29 in 2e7 samples) = 2.68,
  // to 5.7 km, and most rises are wider than 0.61 texels.
  const double texel_km = 2.0 / 512 * earth_radius_km;
  std::vector<double> coarse;
  for (std::uint32_t seed = 1; seed <= 3; ++seed) {
    for (double degrees : {12.0, 18.0, 24.0}) {
      const double lat = degrees * M_PI / 180.0, circle = 2 * M_PI * earth_radius_km * std::cos(lat);
      const auto east = [&](double lon) { return direction_at(lat, lon); };
      const auto f =
          rise_widths([&](vec3 p) { return glsl::flower_clumps(p, seed, 0.0f, 2.0f / 512, glsl::NEIGHBOUR_CELLS).x; },
                      east, circle, 200000);
      coarse.insert(coarse.end(), f.begin(), f.end());
    }
  }
  const double step_km = 2 * M_PI * earth_radius_km / 200000;
  const double least = *std::min_element(coarse.begin(), coarse.end());
  INFO("flowers at 512: " << coarse.size() << " rises, median " << median_of(coarse) << " km, least " << least
                          << " km");
  REQUIRE(coarse.size() > 100);
  CHECK(least >= 0.61 * texel_km / (1.0 + 0.006 * 80 * 3.5) - 2 * step_km);
  CHECK(median_of(coarse) > 0.61 * texel_km);
}

TEST_CASE(
    "the 8 nearest cells hold every feature point within half a cell, and every gravel and fish clump the 27 find",
    "[fast][systems]") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> uniform(-30.0f, 30.0f);
  const glsl::uvec3 key = glsl::noise_key(3u, 13u);
  int near = 0;
  for (int k = 0; k < 20000; ++k) {
    const vec3 p(uniform(rng), uniform(rng), uniform(rng));
    const vec3 base = glm::floor(p), f = p - base;
    const glsl::ivec3 cell(base);
    float all = 1e30f, nearest8 = 1e30f;
    for (int i = 0; i < glsl::NEIGHBOUR_CELLS; ++i) {
      const glsl::ivec3 o = glsl::neighbour_offset(i);
      all = std::min(all, glm::length(vec3(o) + glsl::wrapped_feature_offset(cell + o, key) - f));
    }
    for (int i = 0; i < glsl::NEAR_CELLS; ++i) {
      const glsl::ivec3 o = glsl::near_offset(i, f);
      nearest8 = std::min(nearest8, glm::length(vec3(o) + glsl::wrapped_feature_offset(cell + o, key) - f));
    }
    if (all <= 0.5f) {
      ++near;
      REQUIRE(nearest8 == all);
    }
  }
  CHECK(near > 1000);  // the check saw many points with a feature that near
  // The clumps reach at most 0.38 x 1.3 = 0.494 cells: the same values from either search.
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  for (int k = 0; k < 4000; ++k) {
    const vec3 p = glm::normalize(vec3(unit(rng), unit(rng), 0.5f * unit(rng)));
    const float edge = unit(rng);
    for (std::uint32_t seed : {1u, 2u}) {
      REQUIRE(glsl::gravel_clumps(p, seed, edge, 0.0f, glsl::NEAR_CELLS) ==
              glsl::gravel_clumps(p, seed, edge, 0.0f, glsl::NEIGHBOUR_CELLS));
      REQUIRE(glsl::fish_clumps(p, seed, edge, 0.0f, glsl::NEAR_CELLS) ==
              glsl::fish_clumps(p, seed, edge, 0.0f, glsl::NEIGHBOUR_CELLS));
    }
  }
}

TEST_CASE("the flowers' discs on the sphere are whole and each bouquet has its own peak from the faintest to 1",
          "[fast][systems]") {
  // Each disc's centre is its feature point moved onto the sphere (in double here), present where
  // the point lies within FLOWER_SHELL cells of it; a disc reaches p (frayed: 1 + FLOWER_EDGE_REACH
  // of its radius, 1.5) only from a point within sqrt(0.4^2 + (1 + 0.4 / 28) 0.57^2) = 0.700 cells
  // (the cells the search loops over; the triangle inequality's 0.97 at most), which the 27 cells
  // hold and the 125 around p hold with room. The outlines and the cloud agree with the brute
  // force's to the distances' float rounding: coordinates below 30 cells (ulp 1.9e-6) through a few
  // operations, over radii from 0.22 cells, 5e-5 of a radius (1e-4 taken), through a rim's slope of
  // at most 1.5 / FLOWER_RIM = 10: 1e-3.
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  const float cells = glsl::FLOWER_CELLS;
  const glsl::vec2 radii = glsl::FLOWER_RADII;
  const float frayed = 1.0f + glsl::FLOWER_EDGE_REACH, reach = frayed * radii.y;
  int near = 0;
  for (std::uint32_t seed : {1u, 5u}) {
    const glsl::uvec3 key = glsl::noise_key(seed, glsl::FLOWERS_LAYER),
                      size_key = glsl::noise_key(seed, glsl::FLOWERS_LAYER + 1u);
    for (int k = 0; k < 4000; ++k) {
      const vec3 p = glm::normalize(vec3(unit(rng), unit(rng), unit(rng)));
      const float edge = unit(rng), texel_arc = k % 2 ? 2.0f / 512 : 0.0f;
      const glsl::vec4 rims(edge, glsl::FLOWER_EDGE_REACH, glsl::FLOWER_RIM, texel_arc);
      const glm::dvec3 scaled = glm::dvec3(p) * double(cells);
      const glsl::ivec3 cell(glm::floor(vec3(p) * cells));
      double nearest = 1e30;
      glm::dvec2 brute(0.0);
      for (int z = -2; z <= 2; ++z)
        for (int y = -2; y <= 2; ++y)
          for (int x = -2; x <= 2; ++x) {
            const glsl::ivec3 c = cell + glsl::ivec3(x, y, z);
            const glsl::vec4 system =
                glsl::convective_cell(c, key, size_key, radii, glsl::presence_everywhere(1.0f), glsl::no_line_waves());
            const glm::dvec3 point = glm::dvec3(c) + glm::dvec3(vec3(system));
            const double height = glm::length(point);
            if (std::abs(height - cells) > glsl::FLOWER_SHELL) continue;
            const double d = glm::length(point * (cells / height) - scaled) / system.w;
            nearest = std::min(nearest, d);
            const double outline = glsl::rimmed_cloud(float(d), edge, glsl::FLOWER_EDGE_REACH,
                                                      glsl::resolved_rim(glsl::FLOWER_RIM, cells, system.w, texel_arc));
            const double peak =
                glsl::FLOWER_FAINTEST + (1.0 - glsl::FLOWER_FAINTEST) * glsl::system_hashes(c, size_key).z;
            brute = glm::max(brute, glm::dvec2(outline, outline * peak));
          }
      const glsl::vec2 found = glsl::surface_disc_clouds(p, cells, seed, glsl::FLOWERS_LAYER, radii, glsl::FLOWER_SHELL,
                                                         rims, glsl::FLOWER_FAINTEST, glsl::NEIGHBOUR_CELLS);
      if (nearest <= frayed) ++near;
      REQUIRE(found.x == Approx(brute.x).margin(1e-3));
      REQUIRE(found.y == Approx(brute.y).margin(1e-3));
      REQUIRE(found.y <= found.x);
      REQUIRE(glsl::surface_disc_clouds(p, cells, seed, glsl::FLOWERS_LAYER, radii, glsl::FLOWER_SHELL, rims,
                                        glsl::FLOWER_FAINTEST, 0) == glsl::vec2(0.0f));
    }
  }
  // 0.8 discs a cell^2 of 1.5 x 0.3 cells' radius cover about two fifths of the sphere.
  CHECK(near > 2000);
  CHECK(glsl::FLOWER_SHELL + reach <= 1.0f);  // whole by the triangle inequality alone
  // At the centres of the discs the outline is full and the cloud is the largest peak of the discs
  // whose outline is full there, the disc's own at least. The peaks, uniform from FLOWER_FAINTEST to
  // 1, put half the discs below the middle of that range; a brighter disc covering a centre (about
  // a fifth of the sea is under a bouquet) lifts a few, so that between two fifths and a half of the
  // centres are dimmer than the middle, and the dimmest are near FLOWER_FAINTEST.
  const glsl::uvec3 key = glsl::noise_key(3u, glsl::FLOWERS_LAYER),
                    size_key = glsl::noise_key(3u, glsl::FLOWERS_LAYER + 1u);
  const glsl::vec4 rims(0.0f, glsl::FLOWER_EDGE_REACH, glsl::FLOWER_RIM, 0.0f);
  const float middle = 0.5f * (1.0f + glsl::FLOWER_FAINTEST);
  int centres = 0, dim = 0;
  float dimmest = 1.0f;
  const int n = int(cells) + 1;
  for (int x = -n; x <= n; ++x)
    for (int y = -n; y <= n; ++y)
      for (int z = -n; z <= n; ++z) {
        const glsl::ivec3 c(x, y, z);
        const glsl::vec4 system =
            glsl::convective_cell(c, key, size_key, radii, glsl::presence_everywhere(1.0f), glsl::no_line_waves());
        const vec3 point = vec3(c) + vec3(system);
        if (std::abs(glm::length(point) - cells) > glsl::FLOWER_SHELL) continue;
        const glsl::vec2 found =
            glsl::surface_disc_clouds(glm::normalize(point), cells, 3u, glsl::FLOWERS_LAYER, radii, glsl::FLOWER_SHELL,
                                      rims, glsl::FLOWER_FAINTEST, glsl::NEIGHBOUR_CELLS);
        const float peak = glsl::FLOWER_FAINTEST + (1.0f - glsl::FLOWER_FAINTEST) * glsl::system_hashes(c, size_key).z;
        REQUIRE(found.x == Approx(1.0f).margin(1e-3));
        REQUIRE(found.y >= peak - 1e-3f);
        ++centres;
        dim += found.y < middle;
        dimmest = std::min(dimmest, found.y);
      }
  INFO(dim << " of " << centres << " centres dimmer than " << middle << ", the dimmest " << dimmest);
  REQUIRE(centres > 5000);
  CHECK(double(dim) / centres > 0.4);
  CHECK(double(dim) / centres < 0.5 + 4.0 * std::sqrt(0.25 / centres));
  CHECK(dimmest < glsl::FLOWER_FAINTEST + 0.01f);
}

TEST_CASE("the organised patterns' clumps are brighter than sugar and the sea between them darker and clearer",
          "[fast][systems]") {
  // The clumps' cover contrast, from the square of their strength: gravel 1 - 0.8 x 0.92, fish
  // 1 - 0.36 x 0.92, flowers 1, each above sugar's SHALLOW_CONTRAST; between the clumps of a
  // fully organised region, SHALLOW_CONTRAST x MOAT_CONTRAST.
  const float degree = float(M_PI) / 180.0f;
  const glm::vec3 strength = glsl::TRADE_PATTERN_STRENGTH;
  float previous = glsl::cover_contrast(1.0f, 0.0f, 0.0f);  // sugar
  for (int k = 0; k < 3; ++k) {
    glsl::CloudTypes clump{};
    clump.cumulus = strength[k];
    const float contrast =
        glsl::cover_contrast(glsl::shallow_trades_weight(clump, 15.0f * degree, 0.0f, 1.0f), 1.0f, 0.0f);
    const float s2 = strength[k] * strength[k];
    CHECK(contrast == Approx(1.0f - (1.0f - s2) * (1.0f - glsl::SHALLOW_CONTRAST * glsl::MOAT_CONTRAST)).margin(1e-6));
    CHECK(contrast > previous);
    previous = contrast;
  }
  CHECK(glsl::cover_contrast(1.0f, 1.0f, 0.0f) < glsl::cover_contrast(1.0f, 0.0f, 0.0f));
  // The moat: the shallow regime's weight times the organised share away from the clumps, none
  // at a clump (its cumulus weight from 0.15) or under sugar; the density thinned by MOAT_CLEARING.
  CHECK(glsl::trade_moat(1.0f, 1.0f, 0.0f) == 1.0f);
  CHECK(glsl::trade_moat(0.5f, 1.0f, 0.0f) == 0.5f);
  CHECK(glsl::trade_moat(1.0f, 1.0f, 0.15f) == 0.0f);
  CHECK(glsl::trade_moat(1.0f, 0.0f, 0.0f) == 0.0f);
  CHECK(glsl::trade_moat(1.0f, 1.0f, 0.075f) == Approx(0.5f).margin(1e-6));
  CHECK(glsl::with_moats(0.5f, 1.0f) == Approx(0.5f * (1.0f - glsl::MOAT_CLEARING)).margin(1e-7));
  CHECK(glsl::with_moats(0.5f, 0.0f) == 0.5f);
}

TEST_CASE("trade cumulus fade over the deserts and stay over the ocean, the other belts stay everywhere",
          "[fast][systems]") {
  const glsl::vec4 fields(0.9f, 0.6f, 0.3f, 0.5f);
  // No mask (bias 0) and the decks' ocean (positive bias): unchanged, to the bit.
  for (float ocean : {0.0f, 0.3f, 1.0f}) CHECK(glsl::belts_over_surface(fields, ocean) == fields);
  // Inside a desert (bias -0.4 and below: the Sahara's interior about -1): no cumulus, the
  // clusters and the cirrus untouched.
  for (float desert : {-0.4f, -1.0f})
    CHECK(glsl::belts_over_surface(fields, desert) == glsl::vec4(0.9f, 0.0f, 0.3f, 0.5f));
  // Half way, smoothstep's middle: half the cumulus; and the fade is monotonic.
  CHECK(glsl::belts_over_surface(fields, -0.2f).y == Approx(0.3f).margin(1e-6));
  float previous = fields.y;
  for (int k = 1; k <= 40; ++k) {
    const float y = glsl::belts_over_surface(fields, -0.01f * k).y;
    CHECK(y <= previous);
    previous = y;
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

namespace {

// A patch of `n` x `n` points of the sphere around `centre`, `half` radians either side along
// its local east and north.
std::vector<vec3> patch(vec3 centre, float half, int n) {
  const vec3 east = glm::normalize(glm::cross(vec3(0.0f, 0.0f, 1.0f), centre));
  const vec3 north = glm::cross(centre, east);
  std::vector<vec3> points;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const float u = half * (2.0f * (i + 0.5f) / n - 1.0f), v = half * (2.0f * (j + 0.5f) / n - 1.0f);
      points.push_back(glm::normalize(centre + u * east + v * north));
    }
  return points;
}

// The 4-connected components of the set pixels of an n x n mask: their sizes, and how many of
// them keep off the mask's edge.
struct Components {
  std::vector<int> sizes;
  int inside = 0;
};
Components components(const std::vector<bool>& mask, int n) {
  std::vector<int> label(mask.size(), -1), sizes, stack;
  std::vector<bool> edge;
  for (int start = 0; start < n * n; ++start) {
    if (!mask[start] || label[start] >= 0) continue;
    const int id = static_cast<int>(sizes.size());
    sizes.push_back(0);
    edge.push_back(false);
    stack.push_back(start);
    label[start] = id;
    while (!stack.empty()) {
      const int k = stack.back();
      stack.pop_back();
      ++sizes[id];
      const int i = k % n, j = k / n;
      if (i == 0 || j == 0 || i == n - 1 || j == n - 1) edge[id] = true;
      const int next[4][2] = {{i - 1, j}, {i + 1, j}, {i, j - 1}, {i, j + 1}};
      for (const auto& q : next) {
        if (q[0] < 0 || q[0] >= n || q[1] < 0 || q[1] >= n) continue;
        const int m = q[1] * n + q[0];
        if (mask[m] && label[m] < 0) label[m] = id, stack.push_back(m);
      }
    }
  }
  return {sizes, static_cast<int>(std::count(edge.begin(), edge.end(), false))};
}

// Parts and cells are counted where they keep off the patch's edge (the edge cuts the others).
struct Topology {
  double cloudy;         // share of the patch where the pattern exceeds 0.5
  int cloud_parts;       // connected cloudy parts
  double largest_cloud;  // the largest cloudy part's share of the cloud
  int clear_parts;       // connected clear parts
  double largest_clear;  // the largest clear part's share of the clear
  int cells;             // Voronoi cells of the lattice within the patch
};

// A cell pattern's topology over a patch, with the cells its lattice (frequency, layer) puts there.
template <class Pattern>
Topology topology(Pattern pattern, float frequency, std::uint32_t seed, std::uint32_t layer) {
  const int n = 500;
  const auto points = patch(vec3(std::cos(0.38f), 0.0f, std::sin(0.38f)), 0.06f, n);
  std::vector<bool> cloud(points.size()), clear(points.size());
  std::vector<std::array<int, 3>> cells, edge_cells;
  for (size_t k = 0; k < points.size(); ++k) {
    cloud[k] = pattern(points[k]) > 0.5f;
    clear[k] = !cloud[k];
    const vec3 scaled = points[k] * frequency;
    const glsl::vec4 f1 = glsl::worley_f1(scaled, glsl::ivec3(0), glsl::noise_key(seed, layer));
    const glm::ivec3 cell = glsl::nearest_cell(scaled, f1);
    cells.push_back({cell.x, cell.y, cell.z});
    const int i = static_cast<int>(k) % n, j = static_cast<int>(k) / n;
    if (i == 0 || j == 0 || i == n - 1 || j == n - 1) edge_cells.push_back(cells.back());
  }
  for (auto* list : {&cells, &edge_cells}) {
    std::sort(list->begin(), list->end());
    list->erase(std::unique(list->begin(), list->end()), list->end());
  }
  Topology t{};
  t.cells = static_cast<int>(cells.size() - edge_cells.size());
  const auto clouds = components(cloud, n), clears = components(clear, n);
  const double cloudy = std::count(cloud.begin(), cloud.end(), true);
  t.cloudy = cloudy / points.size();
  t.cloud_parts = clouds.inside;
  t.largest_cloud = *std::max_element(clouds.sizes.begin(), clouds.sizes.end()) / cloudy;
  t.clear_parts = clears.inside;
  t.largest_clear = *std::max_element(clears.sizes.begin(), clears.sizes.end()) / (points.size() - cloudy);
  return t;
}

}  // namespace

TEST_CASE("closed cells hold the cloud in one cell each with the clear a network, open cells the opposite",
          "[fast][systems]") {
  const std::uint32_t seed = 777u;
  const Topology closed = topology([&](vec3 p) { return glsl::closed_cells(p, seed, glsl::NEIGHBOUR_CELLS); },
                                   glsl::CLOSED_CELLS, seed, glsl::CLOSED_CELLS_LAYER);
  INFO("closed: cloudy " << closed.cloudy << ", " << closed.cloud_parts << " clouds in " << closed.cells
                         << " cells, largest clear part " << closed.largest_clear);
  // Each cell its own cloud: as many clouds as cells, to the few cells that the sphere cuts to
  // slivers thinner than their rims.
  CHECK(closed.cloud_parts == Approx(closed.cells).epsilon(0.05));
  CHECK(closed.largest_clear > 0.95);
  CHECK(closed.cloudy > 0.7);
  const Topology open = topology([&](vec3 p) { return glsl::open_cells(p, seed, 0.0f, glsl::NEIGHBOUR_CELLS); },
                                 glsl::OPEN_CELLS, seed, glsl::OPEN_CELLS_LAYER);
  INFO("open: cloudy " << open.cloudy << ", " << open.clear_parts << " clear centres in " << open.cells
                       << " cells, largest cloud part " << open.largest_cloud);
  // Open cells: the walls one network around clear centres, some of the walls broken. A wall is
  // cloud (above 0.5) along its middle where its strength is above 0.5, which a share u* of the
  // walls misses (open_cell_wall(u*) = 0.5, found here by bisection: about 0.18). A tessellation
  // with three walls at each vertex has six walls a cell on average (Euler's formula), three
  // walls per cell, so 3 u* cells of broken walls, each joining two centres at most: between
  // (1 - 3 u*) of the cells (every broken wall joining two parts; less the count's binomial
  // spread, sqrt(3 u* cells) = 7 at 100 cells, twice) and nine tenths of them.
  float low = 0.0f, high = 1.0f;
  for (int k = 0; k < 40; ++k) (glsl::open_cell_wall(0.5f * (low + high)) < 0.5f ? low : high) = 0.5f * (low + high);
  const double broken = 3.0 * low * open.cells;
  INFO("u* " << low << ": " << broken << " broken walls expected");
  CHECK(low == Approx(0.18).margin(0.02));
  CHECK(open.clear_parts >= open.cells - broken - 2.0 * std::sqrt(broken));
  CHECK(open.clear_parts <= 0.9 * open.cells);
  CHECK(open.largest_cloud > 0.95);
  CHECK(open.cloudy < 0.6);
}

TEST_CASE("each wall between two open cells has one strength, the same from either side of it", "[fast][systems]") {
  // Pairs of points a thousandth of a cell apart across a wall (in different Voronoi cells, both
  // within 0.01 of a cell of their nearest border and away from a vertex): the same number.
  const std::uint32_t seed = 31u;
  const glsl::uvec3 key = glsl::noise_key(seed, glsl::OPEN_CELLS_LAYER);
  const auto points = patch(vec3(std::cos(0.5f), 0.0f, std::sin(0.5f)), 0.05f, 400);
  const float step = 1.0e-3f / glsl::OPEN_CELLS;
  int pairs = 0, differ = 0;
  std::vector<float> numbers;
  for (size_t k = 0; k + 1 < points.size(); ++k) {
    const vec3 p = points[k], q = glm::normalize(p + glm::normalize(points[k + 1] - p) * step);
    const glsl::vec3 a = glsl::cell_borders(p * glsl::OPEN_CELLS, p, key, glsl::NEIGHBOUR_CELLS);
    const glsl::vec3 b = glsl::cell_borders(q * glsl::OPEN_CELLS, q, key, glsl::NEIGHBOUR_CELLS);
    const glm::ivec3 cell_a =
        glsl::nearest_cell(p * glsl::OPEN_CELLS, glsl::worley_f1(p * glsl::OPEN_CELLS, glsl::ivec3(0), key));
    const glm::ivec3 cell_b =
        glsl::nearest_cell(q * glsl::OPEN_CELLS, glsl::worley_f1(q * glsl::OPEN_CELLS, glsl::ivec3(0), key));
    if (cell_a == cell_b || a.x > 0.01f || b.x > 0.01f || a.y < 0.1f || b.y < 0.1f) continue;
    ++pairs;
    if (a.z != b.z) ++differ;
    numbers.push_back(a.z);
  }
  INFO(pairs << " pairs across walls");
  REQUIRE(pairs > 20);
  CHECK(differ == 0);
  // The numbers are spread over [0, 1) rather than one value (a wall each).
  CHECK(*std::max_element(numbers.begin(), numbers.end()) - *std::min_element(numbers.begin(), numbers.end()) > 0.5f);
  // The strength: none below u = 0.05, 0.55 + 0.9 u above 0.25.
  CHECK(glsl::open_cell_wall(0.04f) == 0.0f);
  CHECK(glsl::open_cell_wall(0.5f) == Approx(1.0f).margin(1e-6));
  CHECK(glsl::open_cell_wall(1.0f) == Approx(1.45f).margin(1e-6));
}

TEST_CASE("the cell patterns' means over the sphere are the constants the modulation subtracts", "[fast][systems]") {
  std::mt19937 rng(5);
  std::normal_distribution<float> g;
  const int n = 100000;
  double closed = 0, open = 0, clumped = 0;
  for (int k = 0; k < n; ++k) {
    const vec3 p = glm::normalize(vec3(g(rng), g(rng), g(rng)));
    closed += glsl::closed_cells(p, 9u, glsl::NEIGHBOUR_CELLS);
    open += glsl::open_cells(p, 9u, 0.0f, glsl::NEIGHBOUR_CELLS);
    clumped += glsl::open_cells(p, 9u, 1.0f, glsl::NEIGHBOUR_CELLS);
  }
  // The sample's standard error: the patterns' spread (below 0.6) over sqrt(n), 0.0019; the cells'
  // own number (a million on the sphere) adds less.
  CHECK(closed / n == Approx(glsl::CLOSED_CELLS_MEAN).margin(0.005));
  CHECK(open / n == Approx(glsl::OPEN_CELLS_MEAN).margin(0.005));
  CHECK(clumped / n == Approx(glsl::OPEN_CELLS_CLUMPED_MEAN).margin(0.005));
}

TEST_CASE("cells are drawn only where the cover resolves them, from 2.5 texels a cell", "[fast][systems]") {
  for (int size : {64, 256, 512, 1024, 2048}) {
    const float arc = 2.0f / float(size);
    INFO("size " << size);
    // The closed cells' spacing is size / 320 texels, the open ones' size / 160.
    // smoothstep(2.5, 5, 3.2) = 3 t^2 - 2 t^3 = 0.1913 at t = 0.28.
    const float closed = size <= 512 ? 0.0f : size >= 2048 ? 1.0f : 0.1913f;
    const float open = size <= 256 ? 0.0f : size >= 1024 ? 1.0f : 0.1913f;
    CHECK(glsl::cells_resolved(glsl::CLOSED_CELLS, arc) == Approx(closed).margin(1e-5));
    CHECK(glsl::cells_resolved(glsl::OPEN_CELLS, arc) == Approx(open).margin(1e-5));
  }
}

TEST_CASE("the density pass is compiled with the cell patterns a cover draws and no others", "[fast][systems]") {
  cover::CoverParameters p;
  // The boundaries: the open cells from 5 / (2 x 80 x 0.5) = 400 texels a face (2.5 texels a
  // cell: 1 / (80 x 2 / N) > 2.5), the closed from 800 (at those two sizes exactly the fade's
  // weight is float's rounding of 0, so the sizes beside them are judged).
  // The streets from 5 x 531 / 2 = 1327.5 x 2 = 2655 texels a face (2.5 texels a row).
  for (int size : {64, 256, 399, 401, 512, 799, 801, 1024, 2048, 2654, 2656, 4096}) {
    INFO("size " << size);
    p.size = size;
    p.stratocumulus_cells = 1.0f;
    p.cloud_streets = 1.0f;
    const cover::CellPatterns drawn = cover::cell_patterns_drawn(p);
    CHECK(drawn.open == (size > 400));
    CHECK(drawn.closed == (size > 800));
    CHECK(drawn.streets == (size > 2655));
    p.stratocumulus_cells = 0.0f;
    p.cloud_streets = 0.0f;
    const cover::CellPatterns none = cover::cell_patterns_drawn(p);
    CHECK_FALSE(none.open);
    CHECK_FALSE(none.closed);
    CHECK_FALSE(none.streets);
  }
  // No cyclones, no cold air: no streets.
  p.size = 4096;
  p.cloud_streets = 1.0f;
  p.cyclones = 0;
  CHECK_FALSE(cover::cell_patterns_drawn(p).streets);
}

TEST_CASE("stratocumulus decks lie in patches of their belt, off the west coasts with a land mask", "[fast][systems]") {
  const std::uint32_t seed = 4242u;
  auto at = [](float lat_deg, float lon) {
    const float lat = lat_deg * float(M_PI) / 180.0f;
    return vec3(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat));
  };
  for (float lat : {-60.0f, -42.0f, -3.0f, 0.0f, 3.0f, 42.0f, 60.0f})
    for (int k = 0; k < 64; ++k) {
      const vec3 p = at(lat, 0.1f * k);
      CHECK(glsl::deck_strength(p, std::asin(p.z), seed, 0.0f, 0.0f) == 0.0f);
    }
  // Along 22 degrees: decks in separate patches covering part of the circle.
  for (float lat : {-22.0f, 22.0f}) {
    const int n = 3600;
    int present = 0, patches = 0;
    bool previous = false;
    for (int k = 0; k < n; ++k) {
      const vec3 p = at(lat, 2.0f * float(M_PI) * k / n);
      const bool deck = glsl::deck_presence(glsl::deck_strength(p, std::asin(p.z), seed, 0.0f, 0.0f)) > 0.5f;
      present += deck;
      patches += deck && !previous;
      previous = deck;
    }
    INFO("latitude " << lat << ": decks over " << double(present) / n << " of the circle in " << patches << " patches");
    CHECK(double(present) / n > 0.2);
    CHECK(double(present) / n < 0.8);
    CHECK(patches >= 3);
  }
  // With a land mask the bias alone: full from 0.4, none over land (b < 0).
  const vec3 p = at(22.0f, 0.0f);
  CHECK(glsl::deck_strength(p, std::asin(p.z), seed, 0.2f, 0.4f) == Approx(0.5f));
  CHECK(glsl::deck_strength(p, std::asin(p.z), seed, 0.7f, 0.4f) == 1.0f);
  CHECK(glsl::deck_strength(p, std::asin(p.z), seed, -0.5f, 0.4f) == 0.0f);
}

TEST_CASE("a deck's edge moves with the cover's noise and its brightness fades with its strength", "[fast][systems]") {
  for (float edge = -1.0f; edge <= 1.0f; edge += 0.125f) {
    INFO("edge " << edge);
    CHECK(glsl::frayed_deck(0.0f, edge) == 0.0f);
    // The core stays a deck: strength 1 times 1 - 0.75 at the least, presence smoothstep(0.1, 0.3, 0.25).
    CHECK(glsl::deck_presence(glsl::frayed_deck(1.0f, edge)) >= 0.84f);
    CHECK(glsl::frayed_deck(1.0f, edge) <= 1.0f);
  }
  // The unfrayed fringe's middle (strength 0.2): no deck under the thinnest cloud, all deck under
  // the thickest, so that the noise draws the edge there.
  CHECK(glsl::deck_presence(glsl::frayed_deck(0.2f, -1.0f)) == 0.0f);
  CHECK(glsl::deck_presence(glsl::frayed_deck(0.2f, 1.0f)) == 1.0f);
  // Where the presence is half: strength 0.2 / (1 + 0.75 e), from 0.114 (e = 1) to 0.8 (e = -1).
  CHECK(glsl::deck_presence(glsl::frayed_deck(0.2f / 1.75f, 1.0f)) == Approx(0.5f).margin(1e-5));
  CHECK(glsl::deck_presence(glsl::frayed_deck(0.8f, -1.0f)) == Approx(0.5f).margin(1e-5));
  // A deck organises its cloud into a bright sheet gradually: none at strength 0, all from 0.8,
  // half at 0.4, rising in between.
  CHECK(glsl::deck_organisation(0.0f) == 0.0f);
  CHECK(glsl::deck_organisation(0.8f) == 1.0f);
  CHECK(glsl::deck_organisation(0.4f) == Approx(0.5f).margin(1e-6));
  for (float d = 0.0f; d < 1.0f; d += 0.05f) CHECK(glsl::deck_organisation(d + 0.05f) >= glsl::deck_organisation(d));
  // Rising with the strength and with the noise.
  for (float d = 0.0f; d < 1.0f; d += 0.05f)
    for (float edge = -1.0f; edge < 1.0f; edge += 0.25f) {
      CHECK(glsl::frayed_deck(d + 0.05f, edge) >= glsl::frayed_deck(d, edge));
      CHECK(glsl::frayed_deck(d, edge + 0.25f) >= glsl::frayed_deck(d, edge));
    }
}

TEST_CASE("the cells do not show through a front's or a convective system's deep cloud", "[fast][systems]") {
  // Fields: x the ITCZ's clusters (weight 1), y the trade cumulus (0.6), z the cirrus (0.35), w the anvils.
  CHECK(glsl::cells_hidden(glsl::cloud_types(1.0f, glm::vec4(0.0f))) == 1.0f);
  CHECK(glsl::cells_hidden(glsl::cloud_types(0.0f, glm::vec4(1.0f, 0.0f, 0.0f, 0.0f))) == 1.0f);
  CHECK(glsl::cells_hidden(glsl::cloud_types(0.25f, glm::vec4(0.5f, 0.0f, 0.0f, 0.0f))) == 0.5f);
  // Broken and thin cloud hides nothing: the cumulus, the cirrus streaks and the anvils.
  CHECK(glsl::cells_hidden(glsl::cloud_types(0.0f, glm::vec4(0.0f, 0.6f, 0.35f, 1.0f))) == 0.0f);
}

TEST_CASE("decks are closed cells in their cores and open at their fringes and in the cold air behind cold fronts",
          "[fast][systems]") {
  CHECK(glsl::cell_weights(1.0f, 0.0f).x == 1.0f);
  CHECK(glsl::cell_weights(1.0f, 0.0f).y == 0.0f);
  CHECK(glsl::cell_weights(0.3f, 0.0f).x == 0.0f);
  CHECK(glsl::cell_weights(0.3f, 0.0f).y == 1.0f);
  CHECK(glsl::cell_weights(0.0f, 0.0f) == vec2(0.0f));
  CHECK(glsl::cell_weights(0.0f, 0.8f).y == 0.8f);
  // The cold sector in the cyclone's frame: from the cold front's tail (-0.7, -3) to the join
  // (1, -0.6), "ahead" the unit vector (2.4, -1.7) / 2.94. Behind it by 1.5 radii half way along:
  const vec2 half_way(0.15f, -1.8f), ahead = glm::normalize(vec2(2.4f, -1.7f));
  CHECK(glsl::cold_sector(half_way - 1.5f * ahead) == 1.0f);
  CHECK(glsl::cold_sector(half_way) == 0.0f);                 // the front's band
  CHECK(glsl::cold_sector(half_way - 0.4f * ahead) == 0.0f);  // the dry slot
  CHECK(glsl::cold_sector(half_way + 1.0f * ahead) == 0.0f);  // the warm sector ahead of the front
  CHECK(glsl::cold_sector(half_way - 3.0f * ahead) == 0.0f);  // beyond the outbreak
  CHECK(glsl::cold_sector(vec2(-1.5f, 0.5f)) == 0.0f);        // poleward of the low
  CHECK(glsl::cold_sector(vec2(-0.4f, -0.4f)) == 0.0f);       // the head's hook
}

TEST_CASE("the cold air furthest behind the front is in streets and the rest in open cells", "[fast][systems]") {
  const vec2 half_way(0.15f, -1.8f), ahead = glm::normalize(vec2(2.4f, -1.7f));
  CHECK(glsl::behind_cold_front(half_way - 1.5f * ahead) == Approx(1.5f).margin(1e-5));
  CHECK(glsl::street_share(half_way - 1.0f * ahead) == 0.0f);  // near the front: open cells
  CHECK(glsl::street_share(half_way - 2.0f * ahead) == 1.0f);  // far behind: streets
  // cold_air's x is the cold sector as cold_sectors has it, its y the streets' share there.
  glsl::WeatherSystems systems{};
  systems.cyclone_count = 1;
  glsl::Cyclone& c = systems.cyclones[0];
  c.centre = glm::normalize(vec3(1.0f, 0.0f, 1.2f));
  c.east = vec3(0.0f, 1.0f, 0.0f);
  c.pole = glm::cross(c.centre, c.east);
  c.radius = 0.2f;
  c.strength = 0.8f;
  for (float behind : {0.8f, 1.2f, 1.55f, 2.0f, 2.3f}) {
    const vec2 xy = half_way - behind * ahead;
    const vec3 p = glm::normalize(c.centre + c.radius * (xy.x * c.east + xy.y * c.pole));
    const vec2 air = glsl::cold_air(p, systems, glsl::cyclones_near(p, systems), 1.0f);
    const vec2 frame = glsl::cyclone_frame(p, c);
    INFO("behind " << behind);
    CHECK(air.x == Approx(0.8f * glsl::cold_sector(frame)).margin(1e-6));
    CHECK(air.x == glsl::cold_sectors(p, systems));
    CHECK(air.y == Approx(glsl::street_share(frame)).margin(1e-6));
    // Over land no cold-air cells or streets: the sea's share scales the sector, not the streets'
    // share of it.
    const vec2 coast = glsl::cold_air(p, systems, glsl::cyclones_near(p, systems), 0.25f);
    CHECK(coast.x == Approx(0.25f * air.x).margin(1e-7));
    CHECK(coast.y == air.y);
    CHECK(glsl::cold_air(p, systems, glsl::cyclones_near(p, systems), 0.0f).x == 0.0f);
  }
}

TEST_CASE("the loops over the cyclones near a point give what loops over every cyclone give", "[fast][systems]") {
  // cyclone_systems and cold_air visit only cyclones_near's cyclones, so that SIMD lanes skip the
  // others (prelude.glsl, SKIPPABLE); a cyclone outside the set contributes nothing, so the
  // results equal the full loops' exactly.
  cover::CoverParameters p;
  p.cyclones = 15;  // the most per hemisphere: 30 cyclones of a 32-bit set
  const glsl::WeatherSystems systems = cover::weather_systems(p, 5000.0);
  REQUIRE(systems.cyclone_count >= 20);
  std::mt19937 rng(3);
  std::normal_distribution<float> normal;
  int near_total = 0, points_near = 0;
  const int points = 20000;
  for (int k = 0; k < points; ++k) {
    const vec3 q = glm::normalize(vec3(normal(rng), normal(rng), normal(rng)));
    const float edge = std::uniform_real_distribution<float>(-1.0f, 1.0f)(rng);
    float cloud = 0.0f;
    vec2 air(0.0f);
    for (int i = 0; i < systems.cyclone_count; ++i) {
      const glsl::Cyclone& c = systems.cyclones[i];
      cloud = std::max(cloud, glsl::cyclone_cloud(q, c, edge));
      const vec2 xy = glsl::cyclone_frame(q, c);
      if (glm::dot(xy, xy) < 16.0f && c.strength * glsl::cold_sector(xy) > air.x)
        air = vec2(c.strength * glsl::cold_sector(xy), glsl::street_share(xy));
    }
    INFO("point " << k);
    REQUIRE(glsl::cyclone_systems(q, systems, glsl::cyclones_near(q, systems), edge) == cloud * glsl::frontal_reach(q));
    REQUIRE(glsl::cold_air(q, systems, glsl::cyclones_near(q, systems), 1.0f) == air);
    const int near = glm::bitCount(glsl::cyclones_near(q, systems));
    near_total += near;
    points_near += near > 0 ? 1 : 0;
  }
  // cyclones_near holds a point within 4 head radii in the frame, |xy| = sin(angle) / radius <= 4,
  // and within 60 degrees: a cap of angle min(asin(4 radius), 60 degrees), (1 - cos) / 2 of the
  // sphere. The mean size of the set is the caps' sum (caps of different cyclones overlap, which
  // leaves a sum of independent indicators unbiased); its standard error over the points is below
  // sqrt(sum / points) (each indicator's variance is below its mean).
  double expected = 0.0;
  for (int i = 0; i < systems.cyclone_count; ++i)
    expected +=
        (1.0 - std::cos(std::min(std::asin(std::min(4.0 * systems.cyclones[i].radius, 1.0)), M_PI / 3.0))) / 2.0;
  const double mean = double(near_total) / points;
  CHECK(std::abs(mean - expected) < 4.0 * std::sqrt(expected / points));
  // The loops go through that many cyclones (for the busiest lane of a group) instead of all.
  CHECK(mean < 0.25 * systems.cyclone_count);
  WARN("cyclones near a point: " << mean << " on average (caps " << expected << ") of " << systems.cyclone_count
                                 << ", any near " << double(points_near) / points << " of the sphere");
}

TEST_CASE("the cells' searches and the pockets' octaves left out give the patterns far from any cell",
          "[fast][systems]") {
  // SKIPPABLE's count 0 where the modulation's weight is 0: no border (1e30), so closed cells are
  // whole (1) and open cells clear (0), and no pocket (0), which with_pockets leaves as it found.
  const vec3 q = glm::normalize(vec3(0.3f, -0.5f, 0.8f));
  CHECK(glsl::cell_border(q * glsl::CLOSED_CELLS, q, glsl::noise_key(1u, glsl::CLOSED_CELLS_LAYER), 0) == 1.0e30f);
  CHECK(glsl::closed_cells(q, 1u, 0) == 1.0f);
  CHECK(glsl::open_cells(q, 1u, 1.0f, 0) == 0.0f);
  CHECK(glsl::open_cell_pockets(q, 1u, 0) == 0.0f);
  CHECK(glsl::with_pockets(vec2(0.0f, 0.4f), 0.0f) == vec2(0.0f, 0.4f));
  // And the modulations, which choose the count themselves, are zero where their weight is.
  CHECK(glsl::closed_cell_modulation(q, 0.0f, 1u, 1.0e-4f) == 0.0f);
  CHECK(glsl::open_cell_modulation(q, 0.0f, 1u, 1.0e-4f) == 0.0f);
}

namespace {

// The streets' rows over a patch `half` radians either side of `centre`, n x n points, with the
// wind along the patch's east: 1 where a row is (street_rows above 0.5).
std::vector<bool> street_patch(vec3 centre, float half, int n, std::uint32_t seed) {
  std::vector<bool> rows;
  for (const vec3& p : patch(centre, half, n)) {
    const vec3 east = glm::normalize(glm::cross(vec3(0.0f, 0.0f, 1.0f), p));
    rows.push_back(glsl::street_rows(p, glm::cross(p, east), seed) > 0.5f);
  }
  return rows;
}

}  // namespace

TEST_CASE("cloud streets are long rows along the wind, 12 km apart, that end and merge", "[fast][systems]") {
  // A patch 400 km square at 60 N, 800 x 800 points (0.5 km apart), the wind from the west.
  const int n = 800;
  const float half = 200.0f / 6371.0f;
  const double spacing_km = 6371.0 / glsl::STREETS, pixel_km = 400.0 / n;
  const vec3 centre(std::cos(1.047f), 0.0f, std::sin(1.047f));
  const std::vector<bool> rows = street_patch(centre, half, n, 31u);
  // Along each north-south line, the rows crossed: the patch over the spacing, 33, on average,
  // to the few that end or merge on the way.
  double crossings = 0;
  for (int i = 0; i < n; i += 40) {
    int count = 0;
    for (int j = 1; j < n; ++j) count += rows[size_t(j) * n + i] && !rows[size_t(j - 1) * n + i];
    crossings += count;
  }
  crossings /= n / 40;
  INFO("rows crossed per 400 km: " << crossings << " (spacing " << spacing_km << " km)");
  CHECK(crossings == Approx(400.0 / spacing_km).epsilon(0.15));
  // Along the wind a point stays on its row or off it (correlation of the row mask at 20 km above
  // 0.6), across it the rows alternate: at half the spacing the mask is anti-correlated, at the
  // spacing correlated again.
  const auto correlation = [&](int di, int dj) {
    double same = 0, count = 0;
    for (int j = 0; j + dj < n; ++j)
      for (int i = 0; i + di < n; ++i) {
        same += rows[size_t(j) * n + i] == rows[size_t(j + dj) * n + i + di] ? 1.0 : -1.0;
        ++count;
      }
    return same / count;
  };
  const int along = int(std::lround(20.0 / pixel_km)), across_half = int(std::lround(spacing_km / 2 / pixel_km)),
            across = int(std::lround(spacing_km / pixel_km));
  INFO("correlation along 20 km " << correlation(along, 0) << ", across half a spacing " << correlation(0, across_half)
                                  << ", across a spacing " << correlation(0, across));
  CHECK(correlation(along, 0) > 0.6);
  CHECK(correlation(0, across_half) < -0.4);
  CHECK(correlation(0, across) > 0.3);
  // The rows are long: the separate rows inside the patch are few against those an unbroken
  // patch of 20 km rows would hold (400 / 12 rows x 20 per 400 km = 660).
  const auto parts = components(rows, n);
  INFO(parts.inside << " rows inside the patch");
  CHECK(parts.inside < 200);
}

TEST_CASE("a street is a string of separate clouds, placed independently on neighbouring rows", "[fast][systems]") {
  // The same 400 km patch at 60 N, wind from the west; a cloud where street_clouds is above 1/2.
  const int n = 800;
  const float half = 200.0f / 6371.0f;
  const double pixel_km = 400.0 / n, spacing_km = 6371.0 / glsl::STREETS;
  const vec3 centre(std::cos(1.047f), 0.0f, std::sin(1.047f));
  std::vector<bool> clouds;
  for (const vec3& p : patch(centre, half, n)) {
    const vec3 east = glm::normalize(glm::cross(vec3(0.0f, 0.0f, 1.0f), p));
    clouds.push_back(glsl::street_clouds(p, glm::cross(p, east), 31u) > 0.5f);
  }
  const std::vector<bool> rows = street_patch(centre, half, n, 31u);
  // Along the wind (rows of the patch), the runs of cloud: each pearl's length. Perlin noise is 0
  // at every lattice point and changes sign about once a lattice spacing (12 km) along a line:
  // runs of a third to 4/3 of it on average. The rows alone run for tens of km.
  double length = 0, row_length = 0;
  int runs = 0, row_runs = 0;
  for (int j = 0; j < n; j += 8)
    for (int i = 0; i < n; ++i) {
      const size_t k = size_t(j) * n + i;
      if (clouds[k]) length += pixel_km;
      if (clouds[k] && (i == 0 || !clouds[k - 1])) ++runs;
      if (rows[k]) row_length += pixel_km;
      if (rows[k] && (i == 0 || !rows[k - 1])) ++row_runs;
    }
  const double pearl_km = length / runs, row_km = row_length / row_runs;
  INFO("mean cloud " << pearl_km << " km along the wind, the rows' runs " << row_km << " km");
  CHECK(pearl_km > spacing_km / 3);
  CHECK(pearl_km < 4 * spacing_km / 3);
  CHECK(row_km > 4.0 * pearl_km);
  // Many separate clouds: each row of the patch (33 across it, 100 km long on average) broken into
  // pearls, against the rows' own parts.
  const auto parts = components(clouds, n);
  const auto row_parts = components(rows, n);
  INFO(parts.sizes.size() << " clouds in the patch against " << row_parts.sizes.size() << " rows");
  CHECK(parts.sizes.size() > 3 * row_parts.sizes.size());
  // Of the pairs of points `shift` pixels apart across the wind with a cloud at either end, the
  // share with a cloud at both.
  const auto both_cloudy = [&](int shift) {
    double both = 0, either = 0;
    for (int j = 0; j + shift < n; ++j)
      for (int i = 0; i < n; ++i) {
        const bool a = clouds[size_t(j) * n + i], b = clouds[size_t(j + shift) * n + i];
        if (a || b) both += a && b, ++either;
      }
    return both / either;
  };
  // Still in rows: half a spacing off a row's crest is between rows, so rarely both.
  const double half_spacing = both_cloudy(int(std::lround(spacing_km / 2 / pixel_km)));
  // A whole spacing across, from one row's clouds to the next row's: pearls aligned across the
  // rows (a lattice) would put a cloud at both ends nearly always; placed independently, with
  // a share q of each crest cloudy, q^2 / (2 q - q^2) of such pairs, 1/3 for q = 1/2.
  const double spacing = both_cloudy(int(std::lround(spacing_km / pixel_km)));
  INFO("both cloudy: " << half_spacing << " half a spacing apart, " << spacing << " a spacing apart");
  CHECK(half_spacing < 0.1);
  CHECK(spacing < 0.5);
}

TEST_CASE("the streets' mean over the sphere is the constant their modulation subtracts", "[fast][systems]") {
  std::mt19937 rng(7);
  std::normal_distribution<float> g;
  const int n = 100000;
  double sum = 0;
  for (int k = 0; k < n; ++k) {
    const vec3 p = glm::normalize(vec3(g(rng), g(rng), g(rng)));
    const vec3 across = glm::normalize(glm::cross(p, vec3(g(rng), g(rng), g(rng))));
    sum += glsl::street_clouds(p, across, 3u);
  }
  // The standard error: a spread below 0.5 over sqrt(n), 0.0016.
  CHECK(sum / n == Approx(glsl::STREETS_MEAN).margin(0.005));
  // No wind or no weight: nothing; a resolved pattern's modulation is within its contrast.
  const vec3 p = glm::normalize(vec3(0.3f, 0.4f, 0.8f));
  CHECK(glsl::street_modulation(p, vec3(0.0f), 1.0f, 3u, 1e-4f) == 0.0f);
  CHECK(glsl::street_modulation(p, vec3(0.0f, 1.0f, 0.0f), 0.0f, 3u, 1e-4f) == 0.0f);
  // The clouds lie in [0, 1] about their mean 1/4.
  CHECK(std::abs(glsl::street_modulation(p, vec3(0.0f, 1.0f, 0.0f), 1.0f, 3u, 1e-4f)) <=
        0.75f * glsl::STREET_CONTRAST + 1e-6f);
  // Unresolved (texels of 2 / 2048 radians: 2.5 texels a row is 2655 per face): nothing.
  CHECK(glsl::street_modulation(p, vec3(0.0f, 1.0f, 0.0f), 1.0f, 3u, 2.0f / 2048.0f) == 0.0f);
}

TEST_CASE("pockets of open cells are separate, sharp and larger than 1e4 km2, and turn closed cells open",
          "[fast][systems]") {
  // A patch 7600 km square at 22 degrees, 240 x 240 points (32 km apart).
  const int n = 240;
  const float half = 0.6f, radius_km = 6371.0f;
  const double pixel_km2 = std::pow(2.0 * half * radius_km / n, 2.0);
  const auto points = patch(vec3(std::cos(0.384f), 0.0f, std::sin(0.384f)), half, n);
  std::vector<bool> inside(points.size());
  int partial = 0;
  for (size_t k = 0; k < points.size(); ++k) {
    const float pocket = glsl::open_cell_pockets(points[k], 1u, glsl::POCKET_OCTAVES);
    inside[k] = pocket > 0.5f;
    partial += pocket > 0.05f && pocket < 0.95f ? 1 : 0;
  }
  const auto parts = components(inside, n);
  const double share = double(std::count(inside.begin(), inside.end(), true)) / double(points.size());
  INFO("pockets " << parts.sizes.size() << " (" << parts.inside << " inside), share " << share << ", partial "
                  << double(partial) / double(points.size()));
  // Pockets some 530 km apart at half of the places: tens of them, on a few percent of the area.
  CHECK(parts.inside >= 20);
  CHECK(share > 0.03);
  CHECK(share < 0.3);
  // Pockets are larger than 1e4 km^2 (Smalley et al. 2022); the frayed borders break off a few
  // small fragments, which must hold little of the pockets' area.
  long small_area = 0, area = 0;
  for (int size : parts.sizes) {
    area += size;
    small_area += size * pixel_km2 < 1.0e4 ? size : 0;
  }
  INFO("area below 1e4 km2: " << small_area << " of " << area << " points");
  CHECK(small_area * 10 <= area);
  // Sharp: the border's ramp (a tenth of a pocket) holds far fewer points than the pockets.
  CHECK(double(partial) / double(points.size()) < 0.5 * share);
  // In a pocket the deck's closed cells are open ones, outside it they stay.
  const glsl::vec2 in_pocket = glsl::with_pockets(glsl::vec2(0.8f, 0.1f), 1.0f);
  CHECK(in_pocket.x == 0.0f);
  CHECK(in_pocket.y == Approx(0.9f));
  CHECK(glsl::with_pockets(glsl::vec2(0.8f, 0.1f), 0.0f) == glsl::vec2(0.8f, 0.1f));
}

TEST_CASE("open cells dim their cloud to about half the thick cloud's cover, decks' cores and fronts keep theirs",
          "[fast][systems]") {
  // The open cells' factor 1 - o (1 - OPEN_CELL_CLOUD_CONTRAST), times the trades' own.
  CHECK(glsl::cover_contrast(0.0f, 0.0f, 1.0f) == Approx(glsl::OPEN_CELL_CLOUD_CONTRAST).margin(1e-7));
  CHECK(glsl::cover_contrast(0.0f, 0.0f, 0.5f) ==
        Approx(1.0f - 0.5f * (1.0f - glsl::OPEN_CELL_CLOUD_CONTRAST)).margin(1e-7));
  CHECK(glsl::cover_contrast(1.0f, 0.0f, 1.0f) ==
        Approx(glsl::SHALLOW_CONTRAST * glsl::OPEN_CELL_CLOUD_CONTRAST).margin(1e-7));
  // A wall two noise spreads (0.15) above the threshold at the default softness 0.05: cover
  // 1 - (1 - 0.1 x 0.25) exp(-0.25 x 3) = 0.539 (the edge's step shrinks with the contrast) against
  // 1 - 0.9 exp(-3) = 0.955 without the cells.
  const float threshold = 0.45f, softness = 0.05f, wall = threshold + 0.15f;
  const float dimmed = glsl::contrasted_cover(wall, threshold, 1.0f, softness, glsl::cover_contrast(0.0f, 0.0f, 1.0f));
  CHECK(dimmed == Approx(1.0 - 0.975 * std::exp(-0.75)).margin(1e-5));
  CHECK(glsl::contrasted_cover(wall, threshold, 1.0f, softness, glsl::cover_contrast(0.0f, 0.0f, 0.0f)) ==
        Approx(1.0 - 0.9 * std::exp(-3.0)).margin(1e-5));
  // The weight is the open pattern's: all of a cold sector and of a deck's fringe, none of a deck's
  // closed core, which stays as bright as before.
  CHECK(glsl::cell_weights(0.0f, 1.0f).y == 1.0f);
  CHECK(glsl::cell_weights(0.2f, 0.0f).y == Approx(0.5f).margin(1e-6));
  CHECK(glsl::cell_weights(1.0f, 0.0f).y == 0.0f);
}

TEST_CASE("the storm tracks' cold air streaming equatorward over the sea is open cells, poleward air and ascent none",
          "[fast][systems]") {
  // A point at latitude phi and longitude 0, its local north and east.
  const auto at = [](float degrees) {
    const float phi = glm::radians(degrees);
    return glsl::vec3(std::cos(phi), 0.0f, std::sin(phi));
  };
  const auto north_at = [](float degrees) {
    const float phi = glm::radians(degrees);
    return glsl::vec3(-std::sin(phi), 0.0f, std::cos(phi));
  };
  const glsl::vec3 east(0.0f, 1.0f, 0.0f);
  const auto air = [&](float degrees, glsl::vec3 wind, float cyclonic, float sea) {
    return glsl::storm_track_cold_air(at(degrees), glm::radians(degrees), wind, cyclonic, sea);
  };
  for (float sign : {1.0f, -1.0f}) {
    const float lat = 50.0f * sign;
    const glsl::vec3 equatorward = -sign * north_at(lat);
    // Mid-storm-track, still air over the sea, the wind due equatorward: full, at any wind speed.
    CHECK(air(lat, 3.0f * equatorward, 0.0f, 1.0f) == Approx(1.0f).margin(1e-6));
    CHECK(air(lat, 1e-3f * equatorward, 0.0f, 1.0f) == Approx(1.0f).margin(1e-6));
    // Poleward air (warm advection), a west wind (share 0: smoothstep(-0.2, 0.4, 0) = 0.259) and
    // one 30 degrees off due equatorward (share 0.866: full).
    CHECK(air(lat, -equatorward, 0.0f, 1.0f) == 0.0f);
    CHECK(air(lat, east, 0.0f, 1.0f) == Approx(0.259259f).margin(1e-5));
    CHECK(air(lat, std::cos(glm::radians(30.0f)) * equatorward + 0.5f * east, 0.0f, 1.0f) == Approx(1.0f).margin(1e-6));
    // The cyclones' ascent (the cloud deepened to the cirrus level) and the land take it away.
    CHECK(air(lat, equatorward, glsl::ASCENT_FULL, 1.0f) == 0.0f);
    CHECK(air(lat, equatorward, 0.5f * (glsl::ASCENT_ONSET + glsl::ASCENT_FULL), 1.0f) == Approx(0.5f).margin(1e-6));
    CHECK(air(lat, equatorward, 0.0f, 0.0f) == 0.0f);
    CHECK(air(lat, equatorward, 0.0f, 0.25f) == Approx(0.25f).margin(1e-6));
    // Only in the storm tracks: none in the subtropics or the polar caps, full from 40 to 60.
    for (float degrees : {0.0f, 20.0f, 34.0f, 67.0f, 80.0f})
      CHECK(air(sign * degrees, -sign * north_at(sign * degrees), 0.0f, 1.0f) == 0.0f);
    for (float degrees : {41.0f, 45.0f, 59.0f})
      CHECK(air(sign * degrees, -sign * north_at(sign * degrees), 0.0f, 1.0f) == Approx(1.0f).margin(1e-6));
  }
  // No wind: no direction, no open cells.
  CHECK(air(50.0f, glsl::vec3(0.0f), 0.0f, 1.0f) == 0.0f);
}

TEST_CASE("the trades' shallow regime shrinks the cloud's excess and leaves the systems and the mid-latitudes",
          "[fast][systems]") {
  // The contrast: 1 without the regime, SHALLOW_CONTRAST with all of it under sugar and
  // MOAT_CONTRAST of that between the organised patterns' clumps, linear between; a cloudy texel's
  // excess over the threshold shrinks by it, a clear texel keeps its density, and any contrast
  // keeps the order of the cloudy densities.
  for (float organised : {0.0f, 0.5f, 1.0f}) CHECK(glsl::cover_contrast(0.0f, organised, 0.0f) == 1.0f);
  CHECK(glsl::cover_contrast(1.0f, 0.0f, 0.0f) == Approx(glsl::SHALLOW_CONTRAST).margin(1e-7));
  CHECK(glsl::cover_contrast(0.5f, 0.0f, 0.0f) == Approx(0.5f * (1.0f + glsl::SHALLOW_CONTRAST)).margin(1e-7));
  CHECK(glsl::cover_contrast(1.0f, 1.0f, 0.0f) == Approx(glsl::SHALLOW_CONTRAST * glsl::MOAT_CONTRAST).margin(1e-7));
  CHECK(glsl::cover_contrast(1.0f, 0.5f, 0.0f) ==
        Approx(glsl::SHALLOW_CONTRAST * 0.5f * (1.0f + glsl::MOAT_CONTRAST)).margin(1e-7));
  // The contrasted cover: 0 where clear, the plain cover where the contrast is 1 (to the bit), and
  // where it is below 1 the cover of the excess shrunk by it with an edge's step shrunk as much
  // (1 - (1 - c e) exp(-c x / s)): still cloudy however small the excess, soft at its edge as dim
  // cloud is, and in the order of the densities.
  const float threshold = 0.45f, softness = 0.05f;
  for (float d : {0.2f, 0.45f}) CHECK(glsl::contrasted_cover(d, threshold, 1.0f, softness, 0.08f) == 0.0f);
  for (float d : {0.4500001f, 0.5f, 0.6f, 0.9f}) {
    CHECK(glsl::contrasted_cover(d, threshold, 1.0f, softness, 1.0f) ==
          glsl::cover_from_density(d, threshold, 1.0f, softness));
    CHECK(glsl::contrasted_cover(d, threshold, 1.0f, softness, 0.08f) >= 0.08f * glsl::COVER_EDGE);
  }
  CHECK(glsl::contrasted_cover(0.4500001f, threshold, 1.0f, softness, 0.08f) < 0.01f);  // a soft edge
  for (float d : {0.5f, 0.6f, 0.9f})
    CHECK(glsl::contrasted_cover(d, threshold, 1.0f, softness, 0.08f) ==
          Approx(1.0 - (1.0 - 0.08 * glsl::COVER_EDGE) * std::exp(-0.08 * (d - threshold) / softness)).margin(1e-6));
  // Shrinking the density itself would lose a cloudy texel this close to the threshold (the sum
  // rounds to the threshold); shrinking its excess keeps it cloudy.
  CHECK(glsl::cover_from_density(threshold + 0.08f * (0.4500001f - threshold), threshold, 1.0f, softness) == 0.0f);
  for (float c : {0.08f, 0.5f, 1.0f})
    for (int k = 47; k < 100; ++k)
      CHECK(glsl::contrasted_cover(0.01f * k, threshold, 1.0f, softness, c) >
            glsl::contrasted_cover(0.01f * (k - 1), threshold, 1.0f, softness, c));
  // The weight: the whole regime in the tropics where nothing organises the cloud, none beyond 33
  // degrees, none in a comma cloud, an ITCZ cluster or a deck, and cirrus is part of it; the
  // trades' cumulus clumps leave it by the square of their strength (gravel's 0.45 keeps 0.80 of
  // it, the fish's 0.8 0.36, the flowers' 1 none).
  glsl::CloudTypes none{};
  const float degree = float(M_PI) / 180.0f;
  CHECK(glsl::shallow_trades_weight(none, 10.0f * degree, 0.0f, 1.0f) == 1.0f);
  CHECK(glsl::shallow_trades_weight(none, -25.0f * degree, 0.0f, 1.0f) == 1.0f);
  CHECK(glsl::shallow_trades_weight(none, 34.0f * degree, 0.0f, 1.0f) == 0.0f);
  CHECK(glsl::shallow_trades_weight(none, 10.0f * degree, 0.0f, 0.0f) == 0.0f);  // --shallow-trades 0
  CHECK(glsl::shallow_trades_weight(none, 10.0f * degree, 1.0f, 1.0f) == 0.0f);  // a deck
  glsl::CloudTypes front = none, cluster = none, thin = none;
  front.frontal = 1.0f;
  cluster.deep_convection = 1.0f;
  thin.cirrus = 1.0f;
  CHECK(glsl::shallow_trades_weight(front, 20.0f * degree, 0.0f, 1.0f) == 0.0f);
  CHECK(glsl::shallow_trades_weight(cluster, 5.0f * degree, 0.0f, 1.0f) == 0.0f);
  CHECK(glsl::shallow_trades_weight(thin, 15.0f * degree, 0.0f, 1.0f) == 1.0f);
  const glm::vec3 strength = glsl::TRADE_PATTERN_STRENGTH;
  const float kept[3] = {1.0f - 0.45f * 0.45f, 1.0f - 0.8f * 0.8f, 0.0f};
  for (int k = 0; k < 3; ++k) {
    glsl::CloudTypes clump = thin;
    clump.cumulus = strength[k];
    CHECK(glsl::shallow_trades_weight(clump, 15.0f * degree, 0.0f, 1.0f) == Approx(kept[k]).margin(1e-6));
  }
  // An anvil takes three quarters of the regime: its cover contrast is 1 - 0.75 x 0.86 = 0.355,
  // between the cumulus' 0.14 and a system's 1.
  glsl::CloudTypes anvil = thin;
  anvil.anvil = 1.0f;
  CHECK(glsl::shallow_trades_weight(anvil, 5.0f * degree, 0.0f, 1.0f) == Approx(0.75f).margin(1e-6));
  CHECK(glsl::cover_contrast(glsl::shallow_trades_weight(anvil, 5.0f * degree, 0.0f, 1.0f), 0.0f, 0.0f) ==
        Approx(0.355f).margin(1e-6));
  // Half a front's weight, half the regime; the belt falls monotonically from 26 to 33 degrees.
  front.frontal = 0.5f;
  CHECK(glsl::shallow_trades_weight(front, 20.0f * degree, 0.0f, 1.0f) == Approx(0.5f).margin(1e-6));
  float previous = 1.0f;
  for (int k = 0; k <= 70; ++k) {
    const float belt = glsl::trades_belt((26.0f + 0.1f * k) * degree);
    CHECK(belt <= previous);
    previous = belt;
  }
}

TEST_CASE("cirrus streaks lie in the storm tracks and none in the tropics, whose cirrus is the anvils'",
          "[fast][systems]") {
  // cirrus_gate: full from 40 to 60 degrees (0.7-1.05 rad), none within 31.5 degrees of the
  // equator (0.55 rad) or beyond 68.8 (1.2 rad). On a grid of 0.5 degrees by 1 degree the streaks
  // are nowhere within 31 degrees and cover some of the storm tracks (their sheets about half,
  // the streaks' cut a few tenths of that).
  const std::uint32_t seed = 3;
  long tropics = 0, tracks = 0, tracks_cloudy = 0;
  for (int j = -62; j <= 62; ++j)
    for (int i = 0; i < 360; ++i) {
      const double lat = 0.5 * j * M_PI / 180.0, lon = i * M_PI / 180.0;
      const vec3 p(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat));
      ++tropics;
      REQUIRE(glsl::cirrus_streaks(p, float(lat), seed) == 0.0f);
    }
  for (int j = 80; j <= 120; ++j)
    for (int sign : {-1, 1})
      for (int i = 0; i < 360; ++i) {
        const double lat = sign * 0.5 * j * M_PI / 180.0, lon = i * M_PI / 180.0;
        const vec3 p(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat));
        ++tracks;
        tracks_cloudy += glsl::cirrus_streaks(p, float(lat), seed) > 0.5f;
      }
  INFO(tracks_cloudy << " of " << tracks << " storm-track places under a streak; " << tropics << " tropical without");
  CHECK(double(tracks_cloudy) / tracks > 0.02);
  CHECK(double(tracks_cloudy) / tracks < 0.5);
  CHECK(glsl::cirrus_gate(0.0f) == 0.0f);
  CHECK(glsl::cirrus_gate(0.55f) == 0.0f);
  CHECK(glsl::cirrus_gate(0.8f) == 1.0f);
  CHECK(glsl::cirrus_gate(-0.8f) == 1.0f);
  CHECK(glsl::cirrus_gate(1.2f) == 0.0f);
}

TEST_CASE("cirrus streaks run along the latitude circles and are several times longer than wide", "[fast][systems]") {
  // The streaks' noise is Worley noise, whose statistics hardly depend on the direction (a
  // jittered point in every lattice cell), of the point with its north component stretched by s =
  // CIRRUS_STRETCH: a line running north crosses its level sets as often a kilometre as a line
  // through the unstretched noise does over sqrt(sin^2 lat + s^2 cos^2 lat) kilometres, so
  // that many times as often as a line running east (7.0 at 46 degrees). Sampled on a grid of
  // 0.1 degrees, 42-50 degrees north, all longitudes.
  const std::uint32_t seed = 7;
  const int columns = 3600, rows = 80;
  const double step = 0.1 * M_PI / 180.0;
  auto crossing_ratio = [&](auto&& inside) {
    std::vector<std::uint8_t> in(std::size_t(columns) * rows);
    for (int j = 0; j < rows; ++j)
      for (int i = 0; i < columns; ++i) {
        const double lat = (42.0 + 0.1 * j) * M_PI / 180.0, lon = i * step;
        const vec3 p(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat));
        in[std::size_t(j) * columns + i] = inside(p, float(lat));
      }
    long east = 0, north = 0;
    double east_km = 0.0, north_km = 0.0;
    for (int j = 0; j < rows; ++j) {
      const double lat = (42.0 + 0.1 * j) * M_PI / 180.0;
      for (int i = 0; i < columns; ++i) {
        const std::size_t at = std::size_t(j) * columns + i;
        east += in[at] != in[std::size_t(j) * columns + (i + 1) % columns];
        east_km += earth_radius_km * std::cos(lat) * step;
        if (j + 1 < rows) {
          north += in[at] != in[at + columns];
          north_km += earth_radius_km * step;
        }
      }
    }
    INFO("crossings east " << east << ", north " << north);
    CHECK(east > 300);  // a count's sampling error below 6 %
    return (north / north_km) / (east / east_km);
  };
  const double lat = 46.0 * M_PI / 180.0, s = glsl::CIRRUS_STRETCH;
  const double expected = std::sqrt(std::sin(lat) * std::sin(lat) + s * s * std::cos(lat) * std::cos(lat));
  // The streaks' edges, the noise's level CIRRUS_STREAK_EDGES.x: the counts' sampling error is
  // that of about a thousand east crossings, a few per cent, and the latitudes' spread of the
  // expected ratio (6.4-7.6 from 42 to 50 degrees) averages out.
  const double streaks = crossing_ratio([&](vec3 p, float) {
    return glsl::cirrus_streak_noise(p, seed, glsl::CIRRUS_OCTAVES) > glsl::CIRRUS_STREAK_EDGES.x;
  });
  INFO("streak noise: ratio " << streaks << " against " << expected);
  CHECK(streaks > 0.85 * expected);
  CHECK(streaks < 1.15 * expected);
  // The cirrus itself: the sheets' edges, stretched only twofold, add crossings of their own ratio
  // (at most 2), fewer (3 cells a radius against 40 across the streaks): between the two.
  const double cirrus =
      crossing_ratio([&](vec3 p, float latitude) { return glsl::cirrus_streaks(p, latitude, seed) > 0.5f; });
  INFO("cirrus: ratio " << cirrus);
  CHECK(cirrus > 2.0);
  CHECK(cirrus < 1.15 * expected);
}
