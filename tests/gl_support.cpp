#include "gl_support.hpp"

namespace nephele::test {

gpu::EglContext& test_context() {
  static gpu::EglContext context;
  return context;
}

}  // namespace nephele::test
