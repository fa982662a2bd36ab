#include "gpu/storage_buffer.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace nephele::gpu {

StorageBuffer::StorageBuffer(size_t bytes, const void* data) : bytes_(bytes) {
  glCreateBuffers(1, &id_);
  glNamedBufferStorage(id_, static_cast<GLsizeiptr>(bytes), data, GL_DYNAMIC_STORAGE_BIT | GL_MAP_READ_BIT);
  // A buffer the driver could not allocate has no storage (GL_OUT_OF_MEMORY); asked of the buffer
  // itself, so that an earlier call's error flag is left to whoever checks it.
  GLint64 allocated = 0;
  glGetNamedBufferParameteri64v(id_, GL_BUFFER_SIZE, &allocated);
  if (bytes > 0 && static_cast<size_t>(allocated) != bytes) {
    glDeleteBuffers(1, &id_);
    throw std::runtime_error("could not allocate a storage buffer of " + std::to_string(bytes) + " bytes");
  }
}

StorageBuffer::~StorageBuffer() {
  if (id_) glDeleteBuffers(1, &id_);
}

StorageBuffer::StorageBuffer(StorageBuffer&& other) noexcept
    : id_(std::exchange(other.id_, 0)), bytes_(std::exchange(other.bytes_, 0)) {}

StorageBuffer& StorageBuffer::operator=(StorageBuffer&& other) noexcept {
  if (this != &other) {
    if (id_) glDeleteBuffers(1, &id_);
    id_ = std::exchange(other.id_, 0);
    bytes_ = std::exchange(other.bytes_, 0);
  }
  return *this;
}

void StorageBuffer::bind(GLuint binding) const { glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, id_); }

void StorageBuffer::write(const void* data, size_t bytes, size_t offset) const {
  if (bytes > 0) glNamedBufferSubData(id_, static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), data);
}

void StorageBuffer::read(void* out, size_t bytes, size_t offset) const {
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  if (bytes > 0) glGetNamedBufferSubData(id_, static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), out);
}

std::vector<float> StorageBuffer::read_floats() const {
  std::vector<float> out(bytes_ / sizeof(float));
  read(out.data(), out.size() * sizeof(float));
  return out;
}

void reserve(StorageBuffer& buffer, size_t bytes) {
  if (buffer.bytes() < bytes) buffer = StorageBuffer(bytes);
}

void upload(StorageBuffer& buffer, const void* data, size_t bytes, size_t minimum) {
  reserve(buffer, std::max(bytes, minimum));
  buffer.write(data, bytes);
}

}  // namespace nephele::gpu
