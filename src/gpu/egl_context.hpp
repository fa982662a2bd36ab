#pragma once
// A headless OpenGL 4.5 core context through EGL: the EGL device platform when a
// hardware driver offers one, else Mesa's surfaceless platform (llvmpipe on the CPU).
#include <stdexcept>
#include <string>
#include <vector>

namespace nephele::gpu {

// Thrown when no context can be made; the message names every attempt.
class ContextError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ContextInfo {
  std::string platform;  // "device" or "surfaceless"
  std::string vendor;
  std::string renderer;
  std::string version;
};

class EglContext {
 public:
  // NEPHELE_EGL_PLATFORM=surfaceless|device restricts the platforms tried.
  EglContext();
  ~EglContext();
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  const ContextInfo& info() const { return info_; }
  // True for software rasterisers (llvmpipe, softpipe, lavapipe): their memory is host memory.
  bool is_software() const;

 private:
  bool try_display(void* display, const std::string& platform, std::vector<std::string>& attempts);
  void* display_ = nullptr;
  void* context_ = nullptr;
  ContextInfo info_;
};

}  // namespace nephele::gpu
