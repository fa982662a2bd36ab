#pragma once
// How the program asks the kernel for memory: large blocks on transparent huge pages, and freed
// heap memory kept for reuse. On the virtual machines this project runs on, the first touch of
// a fresh 4 KiB page costs about 3.6 ms per MiB (a 64 MiB buffer: 230 ms), so the commands'
// images and cube maps spent a quarter of a render's wall time in page faults; a 2 MiB page
// takes one fault for 512 of them (docs/performance.md, "Memory pages").
#include <cstddef>

namespace nephele::core {

// Blocks of at least this many bytes are advised onto huge pages (by the program's malloc, which
// forwards to glibc's: large_pages.cpp).
constexpr std::size_t large_block_bytes = std::size_t(4) << 20;

// Whether the program's malloc advises large blocks (large_pages.cpp): not in builds with
// AddressSanitizer, whose own malloc must serve every block it later frees and checks.
#if defined(__SANITIZE_ADDRESS__)
#define NEPHELE_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define NEPHELE_ADDRESS_SANITIZER 1
#endif
#endif
#ifdef NEPHELE_ADDRESS_SANITIZER
constexpr bool large_blocks_advised = false;
#else
constexpr bool large_blocks_advised = true;
#endif

// Sets the heap's policy for the rest of the process: blocks up to 32 MiB (glibc's own ceiling
// for its dynamic threshold) come from the heap, and up to 256 MiB of freed heap stays mapped for
// reuse instead of being returned and faulted in again. Called first thing in main; idempotent.
void use_large_pages();

// Advises the whole 2 MiB pages inside [block, block + bytes) onto transparent huge pages
// (madvise MADV_HUGEPAGE; the kernel's "madvise" mode, Debian's default, needs the advice).
// Returns whether any range was advised. Harmless on memory already touched.
bool advise_huge_pages(void* block, std::size_t bytes);

}  // namespace nephele::core
