#include "core/integer_text.hpp"

#include <charconv>
#include <system_error>

namespace nephele::core {

std::optional<long long> parse_integer(std::string_view text) {
  const std::string_view digits = !text.empty() && text.front() == '-' ? text.substr(1) : text;
  if (digits.empty()) return std::nullopt;
  for (const char c : digits)
    if (c < '0' || c > '9') return std::nullopt;
  long long value = 0;
  // from_chars reports overflow (4294967297 stays itself, 99999999999999999999 is refused).
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

}  // namespace nephele::core
