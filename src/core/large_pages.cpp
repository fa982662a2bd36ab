#include "core/large_pages.hpp"

#include <malloc.h>
#include <sys/mman.h>

#include <cerrno>
#include <cstdint>

namespace nephele::core {

namespace {
constexpr std::uintptr_t huge_page_bytes = std::uintptr_t(2) << 20;
}

bool advise_huge_pages(void* block, std::size_t bytes) {
  const auto first = reinterpret_cast<std::uintptr_t>(block);
  const std::uintptr_t begin = (first + huge_page_bytes - 1) & ~(huge_page_bytes - 1);
  const std::uintptr_t end = (first + bytes) & ~(huge_page_bytes - 1);
  if (end <= begin) return false;
  return ::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE) == 0;
}

void use_large_pages() {
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
}

}  // namespace nephele::core

// glibc's allocator, advised. The program's malloc and its aligned forms interpose glibc's by
// ELF symbol interposition (the glibc manual, "Replacing malloc") for every library in the
// process: the GL driver's textures, OpenImageIO's buffers, and C++'s operator new, which calls
// malloc. They forward to glibc's own (__libc_malloc, __libc_calloc and __libc_memalign, which
// glibc exports for this) and advise large blocks onto huge pages before anything touches them.
// free, realloc and the rest stay glibc's: every block is still its. Not with AddressSanitizer,
// which replaces the allocator itself (large_blocks_advised).
#ifndef NEPHELE_ADDRESS_SANITIZER
extern "C" {
void* __libc_malloc(std::size_t bytes);
void* __libc_calloc(std::size_t count, std::size_t bytes);
void* __libc_memalign(std::size_t alignment, std::size_t bytes);

namespace {
void* advised(void* block, std::size_t bytes) {
  if (block != nullptr && bytes >= nephele::core::large_block_bytes) nephele::core::advise_huge_pages(block, bytes);
  return block;
}
}  // namespace

void* malloc(std::size_t bytes) { return advised(__libc_malloc(bytes), bytes); }

void* calloc(std::size_t count, std::size_t bytes) {
  // A product that overflows is glibc's to refuse (it returns null and sets ENOMEM).
  void* block = __libc_calloc(count, bytes);
  return bytes != 0 && count <= SIZE_MAX / bytes ? advised(block, count * bytes) : block;
}

int posix_memalign(void** out, std::size_t alignment, std::size_t bytes) {
  if (alignment % sizeof(void*) != 0 || (alignment & (alignment - 1)) != 0) return EINVAL;
  void* block = __libc_memalign(alignment, bytes);
  if (block == nullptr) return ENOMEM;
  *out = advised(block, bytes);
  return 0;
}

void* aligned_alloc(std::size_t alignment, std::size_t bytes) {
  return advised(__libc_memalign(alignment, bytes), bytes);
}
}
#endif
