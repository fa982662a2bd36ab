#pragma once
// Command-line options with stated ranges: parsing, validation and --help text.
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace nephele::cli {

// Bad input: the message names the option and the allowed range; exit code 2.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Options {
 public:
  Options(std::string command, std::string summary);

  void add_int(const std::string& name, int* target, int min, int max, const std::string& help);
  void add_uint32(const std::string& name, std::uint32_t* target, const std::string& help);
  void add_float(const std::string& name, float* target, double min, double max, const std::string& help);
  void add_string(const std::string& name, std::string* target, const std::string& help);
  void add_flag(const std::string& name, bool* target, const std::string& help);
  // An option that may be given several times; each value is appended.
  void add_string_list(const std::string& name, std::vector<std::string>* target, const std::string& help);

  // Parses arguments (without the command words). Returns false when --help was given
  // (help() then has the text). Throws UsageError.
  bool parse(const std::vector<std::string>& arguments);
  std::string help() const;

 private:
  struct Option {
    std::string name, help, range, default_text;
    bool takes_value;
    std::function<void(const std::string&)> apply;
    bool repeatable = false;
  };
  std::string command_, summary_;
  std::vector<Option> options_;
};

// Strict number parsing: the whole text, finite, within [min, max]; errors name the option.
double parse_number(const std::string& option, const std::string& text, double min, double max);

}  // namespace nephele::cli
