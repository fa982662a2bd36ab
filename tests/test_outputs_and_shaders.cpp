// Shader compile errors that name the file and line (output sets: test_output_set.cpp).
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <random>

#include "gpu/compute_program.hpp"
#include "gpu/shader_sources.hpp"
#include "gl_support.hpp"

namespace fs = std::filesystem;
using namespace nephele;

TEST_CASE("every embedded shader compiles", "[shaders]") {
  test::test_context();
  for (const auto& [path, text] : gpu::embedded_shader_sources()) {
    if (path.size() < 5 || path.substr(path.size() - 5) != ".comp") continue;
    INFO(path);
    CHECK_NOTHROW(gpu::ComputeProgram(path));
  }
}

TEST_CASE("shader compile errors name the file and line", "[shaders]") {
  test::test_context();
  const std::string source =
      "#version 450\n"
      "layout(local_size_x = 1) in;\n"
      "#include \"../lib/hash.glsl\"\n"
      "void main() {\n"
      "  undeclared_thing = 1;\n"
      "}\n";
  try {
    gpu::ComputeProgram::from_text("tests/broken.comp", source);
    FAIL("no error");
  } catch (const gpu::ShaderError& e) {
    CHECK_THAT(e.what(), Catch::Contains("tests/broken.comp:5"));
  }
  try {
    gpu::ComputeProgram::from_text("tests/missing.comp", "#version 450\n#include \"../lib/nothing.glsl\"\n");
    FAIL("no error");
  } catch (const std::runtime_error& e) {
    CHECK_THAT(e.what(), Catch::Contains("lib/nothing.glsl") && Catch::Contains("tests/missing.comp:2"));
  }
}

TEST_CASE("includes are expanded once and marked with line directives", "[shaders]") {
  const auto expanded = gpu::expand_shader("cover/curl.comp");
  CHECK(expanded.files.front() == "cover/curl.comp");
  CHECK(std::count(expanded.files.begin(), expanded.files.end(), "lib/hash.glsl") == 1);
  CHECK(expanded.text.find("#include") == std::string::npos);
  CHECK(expanded.text.rfind("#version 450", 0) == 0);
}
