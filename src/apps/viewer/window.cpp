#include "apps/viewer/window.hpp"
#include "gpu/driver_lifetime.hpp"

#include <epoxy/gl.h>
// After epoxy: GLFW must not include a GL header of its own.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdlib>

namespace nephele::viewer {
namespace {

std::string last_glfw_error;

void record_error(int, const char* description) { last_glfw_error = description ? description : "unknown"; }

}  // namespace

std::string no_window_message(const std::string& reason) {
  return "no window: " + reason +
         ". Without a display, run the viewer under a virtual X server (xvfb-run -a nephele view ...) "
         "or render headless (nephele render ...)";
}

Window::Window(int width, int height, const std::string& title, bool visible) {
  // GLFW 3.3 on Debian opens X11 displays; check first so that the message is plain.
  const char* display = std::getenv("DISPLAY");
  if (display == nullptr || *display == '\0') throw WindowError(no_window_message("DISPLAY is not set"));
  glfwSetErrorCallback(record_error);
  if (glfwInit() != GLFW_TRUE) throw WindowError(no_window_message("GLFW cannot start (" + last_glfw_error + ")"));
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_VISIBLE, visible ? GLFW_TRUE : GLFW_FALSE);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (window_ == nullptr) {
    const std::string reason = "no OpenGL 4.5 core window on " + std::string(display) + " (" + last_glfw_error + ")";
    glfwTerminate();
    throw WindowError(no_window_message(reason));
  }
  glfwMakeContextCurrent(window_);
  gpu::keep_drivers_loaded();  // sanitizer builds: see gpu/driver_lifetime.hpp
  glfwSwapInterval(0);         // the refinement, not the monitor, paces the frames
  info_.platform = "window";
  info_.vendor = reinterpret_cast<const char*>(glGetString(GL_VENDOR));
  info_.renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  info_.version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
}

Window::~Window() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

void Window::make_current() { glfwMakeContextCurrent(window_); }

void Window::framebuffer_size(int& width, int& height) const { glfwGetFramebufferSize(window_, &width, &height); }

}  // namespace nephele::viewer
