#pragma once
// Hourly weather of one station (read from Open-Meteo or meteoblue JSON by src/io/weather_files).
#include <stdexcept>
#include <string>
#include <vector>

#include "core/error.hpp"

namespace nephele::regional {

// Bad weather input: names the file, the field and the allowed range (exit code 2).
class WeatherError : public core::InputError {
 public:
  using core::InputError::InputError;
};

// One hour of weather; cloud fractions in [0, 1], precipitation in mm/h, wind in m/s and
// degrees (meteorological: the direction the wind comes from, clockwise from north).
struct WeatherSample {
  double time = 0;  // UTC, seconds since 1970
  double cloud_cover = 0, cloud_low = 0, cloud_mid = 0, cloud_high = 0;
  double precipitation = 0;
  double wind_speed = 0, wind_direction_deg = 0;
  bool has_wind = false;
  // What says whether the air is unstable (Open-Meteo's hourly `cape`, `lifted_index` and
  // `weather_code`; docs/convection.md); each is optional in a file, and has_* says whether it
  // was there. CAPE in J/kg, the lifted index in K, the code from WMO code table 4677.
  double cape = 0, lifted_index = 0;
  int weather_code = 0;
  bool has_cape = false, has_lifted_index = false, has_weather_code = false;
  // Whether nearly total low cover in calm air may be radiation fog. A satellite cover cannot
  // tell fog from low cloud and says nothing of the wind: its samples (weather_field.hpp) set
  // this false, and their overcast is a stratus deck, not fog round the camera.
  bool may_be_fog = true;
};

struct WeatherSeries {
  std::string source;  // file name
  std::string format;  // "open-meteo" or "meteoblue"
  double latitude_deg = 0, longitude_deg = 0;
  std::vector<WeatherSample> hours;  // increasing time

  // Linear interpolation between the hours around `time`; throws WeatherError outside the range.
  WeatherSample at(double time) const;
  // Hours from `time` (exclusive) up to `time + horizon_hours` (inclusive).
  std::vector<WeatherSample> ahead(double time, double horizon_hours) const;
};

// The files are read by src/io/weather_files.hpp.

// The largest precipitation rate (mm/h) of the hours up to within_hours after `from` (Unix
// seconds): the layer rules' and the convection rules' "rain within N hours".
double max_precipitation(const std::vector<WeatherSample>& hours, double within_hours, double from);

}  // namespace nephele::regional
