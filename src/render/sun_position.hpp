#pragma once
// Position of the sun seen from the Earth.

namespace nephele::render {

struct SunPosition {
  double elevation_deg;  // above the astronomical horizon, no refraction
  double azimuth_deg;    // clockwise from north
  double declination_deg;
};

// Low-precision formulas of the Astronomical Almanac (as used by Michalsky, "The Astronomical
// Almanac's algorithm for approximate solar position (1950-2050)", Solar Energy 40(3), 1988):
// about 0.01 deg for 1950-2050, refraction not included. `unix_seconds`: UTC.
SunPosition sun_position(double unix_seconds, double latitude_deg, double longitude_deg);

}  // namespace nephele::render
