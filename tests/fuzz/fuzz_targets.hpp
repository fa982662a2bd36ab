#pragma once
// The bodies of the fuzz targets, shared by the libFuzzer entry points (tests/fuzz/fuzz_*.cpp,
// built with -DNEPHELE_FUZZ=ON) and the corpus replay test of the normal suite
// (tests/test_fuzz_corpus.cpp). Each feeds one input to a parser: the parser's own typed errors
// are the expected outcome of bad input and are swallowed; anything else escapes, so libFuzzer
// sees a crash (uncaught exception -> abort) and the replay test a failure.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace nephele::fuzz {

// A broken invariant that no sanitizer would notice (e.g. a value that does not read back).
class Finding : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

void json_input(const std::uint8_t* data, std::size_t size);         // core::json parse/write
void time_input(const std::uint8_t* data, std::size_t size);         // core::parse_utc_time
void scene_input(const std::uint8_t* data, std::size_t size);        // io::parse_scene
void weather_input(const std::uint8_t* data, std::size_t size);      // io::parse_weather
void cloud_model_input(const std::uint8_t* data, std::size_t size);  // io::parse_cloud_model
void profile_input(const std::uint8_t* data, std::size_t size);      // io::parse_profile_csv
void text_input(const std::uint8_t* data, std::size_t size);         // core::parse_decimal, core::printable

struct Target {
  const char* name;  // also the folder of its seed corpus, tests/fuzz/corpus/<name>/
  void (*run)(const std::uint8_t* data, std::size_t size);
};
const std::vector<Target>& targets();

}  // namespace nephele::fuzz
