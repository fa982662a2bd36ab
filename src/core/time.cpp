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
    throw std::invalid_argument("'" + text +
                                "' is not a valid date and time (month 1-12, a day that exists in that month, hour "
                                "0-23, minute 0-59, second 0-59)");
  // Whole seconds and the fraction apart, each exact in a double: a count of nanoseconds since
  // 1970 (about 1.7e18, past 2^53) rounded .250 s to .2499998 s and could move a whole minute
  // off by an ulp outside the common years (found by tests/fuzz).
  const std::int64_t tod = time_of_day.time_since_epoch().count();
  const std::int64_t whole = std::int64_t{day.time_since_epoch().count()} * 86400 + tod / 1'000'000'000;
  const std::int64_t fraction = tod % 1'000'000'000;
  return static_cast<double>(whole) + static_cast<double>(fraction) / 1e9;
}

std::string format_utc_minutes(double unix_seconds) {
  using namespace std::chrono;
  const date::sys_time<seconds> point{seconds{static_cast<long long>(std::floor(unix_seconds))}};
  return date::format("%FT%H:%MZ", floor<minutes>(point));
}

std::string format_utc_seconds(double unix_seconds) {
  using namespace std::chrono;
  const date::sys_time<seconds> point{seconds{static_cast<long long>(std::floor(unix_seconds))}};
  return date::format("%FT%H:%M:%SZ", point);
}

int day_of_year(double unix_seconds) {
  using namespace std::chrono;
  const date::sys_days day =
      date::floor<date::days>(date::sys_time<seconds>{seconds{static_cast<long long>(std::floor(unix_seconds))}});
  const date::year_month_day ymd{day};
  return static_cast<int>((day - date::sys_days{ymd.year() / 1 / 1}).count()) + 1;
}

}  // namespace nephele::core
