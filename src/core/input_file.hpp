#pragma once
// Reading a user's input file (scene, weather) whole, with a bound on its size.
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

}  // namespace nephele::core
