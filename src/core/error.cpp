#include "core/error.hpp"

namespace nephele::core {

namespace {
std::string compose(const std::string& field, const std::string& value, const std::string& allowed,
                    const std::string& problem) {
  std::string message = field + ": '" + value + "' " + problem;
  if (!allowed.empty()) message += " (allowed: " + allowed + ")";
  return message;
}
}  // namespace

InputError::InputError(std::string field, std::string value, std::string allowed, std::string problem)
    : std::runtime_error(compose(field, value, allowed, problem)),
      field_(std::move(field)),
      value_(std::move(value)),
      allowed_(std::move(allowed)) {}

InputError::InputError(const std::string& message) : std::runtime_error(message) {}

}  // namespace nephele::core
