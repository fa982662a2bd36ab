#pragma once
// The viewer's window: a GLFW window whose OpenGL 4.5 core context is the gpu::Context every
// pass runs in (the renderer never makes an EGL context of its own while the window is open).
#include <string>

#include "gpu/context.hpp"

struct GLFWwindow;

namespace nephele::viewer {

// No display, or no OpenGL 4.5 context on it: exit code 3 (the message says what to run instead).
class WindowError : public gpu::ContextError {
 public:
  using gpu::ContextError::ContextError;
};

class Window : public gpu::Context {
 public:
  // Opens a window of width x height screen units with an OpenGL 4.5 core context, current on
  // the calling thread; `visible` false for tests that never show it.
  Window(int width, int height, const std::string& title, bool visible = true);
  ~Window() override;
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  const gpu::ContextInfo& info() const override { return info_; }
  void make_current() override;
  GLFWwindow* handle() const { return window_; }
  // Size of the default framebuffer in pixels.
  void framebuffer_size(int& width, int& height) const;

 private:
  GLFWwindow* window_ = nullptr;
  gpu::ContextInfo info_;
};

// The message of a WindowError: what failed, and the commands that work without a display.
std::string no_window_message(const std::string& reason);

}  // namespace nephele::viewer
