#pragma once
// Reading a user's input file: every file nephele reads goes through these checks (a regular
// file, no FIFO or device, a size within its cap) before a byte is read or allocated.
#include <cstdint>
#include <stdexcept>
#include <string>

namespace nephele::core {

// The largest scene or weather file read: 16 MiB. A year of hourly data from either provider is
// under 2 MiB; the JSON tree of a file takes up to about 40 times its size in memory (a 40-byte
// value per 2-byte "0," of an array), so the bound also keeps a parse below about 650 MiB.
constexpr std::uint64_t max_input_file_bytes = 16u << 20;

// Bad input file; the message starts with the path.
class InputFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The bytes of a regular file of at most `max_bytes`. Devices, FIFOs and directories (/dev/zero,
// /dev/stdin) are refused before reading, as are larger files; the read itself stops one byte
// past the bound, so a file that grows meanwhile cannot make it allocate more.
std::string read_input_file(const std::string& path, std::uint64_t max_bytes = max_input_file_bytes);

// The size of `path` when it is a regular file (checked on the opened descriptor, opened without
// blocking, so a FIFO cannot make it wait); InputFileError naming the path otherwise. For
// readers that do their own reading (images through OpenImageIO, raw volumes).
std::uint64_t regular_file_size(const std::string& path);

// Memory a reader may allocate for what a file's header declares: half the host memory
// available now (MemAvailable), or 8 GiB when that is unknown.
std::uint64_t input_memory_budget_bytes();

}  // namespace nephele::core
