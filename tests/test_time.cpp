// ISO 8601 UTC times: what parse_utc_time accepts and what it refuses.
#include <catch2/catch.hpp>

#include <string>

#include "core/time.hpp"

using namespace nephele;

TEST_CASE("times that do not exist or are not UTC are refused", "[fast][time]") {
  const char* refused[] = {
      "2024-02-31T12:00Z",       // February has no 31st
      "2023-02-29T12:00Z",       // 2023 is no leap year
      "2024-06-01T24:00Z",       // hours run 0 to 23
      "2024-06-01T12:60Z",       // minutes run 0 to 59
      "2024-06-01T12:nanZ",      // strtod would have read NaN
      "2024-06-01T12:00+01:00",  // another zone
      "2024-06-01T12:00Zextra",  // trailing text
      "2024-06-01T12:00Z ",      // trailing space
      " 2024-06-01T12:00Z",      // leading space
      "",                        // nothing
  };
  for (const char* text : refused) {
    INFO("'" << text << "'");
    try {
      core::parse_utc_time(text);
      FAIL("accepted");
    } catch (const std::invalid_argument& e) {
      // The message quotes the text so that the user sees what was refused.
      CHECK_THAT(e.what(), Catch::Contains("'" + std::string(text) + "'"));
    }
  }
}

TEST_CASE("fractional seconds, a leap day and +00:00 are accepted", "[fast][time]") {
  const double noon = core::parse_utc_time("2024-02-29T12:00Z");  // a leap day
  CHECK(noon == 1709208000.0);
  CHECK(core::parse_utc_time("2024-02-29T12:00+00:00") == noon);
  CHECK(core::parse_utc_time("2024-02-29T12:00:00Z") == noon);
  // 0.5 and 0.25 s are exact in binary, so the sums are exact doubles.
  CHECK(core::parse_utc_time("2024-02-29T12:00:30.5Z") == noon + 30.5);
  CHECK(core::parse_utc_time("2024-02-29T12:00:30.250+00:00") == noon + 30.25);
}
