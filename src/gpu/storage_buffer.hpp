#pragma once
// An owned shader storage buffer of fixed size, for tables a pass writes and a later pass reads.
#include <epoxy/gl.h>

#include <cstddef>
#include <vector>

namespace nephele::gpu {

class StorageBuffer {
 public:
  StorageBuffer() = default;
  // `bytes` of storage, its contents undefined until a pass writes them.
  explicit StorageBuffer(size_t bytes);
  ~StorageBuffer();
  StorageBuffer(StorageBuffer&& other) noexcept;
  StorageBuffer& operator=(StorageBuffer&& other) noexcept;
  StorageBuffer(const StorageBuffer&) = delete;
  StorageBuffer& operator=(const StorageBuffer&) = delete;

  GLuint id() const { return id_; }
  size_t bytes() const { return bytes_; }
  // Binds the whole buffer to a shader storage binding point.
  void bind(GLuint binding) const;
  // Reads the whole buffer as floats, after a barrier for the shaders' writes.
  std::vector<float> read_floats() const;

 private:
  GLuint id_ = 0;
  size_t bytes_ = 0;
};

}  // namespace nephele::gpu
