// libFuzzer entry point for the number scanner and message escaping (tests/fuzz/fuzz_targets.cpp).
#include "fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  nephele::fuzz::text_input(data, size);
  return 0;
}
