#include "params/parameter.hpp"

#include <sstream>

namespace nephele::params {
namespace {

std::string number_text(double v) {
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

}  // namespace

std::string Parameter::option() const {
  std::string name(key);
  for (char& c : name)
    if (c == '_') c = '-';
  return "--" + name;
}

std::string Parameter::range_text() const {
  switch (type) {
    case Type::integer:
    case Type::real: return number_text(min) + " to " + number_text(max);
    case Type::text:
    case Type::list: {
      std::string words(allowed);
      std::string out;
      for (char c : words) out += c == '|' ? std::string(", ") : std::string(1, c);
      return out;
    }
    case Type::flag: return "";
  }
  return "";
}

std::vector<std::string> Parameter::words() const {
  if (type != Type::text || allowed.empty()) return {};
  for (char c : allowed)
    if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '|')) return {};
  std::vector<std::string> out(1);
  for (char c : allowed) {
    if (c == '|')
      out.emplace_back();
    else
      out.back() += c;
  }
  return out;
}

std::string Parameter::default_display() const {
  if (!default_text.empty()) return std::string(default_text);
  if (type == Type::integer || type == Type::real) return number_text(default_number);
  return "";
}

}  // namespace nephele::params
