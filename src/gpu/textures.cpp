#include "gpu/textures.hpp"

#include <stdexcept>
#include <string>
#include <utility>

namespace nephele::gpu {
namespace {

GLenum pixel_format(int channels) {
  switch (channels) {
    case 1: return GL_RED;
    case 2: return GL_RG;
    case 3: return GL_RGB;
    case 4: return GL_RGBA;
    default: throw std::logic_error("unsupported channel count " + std::to_string(channels));
  }
}

}  // namespace

Texture Texture::cube(int size, GLenum internal_format) {
  Texture t;
  t.target_ = GL_TEXTURE_CUBE_MAP;
  t.format_ = internal_format;
  t.width_ = t.height_ = size;
  t.layers_ = 6;
  glCreateTextures(GL_TEXTURE_CUBE_MAP, 1, &t.id_);
  glTextureStorage2D(t.id_, 1, internal_format, size, size);
  if (glGetError() != GL_NO_ERROR)
    throw std::runtime_error("could not allocate a " + std::to_string(size) + "^2 cube map");
  return t;
}

Texture Texture::plane(int width, int height, GLenum internal_format) {
  Texture t;
  t.target_ = GL_TEXTURE_2D;
  t.format_ = internal_format;
  t.width_ = width;
  t.height_ = height;
  t.layers_ = 1;
  glCreateTextures(GL_TEXTURE_2D, 1, &t.id_);
  glTextureStorage2D(t.id_, 1, internal_format, width, height);
  if (glGetError() != GL_NO_ERROR)
    throw std::runtime_error("could not allocate a " + std::to_string(width) + "x" + std::to_string(height) +
                             " texture");
  return t;
}

Texture Texture::layered(int width, int height, int layers, GLenum internal_format) {
  Texture t;
  t.target_ = GL_TEXTURE_2D_ARRAY;
  t.format_ = internal_format;
  t.width_ = width;
  t.height_ = height;
  t.layers_ = layers;
  glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &t.id_);
  glTextureStorage3D(t.id_, 1, internal_format, width, height, layers);
  if (glGetError() != GL_NO_ERROR)
    throw std::runtime_error("could not allocate a " + std::to_string(width) + "x" + std::to_string(height) + "x" +
                             std::to_string(layers) + " array texture");
  return t;
}

Texture Texture::shaped_like(const Texture& other, GLenum internal_format) {
  if (other.target_ == GL_TEXTURE_CUBE_MAP) return cube(other.width_, internal_format);
  if (other.target_ == GL_TEXTURE_2D) return plane(other.width_, other.height_, internal_format);
  return layered(other.width_, other.height_, other.layers_, internal_format);
}

Texture::~Texture() {
  if (layer_view_) glDeleteTextures(1, &layer_view_);
  if (id_) glDeleteTextures(1, &id_);
}

Texture::Texture(Texture&& other) noexcept { *this = std::move(other); }

Texture& Texture::operator=(Texture&& other) noexcept {
  if (this != &other) {
    if (layer_view_) glDeleteTextures(1, &layer_view_);
    if (id_) glDeleteTextures(1, &id_);
    id_ = std::exchange(other.id_, 0);
    layer_view_ = std::exchange(other.layer_view_, 0);
    target_ = other.target_;
    format_ = other.format_;
    width_ = other.width_;
    height_ = other.height_;
    layers_ = other.layers_;
  }
  return *this;
}

int Texture::channels() const {
  switch (format_) {
    case GL_R32F: return 1;
    case GL_RG32F: return 2;
    case GL_RGB32F: return 3;  // sampled only: GL_RGB32F is no image format
    case GL_RGBA32F: return 4;
    default: throw std::logic_error("unsupported texture format");
  }
}

void Texture::bind_image(GLuint unit, GLenum access) const {
  glBindImageTexture(unit, id_, 0, layers_ > 1 ? GL_TRUE : GL_FALSE, 0, access, format_);
}

void Texture::bind_image_layers(GLuint unit, GLenum access) const {
  GLuint id = id_;
  if (target_ == GL_TEXTURE_CUBE_MAP) {
    if (!layer_view_) {
      // A view needs a name that was never bound: glGenTextures, not glCreateTextures.
      glGenTextures(1, &layer_view_);
      glTextureView(layer_view_, GL_TEXTURE_2D_ARRAY, id_, format_, 0, 1, 0, 6);
    }
    id = layer_view_;
  }
  glBindImageTexture(unit, id, 0, GL_TRUE, 0, access, format_);
}

std::vector<float> Texture::read() const {
  std::vector<float> texels(static_cast<size_t>(width_) * height_ * layers_ * channels());
  glGetTextureImage(id_, 0, pixel_format(channels()), GL_FLOAT, static_cast<GLsizei>(texels.size() * sizeof(float)),
                    texels.data());
  return texels;
}

void Texture::write(const std::vector<float>& texels) const {
  if (texels.size() != static_cast<size_t>(width_) * height_ * layers_ * channels())
    throw std::logic_error("Texture::write: wrong number of texels");
  if (target_ == GL_TEXTURE_2D)
    glTextureSubImage2D(id_, 0, 0, 0, width_, height_, pixel_format(channels()), GL_FLOAT, texels.data());
  else
    glTextureSubImage3D(id_, 0, 0, 0, 0, width_, height_, layers_, pixel_format(channels()), GL_FLOAT, texels.data());
}

void image_barrier() {
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                  GL_SHADER_STORAGE_BARRIER_BIT);
}

}  // namespace nephele::gpu
