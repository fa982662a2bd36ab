#include "files/scratch_floats.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>

#include "core/file_descriptor.hpp"

namespace nephele::files {
namespace {
std::runtime_error failure(const std::string& what, const std::filesystem::path& path) {
  return std::runtime_error("could not " + what + " " + path.string() + ": " + std::strerror(errno));
}
}  // namespace

ScratchFloats::ScratchFloats(std::filesystem::path path) : path_(std::move(path)) {
  fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
  if (fd_ < 0) throw failure("create", path_);
}

ScratchFloats::~ScratchFloats() {
  if (mapped_) ::munmap(mapped_, count_ * sizeof(float));
  if (fd_ >= 0) ::close(fd_);
  ::unlink(path_.c_str());
}

void ScratchFloats::append(const float* values, std::size_t count) {
  if (mapped_) throw std::logic_error("ScratchFloats: append after map");
  if (!core::write_exactly(fd_, values, count * sizeof(float))) throw failure("write", path_);
  count_ += count;
}

const float* ScratchFloats::map() {
  if (!mapped_ && count_ > 0) {
    void* at = ::mmap(nullptr, count_ * sizeof(float), PROT_READ, MAP_SHARED, fd_, 0);
    if (at == MAP_FAILED) throw failure("map", path_);
    mapped_ = at;
  }
  return static_cast<const float*>(mapped_);
}

}  // namespace nephele::files
