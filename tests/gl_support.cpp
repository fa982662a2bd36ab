#include "gl_support.hpp"

#include "case_tags.hpp"

namespace nephele::test {

gpu::EglContext& test_context() {
  starting_slow_work("an OpenGL context");
  static gpu::EglContext context;
  return context;
}

}  // namespace nephele::test
