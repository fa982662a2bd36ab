// Sun position, time parsing and the named viewpoints.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

#include "core/time.hpp"
#include "regional/sites.hpp"
#include "render/sun_position.hpp"

using namespace nephele;

TEST_CASE("ISO 8601 UTC times parse to Unix seconds and bad ones are refused", "[sun]") {
  CHECK(core::parse_utc_time("1970-01-01T00:00Z") == 0.0);
  CHECK(core::parse_utc_time("2000-01-01T12:00:00Z") == 946728000.0);
  CHECK(core::parse_utc_time("2026-06-21T16:00Z") == 1782057600.0);
  CHECK_THROWS(core::parse_utc_time("2026-06-21 16:00"));
  CHECK_THROWS(core::parse_utc_time("2026-06-21T16:00+02:00"));
  CHECK_THROWS(core::parse_utc_time("2026-13-01T00:00Z"));
  CHECK_THROWS(core::parse_utc_time("tomorrow"));
}

TEST_CASE("ISO 8601 UTC times of the years 0000 to 9999 parse without 64-bit nanosecond overflow", "[sun]") {
  // Year 0 to 1970: 719528 days of the proleptic Gregorian calendar, times 86400 s.
  CHECK(core::parse_utc_time("0000-01-01T00:00Z") == -719528.0 * 86400);
  // The last second of 9999: one second before 10000-01-01, 2932897 days after 1970.
  CHECK(core::parse_utc_time("9999-12-31T23:59:59Z") == 2932897.0 * 86400 - 1);
  CHECK(core::parse_utc_time("0226-06-22T19:00Z") == -55020402000.0);  // a fuzzer's find (tests/fuzz)
  // Whole minutes stay whole seconds where nanoseconds since 1970 would not fit 64 bits.
  CHECK(core::parse_utc_time("0901-12-31T23:59Z") == -33702825660.0);
  CHECK(core::parse_utc_time("0901-12-31T23:59:59.5Z") == -33702825600.5);
}

TEST_CASE("the sun stands over the tropic at the June solstice and over the equator at the equinox", "[sun]") {
  // June solstice 2026: June 21 08:24 UTC; March equinox 2026: March 20 14:46 UTC (published
  // times). The Almanac formulas are good to about 0.01 deg; the obliquity is 23.436 deg.
  const auto solstice = render::sun_position(core::parse_utc_time("2026-06-21T08:24Z"), 0, 0);
  CHECK(solstice.declination_deg == Approx(23.436).margin(0.02));
  const auto equinox = render::sun_position(core::parse_utc_time("2026-03-20T14:46Z"), 0, 0);
  CHECK(equinox.declination_deg == Approx(0.0).margin(0.03));  // 0.017 deg per hour near the equinox
}

TEST_CASE("at Bern the midsummer sun culminates at 90 - latitude + 23.44 deg due south", "[sun]") {
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
  CHECK(best == Approx(90 - lat + 23.436).margin(0.03));
  CHECK(best_azimuth == Approx(180).margin(1.0));  // within a minute of culmination: 0.3 deg/min
  const auto night = render::sun_position(core::parse_utc_time("2026-06-21T23:00Z"), lat, lon);
  CHECK(night.elevation_deg < 0);
}

TEST_CASE("the views run from Gurten north-north-east and from Bantiger south-west", "[sites]") {
  const auto gurten = regional::find_viewpoint("gurten");
  const auto bantiger = regional::find_viewpoint("bantiger");
  REQUIRE(gurten);
  REQUIRE(bantiger);
  CHECK(gurten->towards == "solothurn");
  CHECK(bantiger->towards == "fribourg");
  // North-north-east is 22.5 deg; the geodesic azimuth to Solothurn lies within its sector.
  CHECK(gurten->heading_deg > 0.0);
  CHECK(gurten->heading_deg < 33.75);
  // South-west is 225 deg.
  CHECK(bantiger->heading_deg > 213.75);
  CHECK(bantiger->heading_deg < 236.25);
  CHECK_FALSE(regional::find_viewpoint("matterhorn"));
  // Gurten to Solothurn is about 32 km.
  CHECK(regional::geodesic_distance_m(46.91722, 7.44361, 47.20833, 7.53722) == Approx(33000).margin(1500));
}

TEST_CASE("the built-in coordinates match the reference table when it is present", "[sites]") {
  std::ifstream csv(std::string(NEPHELE_SOURCE_DIR) + "/../shared/data/sites.csv");
  if (!csv) {
    WARN("../shared/data/sites.csv not present; skipped");
    return;
  }
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
      CHECK(std::stod(lat) == Approx(la).margin(1e-5));
      CHECK(std::stod(lon) == Approx(lo).margin(1e-5));
      ++matched;
    };
    check("Gurten", regional::find_viewpoint("gurten")->site.latitude_deg, regional::find_viewpoint("gurten")->site.longitude_deg);
    check("Bantiger summit", regional::find_viewpoint("bantiger")->site.latitude_deg, regional::find_viewpoint("bantiger")->site.longitude_deg);
    check("Solothurn", regional::find_city("solothurn")->latitude_deg, regional::find_city("solothurn")->longitude_deg);
    check("Fribourg", regional::find_city("fribourg")->latitude_deg, regional::find_city("fribourg")->longitude_deg);
    check("Bern (city", regional::find_city("bern")->latitude_deg, regional::find_city("bern")->longitude_deg);
  }
  CHECK(matched == 5);
}
