#include "io/profile_files.hpp"

#include <sstream>

#include "core/error.hpp"
#include "core/input_file.hpp"
#include "params/table.hpp"
#include "params/values.hpp"

namespace nephele::io {
namespace {

std::string trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

}  // namespace

cover::LatitudeProfile parse_profile_csv(const std::string& text, const std::string& name) {
  std::vector<double> latitudes, fractions;
  std::istringstream lines(text);
  std::string line;
  bool header_allowed = true;
  for (int number = 1; std::getline(lines, line); ++number) {
    const std::string row = trim(line);
    if (row.empty() || row[0] == '#') continue;
    const auto comma = row.find(',');
    const std::string where = name + ": line " + std::to_string(number);
    if (comma == std::string::npos || row.find(',', comma + 1) != std::string::npos)
      throw core::InputError(where, row, "two comma-separated fields: latitude_deg,fraction", "is not a row");
    const std::string latitude_text = trim(row.substr(0, comma)), fraction_text = trim(row.substr(comma + 1));
    if (header_allowed && latitude_text == "latitude_deg" && fraction_text == "fraction") {
      header_allowed = false;
      continue;
    }
    header_allowed = false;
    const double latitude = params::parse_number(where + ": latitude_deg", latitude_text, -90.0, 90.0, false);
    const double fraction = params::parse_number(where + ": fraction", fraction_text, 0.0, 1.0, false);
    if (!latitudes.empty() && latitude <= latitudes.back())
      throw core::InputError(
          where + ": latitude_deg", latitude_text,
          "above the previous row's " + std::to_string(latitudes.back()) + " (latitudes strictly increasing)",
          "is not increasing");
    latitudes.push_back(latitude);
    fractions.push_back(fraction);
  }
  if (latitudes.empty())
    throw core::InputError(name, "no rows", "at least one row latitude_deg,fraction", "has no profile");
  return cover::table_profile(name, std::move(latitudes), std::move(fractions));
}

cover::LatitudeProfile read_profile_csv(const std::string& path) {
  std::string text;
  try {
    text = core::read_input_file(path);
  } catch (const core::InputFileError& e) {
    throw core::InputError(std::string(e.what()) + " (--profile: earth, flat or a CSV file)");
  }
  return parse_profile_csv(text, path);
}

cover::LatitudeProfile profile_from_option(const std::string& value) {
  if (value == "earth") return cover::earth_profile();
  if (value == "flat") return cover::flat_profile();
  if (value.empty()) throw core::InputError(params::cover::profile.option(), value, "earth, flat or a CSV file");
  return read_profile_csv(value);
}

}  // namespace nephele::io
