#pragma once
// Owned OpenGL textures and the transfers the passes need.
#include <epoxy/gl.h>

#include <vector>

namespace nephele::gpu {

class Texture {
 public:
  Texture() = default;
  // A cube map of size x size texels per face (one mip level), e.g. GL_RGBA32F or GL_R32F.
  static Texture cube(int size, GLenum internal_format);
  static Texture plane(int width, int height, GLenum internal_format);
  // A 2D array texture of `layers` width x height layers (one mip level).
  static Texture layered(int width, int height, int layers, GLenum internal_format);
  // A texture of `other`'s kind and extent (cube map, plane or 2D array) in `internal_format`.
  static Texture shaped_like(const Texture& other, GLenum internal_format);
  ~Texture();
  Texture(Texture&& other) noexcept;
  Texture& operator=(Texture&& other) noexcept;
  Texture(const Texture&) = delete;
  Texture& operator=(const Texture&) = delete;

  GLuint id() const { return id_; }
  GLenum target() const { return target_; }
  int width() const { return width_; }
  int height() const { return height_; }
  int layers() const { return layers_; }  // 6 for cube maps
  int channels() const;
  // Binds level 0, all layers, to an image unit for imageLoad/imageStore.
  void bind_image(GLuint unit, GLenum access) const;
  // Binds level 0, all layers, for an image2DArray in the shader: a cube map through a
  // GL_TEXTURE_2D_ARRAY view of its six faces (made at the first call), so that one shader
  // serves a whole cube map and a tile of a few rows of one face (cover/cube_tiles.hpp).
  void bind_image_layers(GLuint unit, GLenum access) const;
  // Reads all texels as floats (faces in order +X,-X,+Y,-Y,+Z,-Z; rows from t = 0).
  std::vector<float> read() const;
  // Replaces all texels; `texels` holds channels() floats per texel in read()'s order.
  void write(const std::vector<float>& texels) const;

 private:
  GLuint id_ = 0;
  mutable GLuint layer_view_ = 0;  // a cube map's faces as a 2D array (bind_image_layers)
  GLenum target_ = 0;
  GLenum format_ = 0;
  int width_ = 0, height_ = 0, layers_ = 0;
};

// Makes image stores of earlier dispatches visible to later image loads and readbacks.
void image_barrier();

}  // namespace nephele::gpu
