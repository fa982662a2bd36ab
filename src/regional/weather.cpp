#include "regional/weather.hpp"

#include <algorithm>
#include <cmath>

#include "core/time.hpp"

namespace nephele::regional {

WeatherSample WeatherSeries::at(double time) const {
  if (hours.empty()) throw WeatherError(source + ": no hours");
  if (time < hours.front().time || time > hours.back().time)
    throw WeatherError(source + ": --time " + core::format_utc_minutes(time) + " is outside the file's range " +
                       core::format_utc_minutes(hours.front().time) + " to " +
                       core::format_utc_minutes(hours.back().time));
  size_t i = 0;
  while (i + 1 < hours.size() && hours[i + 1].time < time) ++i;
  if (i + 1 >= hours.size() || hours[i].time == time) return hours[i];
  const WeatherSample& a = hours[i];
  const WeatherSample& b = hours[i + 1];
  const double t = (time - a.time) / (b.time - a.time);
  auto mix = [t](double x, double y) { return x + (y - x) * t; };
  WeatherSample s = a;
  s.time = time;
  s.cloud_cover = mix(a.cloud_cover, b.cloud_cover);
  s.cloud_low = mix(a.cloud_low, b.cloud_low);
  s.cloud_mid = mix(a.cloud_mid, b.cloud_mid);
  s.cloud_high = mix(a.cloud_high, b.cloud_high);
  s.precipitation = mix(a.precipitation, b.precipitation);
  s.wind_speed = mix(a.wind_speed, b.wind_speed);
  s.cape = mix(a.cape, b.cape);
  s.lifted_index = mix(a.lifted_index, b.lifted_index);
  // A code names a state, not an amount: the nearer hour's (the earlier one at half past).
  s.weather_code = t <= 0.5 ? a.weather_code : b.weather_code;
  // Wind direction: interpolate the vector, not the angle (350 and 10 degrees average to 0).
  const double ra = a.wind_direction_deg * M_PI / 180, rb = b.wind_direction_deg * M_PI / 180;
  s.wind_direction_deg = std::atan2(mix(std::sin(ra), std::sin(rb)), mix(std::cos(ra), std::cos(rb))) * 180 / M_PI;
  if (s.wind_direction_deg < 0) s.wind_direction_deg += 360;
  return s;
}

std::vector<WeatherSample> WeatherSeries::ahead(double time, double horizon_hours) const {
  std::vector<WeatherSample> out;
  for (const auto& h : hours)
    if (h.time > time && h.time <= time + horizon_hours * 3600.0) out.push_back(h);
  return out;
}

double max_precipitation(const std::vector<WeatherSample>& hours, double within_hours, double from) {
  double m = 0;
  for (const auto& h : hours)
    if (h.time <= from + within_hours * 3600) m = std::max(m, h.precipitation);
  return m;
}

}  // namespace nephele::regional
