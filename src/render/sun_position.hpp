#pragma once
// Position of the sun seen from the Earth.
#include <string>

namespace nephele::render {

struct SunPosition {
  double elevation_deg;   // above the astronomical horizon, no refraction
  double azimuth_deg;     // clockwise from north
  double declination_deg;
};

// Low-precision formulas of the Astronomical Almanac (as used by Michalsky, "The Astronomical
// Almanac's algorithm for approximate solar position (1950-2050)", Solar Energy 40(3), 1988):
// about 0.01 deg for 1950-2050, refraction not included. `unix_seconds`: UTC.
SunPosition sun_position(double unix_seconds, double latitude_deg, double longitude_deg);

// Parses ISO 8601 UTC date-times: YYYY-MM-DDTHH:MM[:SS](Z|+00:00); throws std::invalid_argument.
double parse_utc_time(const std::string& text);
// Days since 1970-01-01 of a proleptic Gregorian date (Howard Hinnant's civil-days formula).
long days_from_civil(long year, unsigned month, unsigned day);

}  // namespace nephele::render
