#include "params/values.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <regex>
#include <sstream>

#include "core/error.hpp"

namespace nephele::params {

bool is_decimal_number(const std::string& text, bool integer_only) {
  static const std::regex integer_form(R"(^[+-]?[0-9]+$)");
  static const std::regex real_form(R"(^[+-]?([0-9]+(\.[0-9]*)?|\.[0-9]+)([eE][+-]?[0-9]+)?$)");
  return std::regex_match(text, integer_only ? integer_form : real_form);
}

double parse_number(const std::string& field, const std::string& text, double min, double max, bool integer_only) {
  const Parameter range = integer_only ? integer("", 0, min, max, "", "", 0) : real("", 0, min, max, "", "", 0);
  return parse_number(range, text, field);
}

double parse_number(const Parameter& p, const std::string& text, const std::string& field) {
  const bool integer_only = p.type == Type::integer;
  if (!is_decimal_number(text, integer_only))
    throw core::InputError(field, text, p.range_text(), integer_only ? "is not an integer" : "is not a number");
  errno = 0;
  const double value = std::strtod(text.c_str(), nullptr);
  if (errno == ERANGE || !std::isfinite(value)) throw core::InputError(field, text, p.range_text(), "is out of range");
  check_number(p, value, field);
  return value;
}

void check_number(const Parameter& p, double value, const std::string& field) {
  std::ostringstream shown;
  shown.precision(10);
  shown << value;
  if (!std::isfinite(value)) throw core::InputError(field, shown.str(), p.range_text(), "is not finite");
  if (p.type == Type::integer && value != std::floor(value))
    throw core::InputError(field, shown.str(), p.range_text(), "is not an integer");
  if (value < p.min || value > p.max) throw core::InputError(field, shown.str(), p.range_text(), "is out of range");
}

void check_word(const Parameter& p, const std::string& word, const std::string& field) {
  const std::string allowed(p.allowed);
  std::size_t start = 0;
  while (start <= allowed.size()) {
    const std::size_t bar = allowed.find('|', start);
    const std::size_t end = bar == std::string::npos ? allowed.size() : bar;
    if (allowed.compare(start, end - start, word) == 0) return;
    if (bar == std::string::npos) break;
    start = bar + 1;
  }
  throw core::InputError(field, word, p.range_text());
}

}  // namespace nephele::params
