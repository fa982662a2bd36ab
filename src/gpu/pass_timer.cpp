#include "gpu/pass_timer.hpp"

#include <epoxy/gl.h>

namespace nephele::gpu {

void PassTimer::restart() {
  glFinish();
  start_ = std::chrono::steady_clock::now();
}

double PassTimer::milliseconds() const {
  glFinish();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count();
}

}  // namespace nephele::gpu
