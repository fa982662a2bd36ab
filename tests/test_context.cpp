// The GL context behind its interface (src/gpu/context.hpp) and the probe harness.
#include <catch2/catch.hpp>

#include "gl_support.hpp"

using namespace nephele;

TEST_CASE("the headless context works through the Context interface and can be made current again", "[gpu]") {
  gpu::Context& context = test::test_context();
  CHECK_FALSE(context.info().renderer.empty());
  CHECK(context.is_software() == (context.info().renderer.find("llvmpipe") != std::string::npos));
  context.make_current();
  // A probe still runs after making the context current again: 2 x input, exactly.
  const auto doubled = test::probe<glm::vec4>("", "2.0 * input_value", std::vector<glm::vec4>{{1, 2, 3, 4}});
  CHECK(doubled.front() == glm::vec4(2, 4, 6, 8));
}
