#include "apps/viewer/image_display.hpp"

#include <epoxy/gl.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace nephele::viewer {
namespace {

// Rows of the image from the top, of GL textures from the bottom: the flip is here.
const char* const vertex_shader = R"(#version 450 core
void main() {
  vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  gl_Position = vec4(2.0 * corner - 1.0, 0.0, 1.0);
})";
const char* const fragment_shader = R"(#version 450 core
uniform sampler2D u_image;
uniform vec2 u_viewport;
out vec4 colour;
void main() {
  vec2 uv = gl_FragCoord.xy / u_viewport;
  colour = vec4(texture(u_image, vec2(uv.x, 1.0 - uv.y)).rgb, 1.0);
})";

unsigned compile(GLenum kind, const char* source) {
  const GLuint shader = glCreateShader(kind);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048];
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    throw std::runtime_error(std::string("nephele view: display shader: ") + log);
  }
  return shader;
}

}  // namespace

ImageDisplay::ImageDisplay() {
  program_ = glCreateProgram();
  const GLuint vs = compile(GL_VERTEX_SHADER, vertex_shader), fs = compile(GL_FRAGMENT_SHADER, fragment_shader);
  glAttachShader(program_, vs);
  glAttachShader(program_, fs);
  glLinkProgram(program_);
  glDeleteShader(vs);
  glDeleteShader(fs);
  glCreateVertexArrays(1, &vertex_array_);
}

ImageDisplay::~ImageDisplay() {
  glDeleteTextures(1, &texture_);
  glDeleteProgram(program_);
  glDeleteVertexArrays(1, &vertex_array_);
}

void ImageDisplay::upload(const core::ImageData& display) {
  if (display.width != texture_width_ || display.height != texture_height_) {
    glDeleteTextures(1, &texture_);
    glCreateTextures(GL_TEXTURE_2D, 1, &texture_);
    glTextureStorage2D(texture_, 1, GL_RGBA32F, display.width, display.height);
    glTextureParameteri(texture_, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(texture_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(texture_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(texture_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    texture_width_ = display.width;
    texture_height_ = display.height;
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage2D(texture_, 0, 0, 0, display.width, display.height, GL_RGB, GL_FLOAT, display.pixels.data());
}

void ImageDisplay::draw(int width, int height) const {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, width, height);
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_DEPTH_TEST);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  if (texture_ == 0) return;
  glUseProgram(program_);
  glUniform2f(glGetUniformLocation(program_, "u_viewport"), float(width), float(height));
  glUniform1i(glGetUniformLocation(program_, "u_image"), 0);
  glBindTextureUnit(0, texture_);
  glBindVertexArray(vertex_array_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glUseProgram(0);
}

core::ImageData ImageDisplay::read_framebuffer(int width, int height) {
  std::vector<unsigned char> bytes(std::size_t(width) * height * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
  core::ImageData image{width, height, 3, std::vector<float>(std::size_t(width) * height * 3)};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c)
        image.pixels[(std::size_t(height - 1 - y) * width + x) * 3 + c] =
            bytes[(std::size_t(y) * width + x) * 4 + c] / 255.0f;
  return image;
}

}  // namespace nephele::viewer
