#pragma once
// Text from inputs (option values, file fields, paths) made safe to print in a message: a
// terminal must not receive escape sequences from a crafted file, a NUL must not cut the
// message short, and a 30000-character value must not bury it.
#include <cstddef>
#include <string>
#include <string_view>

namespace nephele::core {

// The longest value shown in an InputError message.
constexpr std::size_t max_shown_value_bytes = 200;

// `text` with control characters (but newline and tab when `keep_lines`), DEL and bytes that are
// not part of well-formed UTF-8 written as \xNN, cut after `max_bytes` of the result with
// "... (N bytes more)". Backslashes stay as they are, so the function leaves its own output
// unchanged.
std::string printable(std::string_view text, std::size_t max_bytes = max_shown_value_bytes, bool keep_lines = false);

}  // namespace nephele::core
