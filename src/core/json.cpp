#include "core/json.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <unordered_set>

namespace nephele::json {

ParseError::ParseError(const std::string& message, size_t line_, size_t column_)
    : std::runtime_error("line " + std::to_string(line_) + ", column " + std::to_string(column_) + ": " + message),
      line(line_),
      column(column_) {}

Value::Value(float f) {
  double shortest = f;
  if (std::isfinite(f)) {
    for (int digits = 1; digits <= 9; ++digits) {
      char buffer[32];
      std::snprintf(buffer, sizeof buffer, "%.*g", digits, static_cast<double>(f));
      if (std::strtof(buffer, nullptr) == f) {
        shortest = std::strtod(buffer, nullptr);
        break;
      }
    }
  }
  data_ = shortest;
}

const Value* Value::find(const std::string& key) const {
  if (!is_object()) return nullptr;
  for (const auto& [k, v] : as_object())
    if (k == key) return &v;
  return nullptr;
}

const Value& Value::at(const std::string& key) const {
  const Value* v = find(key);
  if (!v) throw std::out_of_range("missing key '" + key + "'");
  return *v;
}

Value& Value::set(const std::string& key, Value value) {
  if (is_null()) data_ = Object{};
  for (auto& [k, v] : as_object())
    if (k == key) return v = std::move(value);
  as_object().emplace_back(key, std::move(value));
  return as_object().back().second;
}

namespace {

class Parser {
 public:
  explicit Parser(const std::string& text) : s_(text) {}

  Value document() {
    check_utf8();
    Value v = value(0);
    whitespace();
    if (pos_ != s_.size()) fail("unexpected text after the JSON value");
    return v;
  }

 private:
  [[noreturn]] void fail(const std::string& message) const {
    size_t line = 1, column = 1;
    for (size_t i = 0; i < pos_ && i < s_.size(); ++i) {
      if (s_[i] == '\n') {
        ++line;
        column = 1;
      } else {
        ++column;
      }
    }
    throw ParseError(message, line, column);
  }
  // RFC 8259 text is UTF-8: refuse malformed sequences, overlong forms, surrogates and code
  // points past U+10FFFF (RFC 3629), naming the byte offset of the first bad byte.
  void check_utf8() {
    const size_t n = s_.size();
    for (size_t i = 0; i < n;) {
      const unsigned char b = static_cast<unsigned char>(s_[i]);
      size_t length = 0;
      unsigned char low = 0x80, high = 0xBF;  // allowed range of the second byte
      if (b < 0x80)
        length = 1;
      else if (b >= 0xC2 && b <= 0xDF)
        length = 2;
      else if (b == 0xE0)
        length = 3, low = 0xA0;
      else if (b == 0xED)
        length = 3, high = 0x9F;  // no UTF-16 surrogates
      else if (b >= 0xE1 && b <= 0xEF)
        length = 3;
      else if (b == 0xF0)
        length = 4, low = 0x90;
      else if (b == 0xF4)
        length = 4, high = 0x8F;  // nothing past U+10FFFF
      else if (b >= 0xF1 && b <= 0xF3)
        length = 4;
      // The offset of the first bad byte: the lead byte, a continuation byte, or the end of the text.
      bool valid = length != 0;
      size_t bad = i;
      for (size_t k = 1; k < length && valid; ++k) {
        bad = i + k;
        if (bad >= n)
          valid = false;
        else {
          const unsigned char c = static_cast<unsigned char>(s_[bad]);
          valid = c >= (k == 1 ? low : 0x80) && c <= (k == 1 ? high : 0xBF);
        }
      }
      if (!valid) {
        pos_ = bad;
        char byte[8] = "end";
        if (bad < n) std::snprintf(byte, sizeof byte, "0x%02x", static_cast<unsigned char>(s_[bad]));
        fail("invalid UTF-8 at byte offset " + std::to_string(bad) + " (" + byte + ")");
      }
      i += length;
    }
  }
  void whitespace() {
    while (pos_ < s_.size() && (s_[pos_] == ' ' || s_[pos_] == '\t' || s_[pos_] == '\n' || s_[pos_] == '\r')) ++pos_;
  }
  bool consume(char c) {
    whitespace();
    if (pos_ < s_.size() && s_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }
  void expect(char c) {
    if (!consume(c)) fail(std::string("expected '") + c + "'");
  }
  bool literal(const char* word) {
    size_t n = std::char_traits<char>::length(word);
    if (s_.compare(pos_, n, word) == 0) {
      pos_ += n;
      return true;
    }
    return false;
  }

  Value value(int depth) {
    if (depth > 256) fail("nesting deeper than 256");
    whitespace();
    if (pos_ >= s_.size()) fail("unexpected end of input");
    const char c = s_[pos_];
    if (c == '{') return object(depth);
    if (c == '[') return array(depth);
    if (c == '"') return Value(string());
    if (literal("true")) return Value(true);
    if (literal("false")) return Value(false);
    if (literal("null")) return Value();
    if (c == '-' || (c >= '0' && c <= '9')) return Value(number());
    fail(std::string("unexpected character '") + c + "'");
  }

  Value object(int depth) {
    ++pos_;
    Value::Object members;
    if (consume('}')) return Value(std::move(members));
    // A hash set keeps the duplicate check linear in the number of keys (a scan per key was
    // quadratic: 160k keys took 23 s).
    std::unordered_set<std::string> seen;
    do {
      whitespace();
      if (pos_ >= s_.size() || s_[pos_] != '"') fail("expected a string key");
      std::string key = string();
      if (!seen.insert(key).second) fail("duplicate key '" + key + "'");
      expect(':');
      members.emplace_back(std::move(key), value(depth + 1));
    } while (consume(','));
    expect('}');
    return Value(std::move(members));
  }

  Value array(int depth) {
    ++pos_;
    Value::Array items;
    if (consume(']')) return Value(std::move(items));
    do items.push_back(value(depth + 1));
    while (consume(','));
    expect(']');
    return Value(std::move(items));
  }

  static void append_utf8(std::string& out, unsigned code) {
    if (code < 0x80) {
      out += static_cast<char>(code);
    } else if (code < 0x800) {
      out += static_cast<char>(0xC0 | (code >> 6));
      out += static_cast<char>(0x80 | (code & 0x3F));
    } else if (code < 0x10000) {
      out += static_cast<char>(0xE0 | (code >> 12));
      out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (code & 0x3F));
    } else {
      out += static_cast<char>(0xF0 | (code >> 18));
      out += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
      out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (code & 0x3F));
    }
  }

  unsigned hex4() {
    if (pos_ + 4 > s_.size()) fail("truncated \\u escape");
    unsigned code = 0;
    for (int i = 0; i < 4; ++i) {
      const char h = s_[pos_++];
      code <<= 4;
      if (h >= '0' && h <= '9')
        code |= h - '0';
      else if (h >= 'a' && h <= 'f')
        code |= h - 'a' + 10;
      else if (h >= 'A' && h <= 'F')
        code |= h - 'A' + 10;
      else
        fail("bad hex digit in \\u escape");
    }
    return code;
  }

  std::string string() {
    ++pos_;  // opening quote
    std::string out;
    while (true) {
      if (pos_ >= s_.size()) fail("unterminated string");
      const char c = s_[pos_++];
      if (c == '"') return out;
      if (static_cast<unsigned char>(c) < 0x20) fail("control character in string");
      if (c != '\\') {
        out += c;
        continue;
      }
      if (pos_ >= s_.size()) fail("unterminated escape");
      const char e = s_[pos_++];
      switch (e) {
        case '"': out += '"'; break;
        case '\\': out += '\\'; break;
        case '/': out += '/'; break;
        case 'b': out += '\b'; break;
        case 'f': out += '\f'; break;
        case 'n': out += '\n'; break;
        case 'r': out += '\r'; break;
        case 't': out += '\t'; break;
        case 'u': {
          unsigned code = hex4();
          if (code >= 0xD800 && code < 0xDC00) {
            if (!literal("\\u")) fail("lone high surrogate");
            const unsigned low = hex4();
            if (low < 0xDC00 || low >= 0xE000) fail("bad low surrogate");
            code = 0x10000 + ((code - 0xD800) << 10) + (low - 0xDC00);
          } else if (code >= 0xDC00 && code < 0xE000) {
            fail("lone low surrogate");
          }
          append_utf8(out, code);
          break;
        }
        default: fail(std::string("bad escape '\\") + e + "'");
      }
    }
  }

  double number() {
    const size_t start = pos_;
    auto digits = [&] {
      const size_t from = pos_;
      while (pos_ < s_.size() && s_[pos_] >= '0' && s_[pos_] <= '9') ++pos_;
      return pos_ - from;
    };
    if (s_[pos_] == '-') ++pos_;
    if (pos_ < s_.size() && s_[pos_] == '0')
      ++pos_;
    else if (digits() == 0)
      fail("bad number");
    if (pos_ < s_.size() && s_[pos_] == '.') {
      ++pos_;
      if (digits() == 0) fail("bad number: digits expected after '.'");
    }
    if (pos_ < s_.size() && (s_[pos_] == 'e' || s_[pos_] == 'E')) {
      ++pos_;
      if (pos_ < s_.size() && (s_[pos_] == '+' || s_[pos_] == '-')) ++pos_;
      if (digits() == 0) fail("bad number: exponent digits expected");
    }
    const std::string text = s_.substr(start, pos_ - start);
    const double v = std::strtod(text.c_str(), nullptr);
    if (!std::isfinite(v)) fail("number out of range");
    return v;
  }

  const std::string& s_;
  size_t pos_ = 0;
};

void write_string(std::string& out, const std::string& s) {
  out += '"';
  for (const char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buffer[8];
          std::snprintf(buffer, sizeof buffer, "\\u%04x", c);
          out += buffer;
        } else {
          out += c;
        }
    }
  }
  out += '"';
}

void write_value(std::string& out, const Value& v, int indent, int level) {
  const std::string pad = indent > 0 ? "\n" + std::string(static_cast<size_t>(indent) * (level + 1), ' ') : "";
  const std::string close = indent > 0 ? "\n" + std::string(static_cast<size_t>(indent) * level, ' ') : "";
  if (v.is_null()) {
    out += "null";
  } else if (v.is_bool()) {
    out += v.as_bool() ? "true" : "false";
  } else if (v.is_number()) {
    const double d = v.as_number();
    if (!std::isfinite(d)) {
      out += "null";
    } else if (d == std::floor(d) && std::abs(d) < 1e15) {
      out += std::to_string(static_cast<long long>(d));
    } else {
      char buffer[32];
      for (int digits = 15; digits <= 17; ++digits) {  // shortest that round-trips
        std::snprintf(buffer, sizeof buffer, "%.*g", digits, d);
        if (std::strtod(buffer, nullptr) == d) break;
      }
      out += buffer;
    }
  } else if (v.is_string()) {
    write_string(out, v.as_string());
  } else if (v.is_array()) {
    const auto& items = v.as_array();
    if (items.empty()) {
      out += "[]";
      return;
    }
    out += '[';
    for (size_t i = 0; i < items.size(); ++i) {
      out += (i ? "," : "") + pad;
      write_value(out, items[i], indent, level + 1);
    }
    out += close + "]";
  } else {
    const auto& members = v.as_object();
    if (members.empty()) {
      out += "{}";
      return;
    }
    out += '{';
    for (size_t i = 0; i < members.size(); ++i) {
      out += (i ? "," : "") + pad;
      write_string(out, members[i].first);
      out += indent > 0 ? ": " : ":";
      write_value(out, members[i].second, indent, level + 1);
    }
    out += close + "}";
  }
}

}  // namespace

Value parse(const std::string& text) { return Parser(text).document(); }

std::string write(const Value& value, int indent) {
  std::string out;
  write_value(out, value, indent, 0);
  out += '\n';
  return out;
}

}  // namespace nephele::json
