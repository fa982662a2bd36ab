#include "render/sun_position.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace nephele::render {
namespace {

constexpr double degree = M_PI / 180.0;

double wrap_degrees(double a) { return a - 360.0 * std::floor(a / 360.0); }

}  // namespace

long days_from_civil(long y, unsigned m, unsigned d) {
  y -= m <= 2;
  const long era = (y >= 0 ? y : y - 399) / 400;
  const unsigned yoe = static_cast<unsigned>(y - era * 400);
  const unsigned doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
  const unsigned doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return era * 146097 + static_cast<long>(doe) - 719468;
}

double parse_utc_time(const std::string& text) {
  int year = 0, month = 0, day = 0, hour = 0, minute = 0, consumed = 0;
  double second = 0;
  if (std::sscanf(text.c_str(), "%4d-%2d-%2dT%2d:%2d%n", &year, &month, &day, &hour, &minute, &consumed) != 5)
    throw std::invalid_argument("'" + text + "' is not an ISO 8601 time (YYYY-MM-DDTHH:MM[:SS]Z)");
  std::string rest = text.substr(static_cast<size_t>(consumed));
  if (!rest.empty() && rest[0] == ':') {
    int more = 0;
    if (std::sscanf(rest.c_str(), ":%lf%n", &second, &more) != 1)
      throw std::invalid_argument("'" + text + "': bad seconds");
    rest = rest.substr(static_cast<size_t>(more));
  }
  if (rest != "Z" && rest != "+00:00" && rest != "z")
    throw std::invalid_argument("'" + text + "' must be UTC, ending in Z");
  if (month < 1 || month > 12 || day < 1 || day > 31 || hour > 23 || minute > 59 || second < 0 || second >= 61)
    throw std::invalid_argument("'" + text + "' has a field out of range");
  return days_from_civil(year, static_cast<unsigned>(month), static_cast<unsigned>(day)) * 86400.0 +
         hour * 3600.0 + minute * 60.0 + second;
}

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
  const double sin_elevation = std::sin(latitude) * std::sin(declination) +
                               std::cos(latitude) * std::cos(declination) * std::cos(hour_angle);
  const double elevation = std::asin(std::clamp(sin_elevation, -1.0, 1.0));
  const double azimuth = std::atan2(-std::cos(declination) * std::sin(hour_angle),
                                    std::sin(declination) * std::cos(latitude) -
                                        std::cos(declination) * std::cos(hour_angle) * std::sin(latitude));
  return {elevation / degree, wrap_degrees(azimuth / degree), declination / degree};
}

}  // namespace nephele::render
