#include "params/values.hpp"

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "core/error.hpp"
#include "core/number_text.hpp"

namespace nephele::params {

namespace {

core::NumberForm form_of(bool integer_only) {
  return integer_only ? core::NumberForm::integer : core::NumberForm::real;
}

// The value, shown as the user typed it when there is text (a value read back as a double may
// print as another: 10.000000000000001 is 10 at 10 digits).
void check_value(const Parameter& p, double value, const std::string& field, const std::string& text) {
  std::string shown = text;
  if (shown.empty()) {
    std::ostringstream out;
    out.precision(10);
    out << value;
    shown = out.str();
  }
  if (!std::isfinite(value))
    throw core::InputError(field, shown, p.range_text(), text.empty() ? "is not finite" : "is out of range");
  if (p.type == Type::integer && value != std::floor(value))
    throw core::InputError(field, shown, p.range_text(), "is not an integer");
  if (value < p.min || value > p.max) throw core::InputError(field, shown, p.range_text(), "is out of range");
}

}  // namespace

bool is_decimal_number(const std::string& text, bool integer_only) {
  return core::is_decimal_number(text, form_of(integer_only));
}

std::string number_problem(const std::string& text, bool integer_only) {
  if (text.size() > core::max_number_text_length)
    return "is longer than " + std::to_string(core::max_number_text_length) + " characters";
  return integer_only ? "is not an integer" : "is not a number";
}

double parse_number(const std::string& field, const std::string& text, double min, double max, bool integer_only) {
  const Parameter range = integer_only ? integer("", 0, min, max, "", "", 0) : real("", 0, min, max, "", "", 0);
  return parse_number(range, text, field);
}

double parse_number(const Parameter& p, const std::string& text, const std::string& field) {
  const bool integer_only = p.type == Type::integer;
  const auto value = core::parse_decimal(text, form_of(integer_only));
  if (!value) throw core::InputError(field, text, p.range_text(), number_problem(text, integer_only));
  check_value(p, *value, field, text);
  return *value;
}

void check_number(const Parameter& p, double value, const std::string& field) { check_value(p, value, field, ""); }

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
