// The fuzz corpora (tests/fuzz/corpus/<target>/: seeds and every input a fuzzer found a bug with)
// replayed through the fuzz target bodies, so that the normal suite keeps the fixes
// (docs/testing.md). A parser may refuse an input with its typed error, nothing else.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <vector>

#include "fuzz/fuzz_targets.hpp"

namespace {

namespace fs = std::filesystem;

const fs::path corpus_root = fs::path(NEPHELE_SOURCE_DIR) / "tests" / "fuzz" / "corpus";

std::vector<std::uint8_t> read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST_CASE("Every fuzz corpus input is parsed or refused with the parser's own error", "[fast][fuzz]") {
  for (const auto& target : nephele::fuzz::targets()) {
    const fs::path folder = corpus_root / target.name;
    size_t inputs = 0;
    for (const auto& entry : fs::directory_iterator(folder)) {
      if (!entry.is_regular_file()) continue;
      const std::vector<std::uint8_t> bytes = read_bytes(entry.path());
      INFO("target " << target.name << ", input " << entry.path().filename().string());
      CHECK_NOTHROW(target.run(bytes.data(), bytes.size()));
      ++inputs;
    }
    INFO("target " << target.name);
    CHECK(inputs > 0);
  }
}

TEST_CASE("Every fuzz corpus folder belongs to a fuzz target", "[fast][fuzz]") {
  std::set<std::string> names;
  for (const auto& target : nephele::fuzz::targets()) names.insert(target.name);
  for (const auto& entry : fs::directory_iterator(corpus_root)) {
    INFO("folder " << entry.path().filename().string());
    CHECK(names.count(entry.path().filename().string()) == 1);
  }
}
