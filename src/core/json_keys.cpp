#include "core/json_keys.hpp"

#include <cmath>
#include <stdexcept>

namespace nephele::json {

void KeyReader::fail(const std::string& key, const std::string& message) const {
  fail_(key, message);
  // A Fail that returns is a programming error; still never go on with a bad value.
  throw std::logic_error(key + ": " + message);
}

const Value& KeyReader::member(const Value& object, const std::string& key, const std::string& path) const {
  const Value* v = object.find(key);
  if (!v) fail(path + key, "missing");
  return *v;
}

double KeyReader::number(const Value& v, const std::string& key) const {
  if (!v.is_number()) fail(key, "must be a number");
  return v.as_number();
}

int KeyReader::integer(const Value& v, const std::string& key) const {
  const double d = number(v, key);
  if (d != std::floor(d) || std::abs(d) > 1e9) fail(key, "must be an integer");
  return static_cast<int>(d);
}

std::string KeyReader::string(const Value& v, const std::string& key) const {
  if (!v.is_string()) fail(key, "must be a string");
  return v.as_string();
}

bool KeyReader::boolean(const Value& v, const std::string& key) const {
  if (!v.is_bool()) fail(key, "must be true or false");
  return v.as_bool();
}

std::vector<std::string> KeyReader::strings(const Value& v, const std::string& key) const {
  if (!v.is_array()) fail(key, "must be an array of strings");
  std::vector<std::string> out;
  for (const auto& item : v.as_array()) out.push_back(string(item, key + "[]"));
  return out;
}

}  // namespace nephele::json
