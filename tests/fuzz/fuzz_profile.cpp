// libFuzzer entry point for the profile CSV target (tests/fuzz/fuzz_targets.cpp; docs/testing.md).
#include "fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  nephele::fuzz::profile_input(data, size);
  return 0;
}
