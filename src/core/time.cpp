#include "core/time.hpp"

#include <date/date.h>

#include <chrono>
#include <cmath>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace nephele::core {

double parse_utc_time(const std::string& text) {
  const std::string form = "YYYY-MM-DDTHH:MM[:SS[.fraction]] in UTC, ending in Z or +00:00";
  // The shape first: date::parse alone would accept trailing text and other zones.
  static const std::regex shape(R"(^(\d{4}-\d{2}-\d{2})T(\d{2}:\d{2})(:\d{2}(\.\d{1,9})?)?(Z|z|\+00:00)$)");
  std::smatch parts;
  if (!std::regex_match(text, parts, shape))
    throw std::invalid_argument("'" + text + "' is not an ISO 8601 UTC time (" + form + ")");
  const std::string seconds = parts[3].matched ? parts[3].str() : ":00";
  std::istringstream in(parts[1].str() + "T" + parts[2].str() + seconds);
  date::sys_time<std::chrono::nanoseconds> point;
  in >> date::parse("%FT%T", point);
  if (in.fail())
    throw std::invalid_argument("'" + text + "' is not a valid date and time (month 1-12, a day that exists in that month, hour 0-23, minute 0-59, second 0-59)");
  // Whole seconds and the fraction apart: converting the nanosecond count (about 1.7e18, past
  // 2^53) to double first rounded .250 s to .2499998 s.
  const auto whole = std::chrono::floor<std::chrono::seconds>(point);
  return static_cast<double>(whole.time_since_epoch().count()) + static_cast<double>((point - whole).count()) / 1e9;
}

std::string format_utc_minutes(double unix_seconds) {
  using namespace std::chrono;
  const date::sys_time<seconds> point{seconds{static_cast<long long>(std::floor(unix_seconds))}};
  return date::format("%FT%H:%MZ", floor<minutes>(point));
}

}  // namespace nephele::core
