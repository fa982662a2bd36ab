#include "core/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

#include "core/file_descriptor.hpp"
#include "core/memory.hpp"

namespace nephele::core {

std::uint64_t regular_file_size(const std::string& path) {
  const FileDescriptor d(open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC));
  if (d.get() < 0) throw InputFileError(path + ": cannot be read (" + std::strerror(errno) + ")");
  struct stat info {};
  if (fstat(d.get(), &info) != 0) throw InputFileError(path + ": cannot be read (" + std::strerror(errno) + ")");
  if (!S_ISREG(info.st_mode))
    throw InputFileError(path + ": not a regular file (devices, pipes and directories are not read)");
  return static_cast<std::uint64_t>(info.st_size);
}

std::uint64_t input_memory_budget_bytes() {
  const double available = host_memory_available_bytes();
  return available > 0 ? static_cast<std::uint64_t>(available / 2) : std::uint64_t(8) << 30;
}

std::string read_input_file(const std::string& path, std::uint64_t max_bytes) {
  const std::string limit =
      "at most " + std::to_string(max_bytes) + " bytes (" + std::to_string(max_bytes >> 20) + " MiB) are read";
  // Non-blocking open: opening a FIFO for reading would otherwise wait for a writer.
  const int descriptor = open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (descriptor < 0) throw InputFileError(path + ": cannot be read (" + std::strerror(errno) + ")");
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(fdopen(descriptor, "rb"), &std::fclose);
  if (!file) {
    close(descriptor);
    throw InputFileError(path + ": cannot be read (" + std::strerror(errno) + ")");
  }
  struct stat info {};
  if (fstat(descriptor, &info) != 0) throw InputFileError(path + ": cannot be read (" + std::strerror(errno) + ")");
  if (!S_ISREG(info.st_mode))
    throw InputFileError(path + ": not a regular file (devices, pipes and directories are not read)");
  if (static_cast<std::uint64_t>(info.st_size) > max_bytes)
    throw InputFileError(path + ": " + std::to_string(info.st_size) + " bytes is too large; " + limit);
  std::string text;
  char buffer[65536];
  while (true) {
    const size_t n = std::fread(buffer, 1, sizeof buffer, file.get());
    if (n == 0) break;
    if (text.size() + n > max_bytes) throw InputFileError(path + ": larger than the limit; " + limit);
    text.append(buffer, n);
  }
  if (std::ferror(file.get())) throw InputFileError(path + ": read error");
  return text;
}

}  // namespace nephele::core
