#pragma once
// The one reader of typed keys out of json::Value: each read checks the type and names the key
// (with its path, e.g. "at.latitude" or "hourly.time[3]") in the error.
#include <functional>
#include <string>
#include <vector>

#include "core/json.hpp"

namespace nephele::json {

class KeyReader {
 public:
  // Formats the error and throws the caller's exception type (scene and weather files each
  // have theirs); it must not return.
  using Fail = std::function<void(const std::string& key, const std::string& message)>;
  explicit KeyReader(Fail fail) : fail_(std::move(fail)) {}

  [[noreturn]] void fail(const std::string& key, const std::string& message) const;

  // The member `key` of an object; "missing" when absent. `path` prefixes the key in errors.
  const Value& member(const Value& object, const std::string& key, const std::string& path = "") const;
  double number(const Value& v, const std::string& key) const;
  // A number with an integral value of magnitude at most 1e9 (so that it fits an int).
  int integer(const Value& v, const std::string& key) const;
  std::string string(const Value& v, const std::string& key) const;
  bool boolean(const Value& v, const std::string& key) const;
  std::vector<std::string> strings(const Value& v, const std::string& key) const;

 private:
  Fail fail_;
};

}  // namespace nephele::json
