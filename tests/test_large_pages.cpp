// The allocator policy of core/large_pages.hpp: large blocks from malloc (and so from new) are
// advised onto transparent huge pages, and the blocks stay glibc's. (A small block may lie in heap
// memory an earlier large block had advised, so it is not checked for the absence of advice.)
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "core/large_pages.hpp"

namespace {

// The kernel's mode for transparent huge pages, the bracketed word of its sysfs file ("always",
// "madvise", "never"); empty where there is no such file.
std::string huge_page_mode() {
  std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string line;
  std::getline(in, line);
  const auto open = line.find('['), close = line.find(']');
  return open == std::string::npos || close == std::string::npos ? "" : line.substr(open + 1, close - open - 1);
}

// Whether the mapping that holds `address` may take huge pages: its VmFlags in /proc/self/smaps
// carry "hg" (VM_HUGEPAGE, what MADV_HUGEPAGE sets; proc(5)).
bool advised_huge(const void* address) {
  const auto at = reinterpret_cast<std::uintptr_t>(address);
  std::ifstream smaps("/proc/self/smaps");
  std::string line;
  bool inside = false;
  while (std::getline(smaps, line)) {
    std::uintptr_t begin = 0, end = 0;
    char dash = 0;
    std::istringstream range(line);
    if (range >> std::hex >> begin >> dash >> end && dash == '-' && line.find(':') > line.find(' ')) {
      inside = begin <= at && at < end;
      continue;
    }
    if (inside && line.rfind("VmFlags:", 0) == 0) return (" " + line.substr(8) + " ").find(" hg ") != std::string::npos;
  }
  return false;
}

constexpr std::size_t MiB = std::size_t(1) << 20;

}  // namespace

TEST_CASE("a large block from malloc or new is advised onto huge pages", "[fast][memory]") {
  if (huge_page_mode() == "never" || huge_page_mode().empty()) {
    WARN("this kernel has no transparent huge pages (mode '" << huge_page_mode() << "'): nothing to advise");
    return;
  }
  if (!nephele::core::large_blocks_advised) {
    WARN("built with AddressSanitizer, whose allocator serves every block: nothing is advised");
    return;
  }
  // 8 MiB holds at least three whole aligned 2 MiB pages wherever it starts; its middle byte lies in one.
  void* large = std::malloc(8 * MiB);
  REQUIRE(large != nullptr);
  CHECK(advised_huge(static_cast<char*>(large) + 4 * MiB));
  std::free(large);
  const auto vector = std::make_unique<std::vector<float>>(2 * MiB);  // 8 MiB through operator new
  CHECK(advised_huge(vector->data() + MiB));
}

TEST_CASE("huge-page advice covers only the whole 2 MiB pages inside a block", "[fast][memory]") {
  // A block that holds no whole aligned 2 MiB page has nothing to advise; one that does is advised.
  alignas(64) static char tiny[4096];
  CHECK_FALSE(nephele::core::advise_huge_pages(tiny, sizeof tiny));
  void* block = std::aligned_alloc(2 * MiB, 6 * MiB);
  REQUIRE(block != nullptr);
  CHECK_FALSE(nephele::core::advise_huge_pages(static_cast<char*>(block) + 1, 2 * MiB));  // ends 1 byte short
  CHECK(nephele::core::advise_huge_pages(block, 2 * MiB));
  std::free(block);
}

TEST_CASE("blocks from the interposed allocator are glibc's: calloc zeroes, posix_memalign aligns, realloc keeps",
          "[fast][memory]") {
  auto* zeros = static_cast<unsigned char*>(std::calloc(5 * MiB, 1));
  REQUIRE(zeros != nullptr);
  bool all_zero = true;
  for (std::size_t k = 0; k < 5 * MiB; k += 4093) all_zero = all_zero && zeros[k] == 0;
  CHECK(all_zero);
  std::memset(zeros, 7, 5 * MiB);
  // realloc is glibc's own: it must accept the interposed malloc's block and keep its bytes.
  auto* grown = static_cast<unsigned char*>(std::realloc(zeros, 9 * MiB));
  REQUIRE(grown != nullptr);
  CHECK(grown[0] == 7);
  CHECK(grown[5 * MiB - 1] == 7);
  std::free(grown);
  void* aligned = nullptr;
  REQUIRE(posix_memalign(&aligned, 4096, 6 * MiB) == 0);
  CHECK(reinterpret_cast<std::uintptr_t>(aligned) % 4096 == 0);
  std::free(aligned);
  // Not a power of two: refused as glibc refuses it (AddressSanitizer's allocator, which serves
  // sanitized builds, aborts on it instead).
  if (nephele::core::large_blocks_advised) {
    void* bad = nullptr;
    CHECK(posix_memalign(&bad, 3, 64) != 0);
  }
}
