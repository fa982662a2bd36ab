#include "gpu/context.hpp"

namespace nephele::gpu {

bool Context::is_software() const {
  const std::string& renderer = info().renderer;
  return renderer.find("llvmpipe") != std::string::npos || renderer.find("softpipe") != std::string::npos ||
         renderer.find("lavapipe") != std::string::npos;
}

}  // namespace nephele::gpu
