// libFuzzer entry point for the cloud model target (tests/fuzz/fuzz_targets.cpp; docs/testing.md).
#include "fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  nephele::fuzz::cloud_model_input(data, size);
  return 0;
}
