#pragma once
// The one error type for bad input, and the exit codes of every command.
#include <stdexcept>
#include <string>

namespace nephele::core {

// Exit codes of every nephele command (README, `nephele --help`).
enum ExitCode : int {
  exit_ok = 0,
  exit_failure = 1,      // runtime failure, e.g. a file could not be written
  exit_bad_input = 2,    // an option, scene key or file field is out of its allowed range
  exit_environment = 3,  // no OpenGL 4.5 context, no display for a window
};

// Bad input: carries what the user typed (an option such as `--seed`, or `FILE: key`), the
// value given and the allowed range, so that every message has the same shape:
//   --seed: '-1' is out of range (allowed: 0 to 4294967295)
class InputError : public std::runtime_error {
 public:
  InputError(std::string field, std::string value, std::string allowed, std::string problem = "is not allowed");
  // A message that does not fit the field/value/range shape (e.g. two options that conflict).
  explicit InputError(const std::string& message);
  const std::string& field() const { return field_; }
  const std::string& value() const { return value_; }
  const std::string& allowed() const { return allowed_; }
  int exit_code() const { return exit_bad_input; }

 private:
  std::string field_, value_, allowed_;
};

}  // namespace nephele::core
