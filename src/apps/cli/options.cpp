#include "apps/cli/options.hpp"

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace nephele::cli {
namespace {

std::string format_number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

double parse_number(const std::string& option, const std::string& text, double min, double max) {
  const std::string range = "allowed range " + format_number(min) + " to " + format_number(max);
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE)
    throw UsageError(option + ": '" + text + "' is not a number (" + range + ")");
  if (!std::isfinite(value)) throw UsageError(option + ": '" + text + "' is not finite (" + range + ")");
  if (value < min || value > max)
    throw UsageError(option + ": " + text + " is out of range (" + range + ")");
  return value;
}

Options::Options(std::string command, std::string summary)
    : command_(std::move(command)), summary_(std::move(summary)) {}

void Options::add_int(const std::string& name, int* target, int min, int max, const std::string& help) {
  options_.push_back({name, help, std::to_string(min) + ".." + std::to_string(max),
                      std::to_string(*target), true, [=](const std::string& text) {
                        const double v = parse_number(name, text, min, max);
                        if (v != std::floor(v))
                          throw UsageError(name + ": '" + text + "' is not an integer (allowed range " +
                                           std::to_string(min) + " to " + std::to_string(max) + ")");
                        *target = static_cast<int>(v);
                      }});
}

void Options::add_uint32(const std::string& name, std::uint32_t* target, const std::string& help) {
  options_.push_back({name, help, "0..4294967295", std::to_string(*target), true,
                      [=](const std::string& text) {
                        const double v = parse_number(name, text, 0.0, 4294967295.0);
                        if (v != std::floor(v))
                          throw UsageError(name + ": '" + text +
                                           "' is not an integer (allowed range 0 to 4294967295)");
                        *target = static_cast<std::uint32_t>(v);
                      }});
}

void Options::add_float(const std::string& name, float* target, double min, double max,
                        const std::string& help) {
  options_.push_back({name, help, format_number(min) + ".." + format_number(max),
                      format_number(*target), true, [=](const std::string& text) {
                        *target = static_cast<float>(parse_number(name, text, min, max));
                      }});
}

void Options::add_string(const std::string& name, std::string* target, const std::string& help) {
  options_.push_back({name, help, "", *target, true, [=](const std::string& text) {
                        if (text.empty()) throw UsageError(name + ": an empty value is not allowed");
                        *target = text;
                      }});
}

void Options::add_string_list(const std::string& name, std::vector<std::string>* target,
                              const std::string& help) {
  Option o{name, help + " (repeatable)", "", "", true, [=](const std::string& text) {
             if (text.empty()) throw UsageError(name + ": an empty value is not allowed");
             target->push_back(text);
           }};
  o.repeatable = true;
  options_.push_back(o);
}

void Options::add_flag(const std::string& name, bool* target, const std::string& help) {
  options_.push_back({name, help, "", "", false, [=](const std::string&) { *target = true; }});
}

bool Options::parse(const std::vector<std::string>& arguments) {
  std::vector<std::string> seen;
  for (size_t k = 0; k < arguments.size(); ++k) {
    std::string word = arguments[k];
    if (word == "--help" || word == "-h") return false;
    std::string value;
    bool has_inline_value = false;
    if (const auto eq = word.find('='); word.rfind("--", 0) == 0 && eq != std::string::npos) {
      value = word.substr(eq + 1);
      word = word.substr(0, eq);
      has_inline_value = true;
    }
    const Option* option = nullptr;
    for (const auto& o : options_)
      if (o.name == word) option = &o;
    if (!option)
      throw UsageError("nephele " + command_ + ": unknown argument '" + word + "' (see nephele " +
                       command_ + " --help)");
    if (!option->repeatable)
      for (const auto& s : seen)
        if (s == word) throw UsageError(word + ": given more than once");
    seen.push_back(word);
    if (option->takes_value && !has_inline_value) {
      if (k + 1 >= arguments.size()) throw UsageError(word + ": a value is required");
      value = arguments[++k];
    } else if (!option->takes_value && has_inline_value) {
      throw UsageError(word + ": takes no value");
    }
    option->apply(value);
  }
  return true;
}

std::string Options::help() const {
  std::ostringstream out;
  out << "usage: nephele " << command_ << " [options]\n\n" << summary_ << "\n\noptions:\n";
  for (const auto& o : options_) {
    std::string head = "  " + o.name + (o.takes_value ? " VALUE" : "");
    out << head << (head.size() < 26 ? std::string(26 - head.size(), ' ') : "\n" + std::string(26, ' '))
        << o.help;
    if (!o.range.empty()) out << " [" << o.range << "]";
    if (!o.default_text.empty()) out << " (default " << o.default_text << ")";
    out << "\n";
  }
  out << "  --help                  this text\n";
  return out.str();
}

}  // namespace nephele::cli
