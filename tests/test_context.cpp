// The GL context behind its interface (src/gpu/context.hpp) and the probe harness.
#include <catch2/catch.hpp>

#include "gl_support.hpp"
#include "gpu/storage_buffer.hpp"

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

TEST_CASE("a storage buffer gives back what was written and grows on demand but never shrinks", "[gpu]") {
  test::test_context();
  const std::vector<float> values{1.5f, -2.0f, 3.25f, 0.0f};
  const gpu::StorageBuffer made(values.size() * sizeof(float), values.data());
  CHECK(made.read_floats() == values);
  // A word written at an offset, read back alone and in place.
  const float word = 7.0f;
  made.write(&word, sizeof word, 2 * sizeof(float));
  float back = 0.0f;
  made.read(&back, sizeof back, 2 * sizeof(float));
  CHECK(back == word);
  CHECK(made.read_floats() == std::vector<float>{1.5f, -2.0f, 7.0f, 0.0f});

  gpu::StorageBuffer list;
  CHECK(list.id() == 0);
  // An empty list still makes a buffer of the minimum size, which a storage block can be bound to.
  gpu::upload(list, nullptr, 0, 16);
  CHECK(list.id() != 0);
  CHECK(list.bytes() == 16);
  gpu::upload(list, values.data(), values.size() * sizeof(float));
  const GLuint first = list.id();
  CHECK(list.read_floats() == values);
  // A shorter list reuses the buffer: its size stays, its start holds the list.
  gpu::upload(list, values.data(), 2 * sizeof(float));
  CHECK(list.id() == first);
  CHECK(list.bytes() == values.size() * sizeof(float));
  std::vector<float> start(2);
  list.read(start.data(), 2 * sizeof(float));
  CHECK(start == std::vector<float>{1.5f, -2.0f});
  // A longer one replaces it.
  const std::vector<float> longer(8, 4.0f);
  gpu::upload(list, longer.data(), longer.size() * sizeof(float));
  CHECK(list.bytes() == longer.size() * sizeof(float));
  CHECK(list.read_floats() == longer);
  gpu::reserve(list, 4);
  CHECK(list.bytes() == longer.size() * sizeof(float));
}
