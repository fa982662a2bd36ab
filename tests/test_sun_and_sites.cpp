// Sun position, time parsing and the named viewpoints.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

#include "core/time.hpp"
#include "regional/sites.hpp"
#include "render/sun_position.hpp"

using namespace nephele;

namespace {

// The sun's position uses the Astronomical Almanac's low-precision formulas, good to 0.01 deg
// (1950 to 2050); their obliquity for 2026 (23.4351 deg) is 0.001 deg from the 23.436 deg the
// tests expect, and UT for TT moves the sun 0.0003 deg. The published solstice and equinox times
// are to the minute (half a minute: nothing at the solstice, where the declination is stationary,
// 0.0001 deg at the equinox at 0.017 deg per hour). The checks below allow 2 to 3 times that.
constexpr double kAlmanacDeg = 0.01;
constexpr double kObliquityDeg = 0.001;
// Declination at the June solstice: kAlmanacDeg + kObliquityDeg = 0.011; 0.02 leaves a factor 1.8.
constexpr double kSolsticeDeg = 0.02;
static_assert(kSolsticeDeg >= kAlmanacDeg + kObliquityDeg);
// Declination at the March equinox (expected 0, no obliquity term): kAlmanacDeg and half a minute
// of the published time; 0.03 is 3x looser (kept as set).
constexpr double kEquinoxDeg = 0.03;
static_assert(kEquinoxDeg >= kAlmanacDeg + 0.5 / 60 * 0.017);
// The midsummer culmination at Bern, 90 - lat + 23.436: kAlmanacDeg, kObliquityDeg, the
// declination's change in the 3 hours from the solstice to noon (below 0.0001 deg) and the
// one-minute sampling (the best minute lies within half a minute of the culmination, where the
// elevation is stationary: below 0.001 deg); 0.03 leaves a factor 2.5.
constexpr double kCulminationDeg = 0.03;
static_assert(kCulminationDeg >= kAlmanacDeg + kObliquityDeg + 0.001);
// Its azimuth: at culmination the azimuth turns by 15 deg/h cos(dec) / sin(lat - dec) = 0.57
// deg per minute at Bern on midsummer, so the best minute is within 0.29 deg of 180; the
// formulas' 0.01 deg in hour angle adds 2.3 x 0.01. 1 deg leaves a factor 3.
constexpr double kCulminationAzimuthDeg = 1.0;
static_assert(kCulminationAzimuthDeg >= 0.5 * 0.575 + 2.3 * kAlmanacDeg);
// A point of the 16-point compass covers 22.5 deg, half of it either side.
constexpr double kCompassHalfSectorDeg = 11.25;
// Gurten to Solothurn: 33.1 km on the sphere (GeographicLib's WGS84 geodesic differs by a few
// tenths of a percent). The check is of units and of the pair of points, not of GeographicLib's
// accuracy (nanometres): +- 1500 m is a choice (empirical), not derived.
constexpr double kGurtenSolothurnM = 33000;
constexpr double kDistanceCheckM = 1500;
// Built-in site coordinates against the reference table (tests/data/sites.csv, with its sources): both
// are written with 5 decimals and the same decimal text gives the same double, so equal values
// agree exactly; 1e-5 deg (one unit of the last decimal, 1.1 m north-south) is the table's
// precision, not a rounding bound.
constexpr double kSiteCoordinateDeg = 1e-5;

}  // namespace

TEST_CASE("ISO 8601 UTC times parse to Unix seconds and bad ones are refused", "[fast][sun]") {
  CHECK(core::parse_utc_time("1970-01-01T00:00Z") == 0.0);
  CHECK(core::parse_utc_time("2000-01-01T12:00:00Z") == 946728000.0);
  CHECK(core::parse_utc_time("2026-06-21T16:00Z") == 1782057600.0);
  CHECK_THROWS(core::parse_utc_time("2026-06-21 16:00"));
  CHECK_THROWS(core::parse_utc_time("2026-06-21T16:00+02:00"));
  CHECK_THROWS(core::parse_utc_time("2026-13-01T00:00Z"));
  CHECK_THROWS(core::parse_utc_time("tomorrow"));
}

TEST_CASE("ISO 8601 UTC times of the years 0000 to 9999 parse without 64-bit nanosecond overflow", "[fast][sun]") {
  // Year 0 to 1970: 719528 days of the proleptic Gregorian calendar, times 86400 s.
  CHECK(core::parse_utc_time("0000-01-01T00:00Z") == -719528.0 * 86400);
  // The last second of 9999: one second before 10000-01-01, 2932897 days after 1970.
  CHECK(core::parse_utc_time("9999-12-31T23:59:59Z") == 2932897.0 * 86400 - 1);
  CHECK(core::parse_utc_time("0226-06-22T19:00Z") == -55020402000.0);  // a fuzzer's find (tests/fuzz)
  // Whole minutes stay whole seconds where nanoseconds since 1970 would not fit 64 bits.
  CHECK(core::parse_utc_time("0901-12-31T23:59Z") == -33702825660.0);
  CHECK(core::parse_utc_time("0901-12-31T23:59:59.5Z") == -33702825600.5);
}

TEST_CASE("the sun stands over the tropic at the June solstice and over the equator at the equinox", "[fast][sun]") {
  // June solstice 2026: June 21 08:24 UTC; March equinox 2026: March 20 14:46 UTC (published
  // times). The Almanac formulas are good to about 0.01 deg; the obliquity is 23.436 deg.
  const auto solstice = render::sun_position(core::parse_utc_time("2026-06-21T08:24Z"), 0, 0);
  CHECK(solstice.declination_deg == Approx(23.436).epsilon(0).margin(kSolsticeDeg));
  const auto equinox = render::sun_position(core::parse_utc_time("2026-03-20T14:46Z"), 0, 0);
  CHECK(equinox.declination_deg == Approx(0.0).epsilon(0).margin(kEquinoxDeg));  // 0.017 deg per hour near the equinox
}

TEST_CASE("at Bern the midsummer sun culminates at 90 - latitude + 23.44 deg due south", "[fast][sun]") {
  const double lat = 46.94806, lon = 7.44750;
  double best = -90, best_azimuth = 0;
  const double day = core::parse_utc_time("2026-06-21T00:00Z");
  for (int minute = 0; minute < 24 * 60; ++minute) {
    const auto s = render::sun_position(day + minute * 60.0, lat, lon);
    if (s.elevation_deg > best) {
      best = s.elevation_deg;
      best_azimuth = s.azimuth_deg;
    }
  }
  // One minute of time moves the culminating sun by < 0.001 deg in elevation.
  CHECK(best == Approx(90 - lat + 23.436).epsilon(0).margin(kCulminationDeg));
  CHECK(best_azimuth == Approx(180).epsilon(0).margin(kCulminationAzimuthDeg));  // within half a minute: 0.29 deg
  const auto night = render::sun_position(core::parse_utc_time("2026-06-21T23:00Z"), lat, lon);
  CHECK(night.elevation_deg < 0);
}

TEST_CASE("the views run from Gurten north-north-east and from Bantiger south-west", "[fast][sites]") {
  const auto gurten = regional::find_viewpoint("gurten");
  const auto bantiger = regional::find_viewpoint("bantiger");
  REQUIRE(gurten);
  REQUIRE(bantiger);
  CHECK(gurten->towards == "solothurn");
  CHECK(bantiger->towards == "fribourg");
  // North-north-east is 22.5 deg; the geodesic azimuth to Solothurn (12.4 deg) lies within its
  // sector (from 11.25 deg); the lower bound checked is north itself, looser than the sector.
  CHECK(gurten->heading_deg > 0.0);
  CHECK(gurten->heading_deg < 22.5 + kCompassHalfSectorDeg);
  // South-west is 225 deg.
  CHECK(bantiger->heading_deg > 225 - kCompassHalfSectorDeg);
  CHECK(bantiger->heading_deg < 225 + kCompassHalfSectorDeg);
  CHECK_FALSE(regional::find_viewpoint("matterhorn"));
  // Gurten to Solothurn is about 33 km.
  CHECK(regional::geodesic_distance_m(46.91722, 7.44361, 47.20833, 7.53722) ==
        Approx(kGurtenSolothurnM).epsilon(0).margin(kDistanceCheckM));
}

TEST_CASE("the built-in coordinates match the reference table of tests/data/sites.csv", "[fast][sites]") {
  std::ifstream csv(std::string(NEPHELE_SOURCE_DIR) + "/tests/data/sites.csv");
  REQUIRE(csv);
  std::string line;
  int matched = 0;
  while (std::getline(csv, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::stringstream row(line);
    std::string name, lat, lon;
    std::getline(row, name, ',');
    std::getline(row, lat, ',');
    std::getline(row, lon, ',');
    auto check = [&](const std::string& prefix, double la, double lo) {
      if (name.rfind(prefix, 0) != 0) return;
      CHECK(std::stod(lat) == Approx(la).epsilon(0).margin(kSiteCoordinateDeg));
      CHECK(std::stod(lon) == Approx(lo).epsilon(0).margin(kSiteCoordinateDeg));
      ++matched;
    };
    check("Gurten", regional::find_viewpoint("gurten")->site.latitude_deg,
          regional::find_viewpoint("gurten")->site.longitude_deg);
    check("Bantiger summit", regional::find_viewpoint("bantiger")->site.latitude_deg,
          regional::find_viewpoint("bantiger")->site.longitude_deg);
    check("Solothurn", regional::find_city("solothurn")->latitude_deg, regional::find_city("solothurn")->longitude_deg);
    check("Fribourg", regional::find_city("fribourg")->latitude_deg, regional::find_city("fribourg")->longitude_deg);
    check("Bern (city", regional::find_city("bern")->latitude_deg, regional::find_city("bern")->longitude_deg);
  }
  CHECK(matched == 5);
}
