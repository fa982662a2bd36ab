#pragma once
// Strict checks of values against their parameter's declaration. `field` is what the user
// typed: an option such as "--seed", or "FILE: 'seed'" for a scene key; errors name it, the value
// and the allowed range (core::InputError, exit code 2).
#include <string>

#include "params/parameter.hpp"

namespace nephele::params {

// The whole text must be a decimal number: optional sign, digits, optional fraction and
// exponent. No hex, no leading or trailing space, no inf or nan; integers need integer text.
double parse_number(const Parameter& p, const std::string& text, const std::string& field);
// The range (and integrality for integers) of a number that came from a file.
void check_number(const Parameter& p, double value, const std::string& field);
// One of the allowed words of a text parameter whose `allowed` lists words ("a|b|c").
void check_word(const Parameter& p, const std::string& word, const std::string& field);
// The same rule for values that are not table parameters (items of comma-separated lists,
// key=value settings): `range` is shown in the message.
double parse_number(const std::string& field, const std::string& text, double min, double max, bool integer_only);
// Strict decimal text of a number (the rule of parse_number, core/number_text.hpp), for lists
// such as --sizes.
bool is_decimal_number(const std::string& text, bool integer_only);
// Why a text that is_decimal_number refuses is refused, for the message ("is not a number",
// "is longer than 64 characters").
std::string number_problem(const std::string& text, bool integer_only);

}  // namespace nephele::params
