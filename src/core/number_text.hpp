#pragma once
// The one scanner of numbers in text written by people: options, CSV fields, key=value lists,
// sizes such as 1280x720. A single left-to-right pass, no regex and no recursion, so that no
// input length can exhaust the stack (a 30000-digit --size once did, in std::regex).
#include <cstddef>
#include <optional>
#include <string_view>

namespace nephele::core {

// The longest number text accepted: far more than any value needs (17 significant digits, a
// sign, a point and an exponent), short enough to show whole in a message.
constexpr std::size_t max_number_text_length = 64;

enum class NumberForm {
  integer,  // optional sign and decimal digits
  real,     // optional sign, digits with an optional fraction (".5", "5." too), optional exponent
};

// Whether the whole text is a number of `form` of at most max_number_text_length characters.
// No spaces, hex, "inf" or "nan".
bool is_decimal_number(std::string_view text, NumberForm form);

// The value of such a text (std::nullopt otherwise). Out of double's range it is infinite: the
// callers refuse it as out of range with the text the user typed.
std::optional<double> parse_decimal(std::string_view text, NumberForm form);

// The value of `text` when it is an optional '-' and one or more decimal digits, nothing else
// (no spaces, '+', hex, fraction or exponent), within long long; std::nullopt otherwise.
std::optional<long long> parse_integer(std::string_view text);

}  // namespace nephele::core
