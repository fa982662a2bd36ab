#pragma once
// A POSIX file descriptor that closes itself, and whole reads and writes through one, for the
// readers and writers that need open(2)'s flags (O_NONBLOCK, O_NOFOLLOW, O_EXCL): the guarded
// input reader, the output sets and the noise cache.
#include <unistd.h>

#include <cerrno>
#include <cstddef>
#include <utility>

namespace nephele::core {

class FileDescriptor {
 public:
  explicit FileDescriptor(int fd = -1) : fd_(fd) {}
  ~FileDescriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  FileDescriptor(FileDescriptor&& other) noexcept : fd_(other.release()) {}
  FileDescriptor(const FileDescriptor&) = delete;
  FileDescriptor& operator=(const FileDescriptor&) = delete;
  int get() const { return fd_; }
  int release() { return std::exchange(fd_, -1); }
  // Owns `fd` from now on, closing the one held before.
  void reset(int fd) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = fd;
  }
  // Closes now, so that close's own error (a write that failed late) is seen.
  bool close() { return ::close(release()) == 0; }

 private:
  int fd_;
};

// Reads exactly `bytes`, retrying after signals; false at an error or an early end of file.
inline bool read_exactly(int fd, void* data, std::size_t bytes) {
  auto* p = static_cast<char*>(data);
  while (bytes > 0) {
    const ssize_t n = ::read(fd, p, bytes);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    p += n;
    bytes -= static_cast<std::size_t>(n);
  }
  return true;
}

// Writes all `bytes`, retrying after signals; false at an error, with errno saying which.
inline bool write_exactly(int fd, const void* data, std::size_t bytes) {
  const auto* p = static_cast<const char*>(data);
  while (bytes > 0) {
    const ssize_t n = ::write(fd, p, bytes);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return false;
    if (n == 0) {
      errno = EIO;  // no progress: never loop on it
      return false;
    }
    p += n;
    bytes -= static_cast<std::size_t>(n);
  }
  return true;
}

// Writes all `bytes` at `offset` (pwrite), retrying after signals; false at an error, with errno
// saying which.
inline bool write_exactly_at(int fd, const void* data, std::size_t bytes, off_t offset) {
  const auto* p = static_cast<const char*>(data);
  while (bytes > 0) {
    const ssize_t n = ::pwrite(fd, p, bytes, offset);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return false;
    if (n == 0) {
      errno = EIO;
      return false;
    }
    p += n, offset += n;
    bytes -= static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace nephele::core
