#pragma once
// A scratch file of floats, written in order and then mapped read-only: the faces of a cover
// too large for the GPU's memory, which the streamed equirect map reads at random
// (io/cover_assembly.cpp). The kernel pages in the rows that are read and drops them again
// under memory pressure, so the process holds no more than the pages in use. The file is
// removed when the object goes (and, inside an output set's temporary directory, with it).
#include <cstddef>
#include <filesystem>

namespace nephele::files {

class ScratchFloats {
 public:
  // Creates `path` (it must not exist); throws std::runtime_error naming it.
  explicit ScratchFloats(std::filesystem::path path);
  ~ScratchFloats();
  ScratchFloats(const ScratchFloats&) = delete;
  ScratchFloats& operator=(const ScratchFloats&) = delete;
  // Appends `count` floats; every write checked.
  void append(const float* values, std::size_t count);
  // The floats written, mapped read-only; no append after.
  const float* map();
  std::size_t size() const { return count_; }

 private:
  std::filesystem::path path_;
  int fd_ = -1;
  std::size_t count_ = 0;
  void* mapped_ = nullptr;
};

}  // namespace nephele::files
