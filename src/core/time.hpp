#pragma once
// Times are UTC seconds since 1970-01-01 (Unix time, no leap seconds) as doubles.
#include <string>

namespace nephele::core {

// Parses an ISO 8601 UTC date-time, YYYY-MM-DDTHH:MM[:SS[.fraction]] followed by Z or +00:00,
// and nothing else. Impossible dates (2024-02-31), hours past 23 and non-digits (NaN) are
// refused: the calendar check is Howard Hinnant's date library (libhowardhinnant-date-dev).
// Throws std::invalid_argument with a message that quotes the text and the allowed form.
double parse_utc_time(const std::string& text);

// YYYY-MM-DDTHH:MMZ of a time (seconds are dropped, not rounded).
std::string format_utc_minutes(double unix_seconds);
// YYYY-MM-DDTHH:MM:SSZ of a time (fractions of a second are dropped); parse_utc_time reads it.
std::string format_utc_seconds(double unix_seconds);
// The day of the year (1 on 1 January, to 365 or 366) of a time, in UTC.
int day_of_year(double unix_seconds);

}  // namespace nephele::core
