#pragma once
// The display pass of nephele view: the tone-mapped image in a texture, stretched over the
// window's framebuffer by one triangle; and the framebuffer read back as the user saw it.
#include "core/image.hpp"

namespace nephele::viewer {

class ImageDisplay {
 public:
  ImageDisplay();  // in the window's current GL context
  ~ImageDisplay();
  ImageDisplay(const ImageDisplay&) = delete;
  ImageDisplay& operator=(const ImageDisplay&) = delete;

  // The image to show (display values, RGB, rows from the top); the texture follows its size.
  void upload(const core::ImageData& display);
  // Clears the default framebuffer and draws the last image over it (nothing before the first).
  void draw(int framebuffer_width, int framebuffer_height) const;
  // The default framebuffer's back buffer: RGB in [0, 1] (8-bit values / 255), rows from the top.
  static core::ImageData read_framebuffer(int width, int height);

 private:
  unsigned texture_ = 0, program_ = 0, vertex_array_ = 0;
  int texture_width_ = 0, texture_height_ = 0;
};

}  // namespace nephele::viewer
