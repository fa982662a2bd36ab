#include "core/error.hpp"

#include "core/printable_text.hpp"

namespace nephele::core {

namespace {
std::string compose(const std::string& field, const std::string& value, const std::string& allowed,
                    const std::string& problem) {
  // The value comes from the user or a file: escaped and cut (core/printable_text.hpp).
  std::string message = printable(field) + ": '" + printable(value) + "' " + problem;
  if (!allowed.empty()) message += " (allowed: " + allowed + ")";
  return message;
}
}  // namespace

InputError::InputError(std::string field, std::string value, std::string allowed, std::string problem)
    : std::runtime_error(compose(field, value, allowed, problem)),
      field_(std::move(field)),
      value_(std::move(value)),
      allowed_(std::move(allowed)) {}

InputError::InputError(const std::string& message) : std::runtime_error(printable(message, 4096, true)) {}

}  // namespace nephele::core
