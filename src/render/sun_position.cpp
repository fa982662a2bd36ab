#include "render/sun_position.hpp"

#include <algorithm>
#include <cmath>

namespace nephele::render {
namespace {

constexpr double degree = M_PI / 180.0;

double wrap_degrees(double a) { return a - 360.0 * std::floor(a / 360.0); }

}  // namespace

SunPosition sun_position(double unix_seconds, double latitude_deg, double longitude_deg) {
  // Days from J2000.0 (2000-01-01 12:00 TT ~ UT here; the 69 s difference moves the sun 0.0003 deg).
  const double n = unix_seconds / 86400.0 - 10957.5;
  const double hours_ut = std::fmod(unix_seconds / 3600.0, 24.0);
  const double mean_longitude = wrap_degrees(280.460 + 0.9856474 * n);
  const double mean_anomaly = wrap_degrees(357.528 + 0.9856003 * n) * degree;
  const double ecliptic_longitude =
      (mean_longitude + 1.915 * std::sin(mean_anomaly) + 0.020 * std::sin(2 * mean_anomaly)) * degree;
  const double obliquity = (23.439 - 0.0000004 * n) * degree;
  const double right_ascension =
      std::atan2(std::cos(obliquity) * std::sin(ecliptic_longitude), std::cos(ecliptic_longitude));
  const double declination = std::asin(std::sin(obliquity) * std::sin(ecliptic_longitude));
  const double gmst_hours = 6.697375 + 0.0657098242 * n + hours_ut;
  const double local_sidereal = wrap_degrees(gmst_hours * 15.0 + longitude_deg) * degree;
  const double hour_angle = local_sidereal - right_ascension;
  const double latitude = latitude_deg * degree;
  const double sin_elevation =
      std::sin(latitude) * std::sin(declination) + std::cos(latitude) * std::cos(declination) * std::cos(hour_angle);
  const double elevation = std::asin(std::clamp(sin_elevation, -1.0, 1.0));
  const double azimuth = std::atan2(
      -std::cos(declination) * std::sin(hour_angle),
      std::sin(declination) * std::cos(latitude) - std::cos(declination) * std::cos(hour_angle) * std::sin(latitude));
  return {elevation / degree, wrap_degrees(azimuth / degree), declination / degree};
}

}  // namespace nephele::render
