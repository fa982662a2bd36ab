#include "io/weather_files.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/input_file.hpp"
#include "core/json.hpp"
#include "core/json_keys.hpp"
#include "core/time.hpp"

namespace nephele::io {

using regional::WeatherError;
using regional::WeatherSample;
using regional::WeatherSeries;

namespace {

// UTC offsets stay within +-18 h (ISO 8601 zone offsets; real zones span -12 h to +14 h). Larger
// ones would carry times out of the years 0000-9999 that parse_utc_time and the messages handle
// (a fuzzed 1e300 s offset made every time the same double, and --time checks meaningless).
constexpr double max_utc_offset_hours = 18;

struct Reader {
  const std::string& source;
  const json::Value& root;
  json::KeyReader keys{[this](const std::string& field, const std::string& message) {
    throw WeatherError(source + ": " + field + ": " + message);
  }};

  [[noreturn]] void fail(const std::string& field, const std::string& message) const { keys.fail(field, message); }
  const json::Value& member(const json::Value& object, const std::string& path, const std::string& key) const {
    return keys.member(object, key, path);
  }
  void within(const std::string& field, double x, double lo, double hi) const {
    if (x >= lo && x <= hi) return;
    std::ostringstream m;
    m << x << " is outside the allowed range " << lo << " to " << hi;
    fail(field, m.str());
  }
  double number(const json::Value& object, const std::string& path, const std::string& key) const {
    return keys.number(member(object, path, key), path + key);
  }
  // An hourly array of numbers; nulls (missing values, NaN in the source) are errors.
  std::vector<double> series(const json::Value& block, const std::string& path, const std::string& key, size_t count,
                             double lo, double hi, bool required = true) const {
    const json::Value* v = block.find(key);
    if (!v) {
      if (required) fail(path + key, "missing");
      return {};
    }
    if (!v->is_array()) fail(path + key, "must be an array");
    const auto& items = v->as_array();
    if (items.size() != count)
      fail(path + key, "has " + std::to_string(items.size()) + " values but 'time' has " + std::to_string(count));
    std::vector<double> out;
    for (size_t i = 0; i < items.size(); ++i) {
      if (!items[i].is_number()) fail(path + key + "[" + std::to_string(i) + "]", "missing value (null or NaN)");
      const double x = items[i].as_number();
      if (x < lo || x > hi) {
        std::ostringstream m;
        m << x << " is outside the allowed range " << lo << " to " << hi;
        fail(path + key + "[" + std::to_string(i) + "]", m.str());
      }
      out.push_back(x);
    }
    return out;
  }
  std::vector<double> times(const json::Value& block, const std::string& path, double offset_seconds) const {
    const json::Value& v = member(block, path, "time");
    if (!v.is_array() || v.as_array().empty()) fail(path + "time", "must be a non-empty array of times");
    std::vector<double> out;
    for (size_t i = 0; i < v.as_array().size(); ++i) {
      const json::Value& t = v.as_array()[i];
      if (!t.is_string()) fail(path + "time[" + std::to_string(i) + "]", "must be a string");
      std::string text = t.as_string();
      if (text.size() >= 11 && text[10] == ' ') text[10] = 'T';  // meteoblue "YYYY-MM-DD HH:MM"
      if (text.empty() || text.back() != 'Z') text += "Z";
      try {
        out.push_back(core::parse_utc_time(text) - offset_seconds);
      } catch (const std::invalid_argument& e) {
        fail(path + "time[" + std::to_string(i) + "]", e.what());
      }
      if (i > 0 && out[i] <= out[i - 1]) fail(path + "time[" + std::to_string(i) + "]", "times must increase");
    }
    return out;
  }
};

}  // namespace

regional::WeatherSeries parse_weather(const std::string& text, const std::string& source) {
  json::Value root;
  try {
    root = json::parse(text);
  } catch (const json::ParseError& e) {
    throw WeatherError(source + ": not valid JSON: " + e.what());
  }
  if (!root.is_object()) throw WeatherError(source + ": the top level must be a JSON object");
  Reader r{source, root};
  WeatherSeries w;
  w.source = source;
  std::vector<double> times, total, low, mid, high, rain, speed, direction, cape, lifted, code;
  // The cloud fields and precipitation, named differently by each provider.
  auto read_clouds = [&](const json::Value& block, const std::string& path, const char* total_key, const char* low_key,
                         const char* mid_key, const char* high_key) {
    const size_t n = times.size();
    total = r.series(block, path, total_key, n, 0, 100);
    low = r.series(block, path, low_key, n, 0, 100);
    mid = r.series(block, path, mid_key, n, 0, 100);
    high = r.series(block, path, high_key, n, 0, 100);
    rain = r.series(block, path, "precipitation", n, 0, 500, false);
  };
  if (root.find("hourly")) {
    // Open-Meteo forecast API: hourly arrays beside 'time'; times are local to utc_offset_seconds.
    w.format = "open-meteo";
    w.latitude_deg = r.number(root, "", "latitude");
    w.longitude_deg = r.number(root, "", "longitude");
    const double offset = root.find("utc_offset_seconds") ? r.number(root, "", "utc_offset_seconds") : 0.0;
    r.within("utc_offset_seconds", offset, -max_utc_offset_hours * 3600, max_utc_offset_hours * 3600);
    const json::Value& hourly = root.at("hourly");
    if (!hourly.is_object()) r.fail("hourly", "must be an object");
    times = r.times(hourly, "hourly.", offset);
    const size_t n = times.size();
    read_clouds(hourly, "hourly.", "cloud_cover", "cloud_cover_low", "cloud_cover_mid", "cloud_cover_high");
    // The convective inputs (docs/convection.md), each optional. Ranges: CAPE is at most a few
    // thousand J/kg even in the strongest outbreaks (about 8000 measured); the lifted index spans
    // about -15 K (extreme instability) to +30 K (winter inversions); WMO code table 4677 has
    // the integer codes 0 to 99.
    cape = r.series(hourly, "hourly.", "cape", n, 0, 10000, false);
    lifted = r.series(hourly, "hourly.", "lifted_index", n, -30, 50, false);
    code = r.series(hourly, "hourly.", "weather_code", n, 0, 99, false);
    for (size_t i = 0; i < code.size(); ++i)
      if (code[i] != std::floor(code[i]))
        r.fail("hourly.weather_code[" + std::to_string(i) + "]", "must be an integer code of WMO table 4677 (0 to 99)");
    // Wind aloft when present, else at 10 m (km/h in Open-Meteo's default units).
    const char* speed_keys[] = {"wind_speed_850hPa", "wind_speed_10m"};
    const char* direction_keys[] = {"wind_direction_850hPa", "wind_direction_10m"};
    for (int k = 0; k < 2 && speed.empty(); ++k) {
      speed = r.series(hourly, "hourly.", speed_keys[k], n, 0, 500, false);
      if (!speed.empty()) {
        direction = r.series(hourly, "hourly.", direction_keys[k], n, 0, 360);
        std::string unit = "km/h";
        if (const json::Value* units = root.find("hourly_units"))
          if (const json::Value* u = units->find(speed_keys[k]); u && u->is_string()) unit = u->as_string();
        const double scale = unit == "m/s"    ? 1.0
                             : unit == "km/h" ? 1.0 / 3.6
                             : unit == "mp/h" ? 0.44704
                             : unit == "kn"   ? 0.514444
                                              : -1.0;
        if (scale < 0)
          r.fail(std::string("hourly_units.") + speed_keys[k], "unit '" + unit + "' not one of km/h, m/s, mp/h, kn");
        for (double& s : speed) s *= scale;
      }
    }
  } else if (root.find("data_1h")) {
    // meteoblue packages: metadata with the position, data_1h with hourly arrays (m/s wind).
    w.format = "meteoblue";
    const json::Value& metadata = r.member(root, "", "metadata");
    w.latitude_deg = r.number(metadata, "metadata.", "latitude");
    w.longitude_deg = r.number(metadata, "metadata.", "longitude");
    const double offset_hours =
        metadata.find("utc_timeoffset") ? r.number(metadata, "metadata.", "utc_timeoffset") : 0.0;
    r.within("metadata.utc_timeoffset", offset_hours, -max_utc_offset_hours, max_utc_offset_hours);
    const double offset = offset_hours * 3600.0;
    const json::Value& hourly = root.at("data_1h");
    times = r.times(hourly, "data_1h.", offset);
    const size_t n = times.size();
    read_clouds(hourly, "data_1h.", "totalcloudcover", "lowclouds", "midclouds", "highclouds");
    speed = r.series(hourly, "data_1h.", "windspeed", n, 0, 150, false);
    if (!speed.empty()) direction = r.series(hourly, "data_1h.", "winddirection", n, 0, 360);
  } else {
    throw WeatherError(source + ": neither an Open-Meteo file (key 'hourly') nor a meteoblue file (key 'data_1h')");
  }
  if (w.latitude_deg < -90 || w.latitude_deg > 90) r.fail("latitude", "outside the allowed range -90 to 90");
  if (w.longitude_deg < -180 || w.longitude_deg > 360) r.fail("longitude", "outside the allowed range -180 to 360");
  for (size_t i = 0; i < times.size(); ++i) {
    WeatherSample s;
    s.time = times[i];
    s.cloud_cover = total[i] / 100;
    s.cloud_low = low[i] / 100;
    s.cloud_mid = mid[i] / 100;
    s.cloud_high = high[i] / 100;
    s.precipitation = rain.empty() ? 0.0 : rain[i];
    if (!speed.empty()) {
      s.has_wind = true;
      s.wind_speed = speed[i];
      s.wind_direction_deg = direction[i];
    }
    if (!cape.empty()) {
      s.has_cape = true;
      s.cape = cape[i];
    }
    if (!lifted.empty()) {
      s.has_lifted_index = true;
      s.lifted_index = lifted[i];
    }
    if (!code.empty()) {
      s.has_weather_code = true;
      s.weather_code = static_cast<int>(code[i]);
    }
    w.hours.push_back(s);
  }
  return w;
}

regional::WeatherSeries read_weather_file(const std::string& path) {
  std::string text;
  try {
    text = core::read_input_file(path);
  } catch (const core::InputFileError& e) {
    throw WeatherError(e.what());
  }
  return parse_weather(text, path);
}

std::vector<regional::WeatherSeries> read_scene_weather(const regional::Scene& scene) {
  std::vector<regional::WeatherSeries> stations;
  for (const auto& path : scene.weather) stations.push_back(read_weather_file(path));
  return stations;
}

}  // namespace nephele::io
