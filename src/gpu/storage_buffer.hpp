#pragma once
// An owned shader storage buffer of fixed size: tables a pass writes and a later pass reads,
// counters and lists the host writes and reads back. Its storage takes writes from the host
// (glNamedBufferSubData) and may be mapped for reading.
#include <epoxy/gl.h>

#include <cstddef>
#include <vector>

namespace nephele::gpu {

class StorageBuffer {
 public:
  StorageBuffer() = default;
  // `bytes` of storage holding a copy of `data`'s, or undefined until a pass or write() fills it
  // where `data` is null. Throws std::runtime_error where the driver cannot allocate it.
  explicit StorageBuffer(size_t bytes, const void* data = nullptr);
  ~StorageBuffer();
  StorageBuffer(StorageBuffer&& other) noexcept;
  StorageBuffer& operator=(StorageBuffer&& other) noexcept;
  StorageBuffer(const StorageBuffer&) = delete;
  StorageBuffer& operator=(const StorageBuffer&) = delete;

  GLuint id() const { return id_; }
  size_t bytes() const { return bytes_; }
  // Binds the whole buffer to a shader storage binding point.
  void bind(GLuint binding) const;
  // Copies `bytes` of `data` into the buffer from byte `offset` on (the buffer's contents, not
  // this handle, change: const as bind).
  void write(const void* data, size_t bytes, size_t offset = 0) const;
  // Copies `bytes` from byte `offset` on into `out`, after a barrier for the shaders' writes.
  void read(void* out, size_t bytes, size_t offset = 0) const;
  // Reads the whole buffer as floats, after a barrier for the shaders' writes.
  std::vector<float> read_floats() const;

 private:
  GLuint id_ = 0;
  size_t bytes_ = 0;
};

// `buffer`, replaced by a new one of `bytes` where it holds fewer (the contents then undefined):
// buffers kept between passes or frames grow to the largest need and are not made again.
void reserve(StorageBuffer& buffer, size_t bytes);
// A list of `bytes` of `data` into the start of `buffer`, reserved first for at least `minimum`
// bytes (a storage block must be bound to a buffer, an empty list too). Shaders take the list's
// length from elsewhere (a uniform), not from the block's size, which may be larger.
void upload(StorageBuffer& buffer, const void* data, size_t bytes, size_t minimum = 16);

}  // namespace nephele::gpu
