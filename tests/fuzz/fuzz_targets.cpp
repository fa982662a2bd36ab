#include "io/cloud_model_files.hpp"
#include "io/profile_files.hpp"
#include "io/scene_files.hpp"
#include "io/weather_files.hpp"
#include "fuzz_targets.hpp"

#include <cmath>
#include <cstdlib>

#include "core/error.hpp"
#include "core/json.hpp"
#include "core/number_text.hpp"
#include "core/printable_text.hpp"
#include "core/time.hpp"
#include "model/cloud_model.hpp"
#include "regional/scene.hpp"
#include "regional/weather.hpp"

namespace nephele::fuzz {
namespace {

std::string text_of(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

void require(bool condition, const std::string& what) {
  if (!condition) throw Finding(what);
}

// Floor division: the minute that a time in seconds falls in, as format_utc_minutes drops seconds.
long long minute_start(double seconds) {
  const long long s = static_cast<long long>(std::floor(seconds));
  return (s >= 0 ? s / 60 : -((-s + 59) / 60)) * 60;
}

}  // namespace

void json_input(const std::uint8_t* data, std::size_t size) {
  json::Value value;
  try {
    value = json::parse(text_of(data, size));
  } catch (const json::ParseError&) {
    return;
  }
  // What the writer writes, the parser reads back to the same value (compared by its writing).
  const std::string indented = json::write(value, 2);
  require(json::write(json::parse(indented), 2) == indented, "json: indented output does not read back");
  const std::string compact = json::write(value, 0);
  require(json::write(json::parse(compact), 0) == compact, "json: compact output does not read back");
}

void time_input(const std::uint8_t* data, std::size_t size) {
  const std::string text = text_of(data, size);
  double t = 0;
  try {
    t = core::parse_utc_time(text);
  } catch (const std::invalid_argument&) {
    return;
  }
  require(std::isfinite(t), "time: '" + text + "' gave a non-finite time");
  // The minutes written for an accepted time read back as the start of its minute.
  const std::string minutes = core::format_utc_minutes(t);
  // 10000-01-01T00:00Z, 2932897 days after 1970: the last fraction of a second of 9999 rounds up
  // to it as a double (30 us apart there), and the minutes have a 5-digit year that is no input.
  constexpr double year_10000 = 2932897.0 * 86400;
  if (t >= year_10000) {
    require(minutes == "10000-01-01T00:00Z", "time: '" + text + "' formats as '" + minutes + "'");
    return;
  }
  double back = 0;
  try {
    back = core::parse_utc_time(minutes);
  } catch (const std::invalid_argument& e) {
    throw Finding("time: '" + text + "' formats as '" + minutes + "', which does not parse: " + e.what());
  }
  require(back == static_cast<double>(minute_start(t)),
          "time: '" + text + "' formats as '" + minutes + "', which is not the start of its minute");
}

void scene_input(const std::uint8_t* data, std::size_t size) {
  try {
    const regional::Scene scene = io::parse_scene(text_of(data, size), "fuzz-scene.json", "base");
    regional::validate_scene(scene, "fuzz-scene.json");  // an accepted scene stays valid
  } catch (const regional::SceneError&) {
  }
}

void weather_input(const std::uint8_t* data, std::size_t size) {
  regional::WeatherSeries series;
  try {
    series = io::parse_weather(text_of(data, size), "fuzz-weather.json");
  } catch (const regional::WeatherError&) {
    return;
  }
  require(!series.hours.empty(), "weather: accepted without hours");
  for (std::size_t i = 1; i < series.hours.size(); ++i)
    require(series.hours[i].time > series.hours[i - 1].time, "weather: accepted with times that do not increase");
  // What `nephele render` does with a series: samples inside its range (interpolated between
  // the first two hours), and an error naming the range for a time after it.
  const double first = series.hours.front().time, last = series.hours.back().time;
  const double inside = series.hours.size() > 1 ? 0.5 * (first + series.hours[1].time) : first;
  for (const double t : {first, inside, last}) {
    const regional::WeatherSample s = series.at(t);
    require(std::isfinite(s.cloud_cover) && std::isfinite(s.wind_speed) && std::isfinite(s.wind_direction_deg),
            "weather: non-finite sample inside the range");
  }
  bool refused = false;
  try {
    series.at(last + 3600);
  } catch (const regional::WeatherError&) {
    refused = true;
  }
  require(refused, "weather: a time an hour after the last one was not refused");
  series.ahead(first, 6);
}

void cloud_model_input(const std::uint8_t* data, std::size_t size) {
  model::CloudModel m;
  try {
    m = io::parse_cloud_model(text_of(data, size), "fuzz.cloud.json");
  } catch (const core::InputError&) {
    return;
  }
  // An accepted model stays valid, and what is written for it reads back to the same model.
  model::validate(m, "fuzz.cloud.json");
  const std::string written = io::write_cloud_model(m);
  require(io::write_cloud_model(io::parse_cloud_model(written, "written")) == written,
          "cloud model: the written model does not read back");
}

void profile_input(const std::uint8_t* data, std::size_t size) {
  try {
    const cover::LatitudeProfile profile = io::parse_profile_csv(text_of(data, size), "fuzz.csv");
    (void)profile;
  } catch (const core::InputError&) {
  }
}

void text_input(const std::uint8_t* data, std::size_t size) {
  const std::string text = text_of(data, size);
  // The number scanner: a text it takes is a whole number strtod reads to its end, within the
  // length bound; parse_decimal agrees with it.
  for (const core::NumberForm form : {core::NumberForm::integer, core::NumberForm::real}) {
    const bool taken = core::is_decimal_number(text, form);
    require(taken == core::parse_decimal(text, form).has_value(), "parse_decimal disagrees with is_decimal_number");
    if (!taken) continue;
    require(text.size() <= core::max_number_text_length, "a number longer than the bound was taken");
    char* end = nullptr;
    std::strtod(text.c_str(), &end);
    require(end == text.c_str() + text.size(), "strtod does not read the whole number '" + text + "'");
  }
  // Messages: no control byte survives, and escaping the result again changes nothing.
  for (const bool keep_lines : {false, true}) {
    const std::string shown = core::printable(text, core::max_shown_value_bytes, keep_lines);
    for (const char c : shown) {
      const auto byte = static_cast<unsigned char>(c);
      require(byte >= 0x20 || (keep_lines && (c == '\n' || c == '\t')), "a control byte in a printable text");
      require(byte != 0x7F, "DEL in a printable text");
    }
    require(core::printable(shown, shown.size() + 1, keep_lines) == shown, "printable is not idempotent");
  }
}

const std::vector<Target>& targets() {
  static const std::vector<Target> all = {{"json", json_input},
                                          {"time", time_input},
                                          {"scene", scene_input},
                                          {"weather", weather_input},
                                          {"cloud_model", cloud_model_input},
                                          {"profile", profile_input},
                                          {"text", text_input}};
  return all;
}

}  // namespace nephele::fuzz
