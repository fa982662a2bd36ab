#pragma once
// Weather files: Open-Meteo and meteoblue JSON of one station, strict (unknown formats, missing
// or out-of-range fields, duplicate keys, invalid UTF-8 and oversized files are refused with the
// file and field named; exit code 2 through regional::WeatherError). docs/layers.md has the fields.
#include <string>
#include <vector>

#include "regional/scene.hpp"
#include "regional/weather.hpp"

namespace nephele::io {

// Reads either format (recognised by its keys); throws regional::WeatherError naming file and field.
regional::WeatherSeries read_weather_file(const std::string& path);
regional::WeatherSeries parse_weather(const std::string& json_text, const std::string& source_name);
// The weather files a scene names, in its order.
std::vector<regional::WeatherSeries> read_scene_weather(const regional::Scene& scene);

}  // namespace nephele::io
