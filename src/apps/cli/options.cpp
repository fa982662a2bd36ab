#include "apps/cli/options.hpp"

#include <iostream>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <functional>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "params/values.hpp"

namespace nephele::cli {

double parse_number(const std::string& option, const std::string& text, double min, double max, bool integer_only) {
  return params::parse_number(option, text, min, max, integer_only);
}

std::string take_leading_operand(std::vector<std::string>& arguments) {
  if (arguments.empty() || arguments.front().empty() || arguments.front()[0] == '-') return "";
  std::string operand = arguments.front();
  arguments.erase(arguments.begin());
  return operand;
}

bool parse_with_cover_dir(Options& options, const std::vector<std::string>& arguments, std::string& cover_dir) {
  std::vector<std::string> rest = arguments;
  cover_dir = take_leading_operand(rest);
  if (!options.parse(rest)) {
    std::cout << options.help();
    return false;
  }
  if (cover_dir.empty())
    throw UsageError("COVER_DIR", "", "a directory written by nephele generate, given before the options",
                     "is missing");
  return true;
}

Options::Options(std::string command, std::string summary, unsigned use)
    : command_(std::move(command)),
      summary_(std::move(summary)),
      use_(use),
      app_(std::make_unique<CLI::App>(summary_, "nephele " + command_)) {
  app_->set_help_flag();  // --help is answered from the table (help()), before CLI11 parses
}

Options::~Options() = default;

void Options::add(const params::Parameter& p, bool takes_value, bool repeatable,
                  std::function<void(const std::string&)> apply) {
  if (!p.used_by(use_))
    throw std::logic_error("parameter '" + std::string(p.key) + "' is not declared for nephele " + command_);
  const std::string name = p.option();
  if (!takes_value) {
    app_->add_flag_function(
        name, [apply](std::int64_t) { apply(""); }, std::string(p.help));
  } else if (repeatable) {
    app_->add_option_function<std::vector<std::string>>(
            name,
            [apply](const std::vector<std::string>& values) {
              for (const auto& v : values) apply(v);
            },
            std::string(p.help))
        ->allow_extra_args(false)
        ->expected(1)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  } else {
    app_->add_option_function<std::string>(name, apply, std::string(p.help));
  }
  entries_.push_back({&p, takes_value});
}

void Options::bind(const params::Parameter& p, int* target) {
  add(p, true, false,
      [&p, target](const std::string& text) { *target = static_cast<int>(params::parse_number(p, text, p.option())); });
}

void Options::bind(const params::Parameter& p, std::uint32_t* target) {
  add(p, true, false, [&p, target](const std::string& text) {
    *target = static_cast<std::uint32_t>(params::parse_number(p, text, p.option()));
  });
}

void Options::bind(const params::Parameter& p, float* target) {
  add(p, true, false, [&p, target](const std::string& text) {
    *target = static_cast<float>(params::parse_number(p, text, p.option()));
  });
}

void Options::bind(const params::Parameter& p, double* target) {
  add(p, true, false, [&p, target](const std::string& text) { *target = params::parse_number(p, text, p.option()); });
}

void Options::bind(const params::Parameter& p, std::string* target) {
  add(p, true, false, [&p, target](const std::string& text) {
    if (text.empty()) throw UsageError(p.option(), text, p.range_text(), "is empty");
    if (!p.words().empty()) params::check_word(p, text, p.option());
    *target = text;
  });
}

void Options::bind(const params::Parameter& p, bool* target) {
  add(p, false, false, [target](const std::string&) { *target = true; });
}

void Options::bind(const params::Parameter& p, std::vector<std::string>* target) {
  add(p, true, true, [&p, target](const std::string& text) {
    if (text.empty()) throw UsageError(p.option(), text, p.range_text(), "is empty");
    target->push_back(text);
  });
}

bool Options::parse(const std::vector<std::string>& arguments) {
  if (std::find(arguments.begin(), arguments.end(), "--help") != arguments.end() ||
      std::find(arguments.begin(), arguments.end(), "-h") != arguments.end())
    return false;
  std::vector<std::string> reversed(arguments.rbegin(), arguments.rend());  // CLI11 pops from the back
  try {
    app_->parse(reversed);
  } catch (const CLI::ParseError& e) {
    throw UsageError("nephele " + command_ + ": " + e.what() + " (see nephele " + command_ + " --help)");
  }
  return true;
}

bool Options::given(const params::Parameter& p) const { return app_->count(p.option()) > 0; }

std::string Options::help() const {
  std::ostringstream out;
  out << "usage: nephele " << command_ << " [options]\n\n" << summary_ << "\n\noptions:\n";
  for (const auto& e : entries_) {
    const params::Parameter& p = *e.parameter;
    std::string head = "  " + p.option() + (e.takes_value ? " VALUE" : "");
    out << head << (head.size() < 26 ? std::string(26 - head.size(), ' ') : "\n" + std::string(26, ' ')) << p.help;
    if (p.type == params::Type::list) out << " (repeatable)";
    const std::string range = p.range_text();
    if (!range.empty()) out << " [" << range << (p.unit.empty() ? "" : ", " + std::string(p.unit)) << "]";
    const std::string default_text = p.default_display();
    if (!default_text.empty()) out << " (default " << default_text << ")";
    out << "\n";
  }
  out << "  --help                  this text\n";
  return out.str();
}

}  // namespace nephele::cli
