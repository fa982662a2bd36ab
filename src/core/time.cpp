#include "core/time.hpp"

#include <date/date.h>

#include <chrono>
#include <cstdint>
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
  // The day and the time of day apart: 64-bit nanoseconds since 1970 overflow outside the years
  // 1678-2262 (undefined behaviour inside date::parse, found by tests/fuzz); days and a
  // nanosecond time of day do not.
  std::istringstream day_in(parts[1].str()), time_in("1970-01-01T" + parts[2].str() + seconds);
  date::sys_days day;
  date::sys_time<std::chrono::nanoseconds> time_of_day;
  day_in >> date::parse("%F", day);
  time_in >> date::parse("%FT%T", time_of_day);
  if (day_in.fail() || time_in.fail())
    throw std::invalid_argument("'" + text + "' is not a valid date and time (month 1-12, a day that exists in that month, hour 0-23, minute 0-59, second 0-59)");
  const std::int64_t tod = time_of_day.time_since_epoch().count();
  const std::int64_t whole = std::int64_t{day.time_since_epoch().count()} * 86400 + tod / 1'000'000'000;
  const std::int64_t fraction = tod % 1'000'000'000;
  // Where the nanoseconds fit, one rounding of them, bit for bit as before; elsewhere the whole
  // seconds exactly (a rounded count of nanoseconds could move a whole minute off by an ulp).
  std::int64_t nanoseconds = 0;
  if (!__builtin_mul_overflow(whole, 1'000'000'000, &nanoseconds) &&
      !__builtin_add_overflow(nanoseconds, fraction, &nanoseconds))
    return static_cast<double>(nanoseconds) / 1e9;
  return static_cast<double>(whole) + static_cast<double>(fraction) / 1e9;
}

std::string format_utc_minutes(double unix_seconds) {
  using namespace std::chrono;
  const date::sys_time<seconds> point{seconds{static_cast<long long>(std::floor(unix_seconds))}};
  return date::format("%FT%H:%MZ", floor<minutes>(point));
}

}  // namespace nephele::core
