#pragma once
// Strict integers in text written by people: decimal digits only.
#include <optional>
#include <string_view>

namespace nephele::core {

// The value of `text` when it is an optional '-' and one or more decimal digits, nothing else
// (no spaces, '+', hex, fraction or exponent), within long long; std::nullopt otherwise.
std::optional<long long> parse_integer(std::string_view text);

}  // namespace nephele::core
