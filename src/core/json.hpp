#pragma once
// A small JSON value with a strict parser (RFC 8259) and a writer. Objects keep key order.
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace nephele::json {

class ParseError : public std::runtime_error {
 public:
  ParseError(const std::string& message, size_t line, size_t column);
  size_t line, column;
};

class Value {
 public:
  using Array = std::vector<Value>;
  using Object = std::vector<std::pair<std::string, Value>>;

  Value() = default;  // null
  Value(std::nullptr_t) {}
  Value(bool b) : data_(b) {}
  Value(double d) : data_(d) {}
  Value(int i) : data_(static_cast<double>(i)) {}
  Value(unsigned i) : data_(static_cast<double>(i)) {}
  Value(long i) : data_(static_cast<double>(i)) {}
  Value(unsigned long i) : data_(static_cast<double>(i)) {}
  // Stores the shortest decimal that reads back as the same float (0.006f stays 0.006).
  Value(float f);
  Value(const char* s) : data_(std::string(s)) {}
  Value(std::string s) : data_(std::move(s)) {}
  Value(Array a) : data_(std::move(a)) {}
  Value(Object o) : data_(std::move(o)) {}

  bool is_null() const { return std::holds_alternative<std::monostate>(data_); }
  bool is_bool() const { return std::holds_alternative<bool>(data_); }
  bool is_number() const { return std::holds_alternative<double>(data_); }
  bool is_string() const { return std::holds_alternative<std::string>(data_); }
  bool is_array() const { return std::holds_alternative<Array>(data_); }
  bool is_object() const { return std::holds_alternative<Object>(data_); }

  bool as_bool() const { return std::get<bool>(data_); }
  double as_number() const { return std::get<double>(data_); }
  const std::string& as_string() const { return std::get<std::string>(data_); }
  const Array& as_array() const { return std::get<Array>(data_); }
  const Object& as_object() const { return std::get<Object>(data_); }
  Array& as_array() { return std::get<Array>(data_); }
  Object& as_object() { return std::get<Object>(data_); }

  // Object member access; find returns nullptr when absent.
  const Value* find(const std::string& key) const;
  const Value& at(const std::string& key) const;  // throws std::out_of_range naming the key
  // Appends or replaces a member (the value must be an object or null).
  Value& set(const std::string& key, Value value);

 private:
  std::variant<std::monostate, bool, double, std::string, Array, Object> data_;
};

Value parse(const std::string& text);
// Indented output; non-finite numbers are written as null; numbers round-trip exactly.
std::string write(const Value& value, int indent = 2);

}  // namespace nephele::json
