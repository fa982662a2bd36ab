#pragma once
// The options of one command, made from the parameter table (src/params/table.hpp) and parsed
// by CLI11: `--name VALUE` and `--name=VALUE` alike, strict numbers, ranges from the table, and
// "was this option given" from the parser.
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "params/parameter.hpp"

namespace CLI {
class App;
}

namespace nephele::cli {

// Bad input: the message names the option and the allowed range; exit code 2.
using UsageError = core::InputError;

class Options {
 public:
  // `use`: the params::Use bit of this command; binding a parameter the table does not give to
  // this command is a programming error (std::logic_error).
  Options(std::string command, std::string summary, unsigned use);
  ~Options();
  Options(const Options&) = delete;
  Options& operator=(const Options&) = delete;

  void bind(const params::Parameter& p, int* target);
  void bind(const params::Parameter& p, std::uint32_t* target);
  void bind(const params::Parameter& p, float* target);
  void bind(const params::Parameter& p, double* target);
  void bind(const params::Parameter& p, std::string* target);               // text: words are checked
  void bind(const params::Parameter& p, bool* target);                      // flag
  void bind(const params::Parameter& p, std::vector<std::string>* target);  // list: repeatable

  // Parses arguments (without the command words). Returns false when --help was given (help()
  // then has the text). Throws UsageError.
  bool parse(const std::vector<std::string>& arguments);
  bool given(const params::Parameter& p) const;
  std::string help() const;
  unsigned use() const { return use_; }  // the command's params::Use bit

 private:
  void add(const params::Parameter& p, bool takes_value, bool repeatable,
           std::function<void(const std::string&)> apply);
  struct Entry {
    const params::Parameter* parameter;
    bool takes_value;
  };
  std::string command_, summary_;
  unsigned use_;
  std::unique_ptr<CLI::App> app_;
  std::vector<Entry> entries_;
};

// The operand before the options (export's and view's COVER_DIR): removed from `arguments` and
// returned; "" when the first argument is an option or there is none.
std::string take_leading_operand(std::vector<std::string>& arguments);
// Takes the leading COVER_DIR operand and parses the rest: false when --help was asked for (the
// help is printed; the caller returns exit_ok), else true with `cover_dir` set; a missing operand
// is a UsageError naming COVER_DIR, checked after the help so that --help needs none.
bool parse_with_cover_dir(Options& options, const std::vector<std::string>& arguments, std::string& cover_dir);

// Strict number parsing for values outside the table (list items, channel settings): the whole
// text, decimal, finite, within [min, max]; errors name the option.
double parse_number(const std::string& option, const std::string& text, double min, double max,
                    bool integer_only = false);

// A comma-separated list of such numbers; an empty item ("16,", "16,,32") is refused too.
template <class T>
std::vector<T> parse_number_list(const std::string& option, const std::string& text, double min, double max,
                                 bool integer_only) {
  std::vector<T> values;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    const std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    values.push_back(static_cast<T>(parse_number(option, item, min, max, integer_only)));
    if (comma == std::string::npos) return values;
    start = comma + 1;
  }
}

}  // namespace nephele::cli
