#include "core/number_text.hpp"

#include <charconv>
#include <cstdlib>
#include <string>
#include <system_error>

namespace nephele::core {
namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// Advances `i` over decimal digits; returns how many.
std::size_t skip_digits(std::string_view text, std::size_t& i) {
  const std::size_t from = i;
  while (i < text.size() && is_digit(text[i])) ++i;
  return i - from;
}

}  // namespace

bool is_decimal_number(std::string_view text, NumberForm form) {
  if (text.empty() || text.size() > max_number_text_length) return false;
  std::size_t i = 0;
  if (text[i] == '+' || text[i] == '-') ++i;
  std::size_t mantissa_digits = skip_digits(text, i);
  if (form == NumberForm::integer) return mantissa_digits > 0 && i == text.size();
  if (i < text.size() && text[i] == '.') {
    ++i;
    mantissa_digits += skip_digits(text, i);
  }
  if (mantissa_digits == 0) return false;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
    if (skip_digits(text, i) == 0) return false;
  }
  return i == text.size();
}

std::optional<double> parse_decimal(std::string_view text, NumberForm form) {
  if (!is_decimal_number(text, form)) return std::nullopt;
  // strtod needs a terminated string; the text is at most 64 characters. It gives +-HUGE_VAL
  // beyond double's range, which the callers refuse.
  const std::string terminated(text);
  return std::strtod(terminated.c_str(), nullptr);
}

std::optional<long long> parse_integer(std::string_view text) {
  if (text.empty() || text.front() == '+' || !is_decimal_number(text, NumberForm::integer)) return std::nullopt;
  long long value = 0;
  // from_chars reports overflow (4294967297 stays itself, 99999999999999999999 is refused).
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

}  // namespace nephele::core
