#pragma once
// The OpenGL 4.5 core context every pass runs in, behind one interface: today a headless EGL
// context (gpu/egl_context.hpp); a window's context (GLFW) implements the same interface, so
// the passes and the renderer do not know which one they run in.
#include <stdexcept>
#include <string>

namespace nephele::gpu {

// Thrown when no context can be made; the message names every attempt (exit code 3).
class ContextError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ContextInfo {
  std::string platform;  // "device" or "surfaceless" (EGL), "window" (GLFW)
  std::string vendor;
  std::string renderer;
  std::string version;
};

class Context {
 public:
  virtual ~Context() = default;
  virtual const ContextInfo& info() const = 0;
  // Makes this context current on the calling thread.
  virtual void make_current() = 0;
  // True for software rasterisers (llvmpipe, softpipe, lavapipe): their memory is host memory.
  bool is_software() const;
};

}  // namespace nephele::gpu
