#pragma once
// A parameter as nephele declares it once: its key (scene files and sidecars), option name
// (--key, with '-' for '_'), type, unit, default, allowed range or words, help text, and the
// commands and files that take it. The command line, scene keys, sidecars and (later) the
// viewer's panels are made from these declarations (src/params/table.hpp).
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace nephele::params {

enum class Type { integer, real, text, flag, list };

// Where a parameter is taken: one bit per command (and per file kind that reads it).
enum Use : unsigned {
  generate = 1u << 0,
  bench_cover = 1u << 1,
  report = 1u << 2,
  render = 1u << 3,
  scene_file = 1u << 4,  // a key of `nephele render --scene FILE`
  bench_render = 1u << 5,
  noise = 1u << 6,
  bench_noise = 1u << 7,
  cover_sidecar = 1u << 8,  // written to cover.json
  model = 1u << 9,          // nephele model
  model_file = 1u << 10,    // a key of a cloud model file (scenes/*.cloud.json)
  bench_model = 1u << 11,
  export_cover = 1u << 12,  // nephele export
  viewer = 1u << 13,        // nephele view: its options and its window's panels (src/apps/viewer)
  bench_view = 1u << 14,    // nephele bench view
  stats = 1u << 15,         // nephele stats
  assemble = 1u << 16,      // nephele assemble
};

struct Parameter {
  std::string_view key;
  Type type;
  std::string_view unit;          // "" for plain numbers and words
  double default_number;          // integer and real parameters (flags: 0)
  std::string_view default_text;  // text and list parameters ("" = none)
  double min, max;                // integer and real: inclusive range
  std::string_view allowed;       // text: the allowed words "a|b|c", or the form, e.g. "WIDTHxHEIGHT"
  std::string_view help;
  unsigned uses;
  std::string_view sidecar = "";  // path in a sidecar when it differs from the key ("potential.octaves")

  std::string option() const;           // "--view-steps" for key "view_steps"
  std::string range_text() const;       // "1 to 4096", "euler, heun, rk4", "WIDTHxHEIGHT"
  std::string default_display() const;  // "48", "0.006", "gurten"; "" when there is none
  // Text: the allowed words when `allowed` lists lower-case words ("euler|heun"), else empty
  // (a form such as WIDTHxHEIGHT, or free text).
  std::vector<std::string> words() const;
  bool used_by(unsigned use) const { return (uses & use) != 0; }
  constexpr std::string_view sidecar_path() const { return sidecar.empty() ? key : sidecar; }
  constexpr int default_int() const { return static_cast<int>(default_number); }
  constexpr float default_float() const { return static_cast<float>(default_number); }
  constexpr std::uint32_t default_uint32() const { return static_cast<std::uint32_t>(default_number); }
};

// The width and height of a default "WIDTHxHEIGHT" text, at compile time (0 when malformed).
constexpr int size_part(std::string_view text, bool height) {
  const auto x = text.find('x');
  if (x == std::string_view::npos) return 0;
  const std::string_view digits = height ? text.substr(x + 1) : text.substr(0, x);
  int value = 0;
  for (char c : digits) {
    if (c < '0' || c > '9') return 0;
    value = 10 * value + (c - '0');
  }
  return value;
}

// Factories that keep the table readable (src/params/table.hpp).
constexpr Parameter integer(std::string_view key, double default_value, double min, double max, std::string_view unit,
                            std::string_view help, unsigned uses, std::string_view sidecar = "") {
  return {key, Type::integer, unit, default_value, "", min, max, "", help, uses, sidecar};
}
constexpr Parameter real(std::string_view key, double default_value, double min, double max, std::string_view unit,
                         std::string_view help, unsigned uses, std::string_view sidecar = "") {
  return {key, Type::real, unit, default_value, "", min, max, "", help, uses, sidecar};
}
constexpr Parameter text(std::string_view key, std::string_view default_value, std::string_view allowed,
                         std::string_view help, unsigned uses) {
  return {key, Type::text, "", 0, default_value, 0, 0, allowed, help, uses};
}
constexpr Parameter flag(std::string_view key, std::string_view help, unsigned uses) {
  return {key, Type::flag, "", 0, "", 0, 1, "", help, uses};
}
// A parameter that may be given several times (each value appended).
constexpr Parameter list(std::string_view key, std::string_view allowed, std::string_view help, unsigned uses) {
  return {key, Type::list, "", 0, "", 0, 0, allowed, help, uses};
}

}  // namespace nephele::params
