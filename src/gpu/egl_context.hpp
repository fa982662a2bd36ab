#pragma once
// A headless OpenGL 4.5 core context through EGL: the EGL device platform when a
// hardware driver offers one, else Mesa's surfaceless platform (llvmpipe on the CPU).
#include <string>
#include <vector>

#include "gpu/context.hpp"

namespace nephele::gpu {

class EglContext : public Context {
 public:
  // NEPHELE_EGL_PLATFORM=surfaceless|device restricts the platforms tried.
  EglContext();
  ~EglContext() override;
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  const ContextInfo& info() const override { return info_; }
  void make_current() override;

 private:
  bool try_display(void* display, const std::string& platform, std::vector<std::string>& attempts);
  void* display_ = nullptr;
  void* context_ = nullptr;
  ContextInfo info_;
};

}  // namespace nephele::gpu
