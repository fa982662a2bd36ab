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

TEST_CASE("includes are expanded once and marked with line directives", "[fast][shaders]") {
  const auto expanded = gpu::expand_shader("cover/curl.comp");
  CHECK(expanded.files.front() == "cover/curl.comp");
  CHECK(std::count(expanded.files.begin(), expanded.files.end(), "lib/hash.glsl") == 1);
  CHECK(expanded.text.find("#include") == std::string::npos);
  CHECK(expanded.text.rfind("#version 450", 0) == 0);
}

TEST_CASE("a declared uniform that the compiler removed can be set, a misspelt one is an error", "[shaders]") {
  // NVIDIA's compiler drops unused members of a uniform struct where Mesa keeps them, so the
  // ground renderer's "u_march.forward" was inactive there: setting it must be a no-op, as GL
  // makes location -1, while a name the shader does not declare still means host and shader disagree.
  test::test_context();
  const std::string source =
      "#version 450\n"
      "layout(local_size_x = 1) in;\n"
      "struct Pair { float used; float unused; };\n"
      "uniform Pair u_pair;\n"
      "uniform float u_unused;\n"
      "layout(std430, binding = 0) buffer Out { float v[]; };\n"
      "void main() { v[0] = u_pair.used; }\n";
  const auto program = gpu::ComputeProgram::from_text("tests/unused_uniforms.comp", source);
  // Mesa removes the plain unused uniform, so the no-op path is taken on llvmpipe too.
  CHECK_FALSE(program.has_uniform("u_unused"));
  CHECK_NOTHROW(program.set("u_unused", 1.0f));
  CHECK_NOTHROW(program.set("u_pair.unused", 1.0f));
  CHECK_NOTHROW(program.set("u_pair.used", 2.0f));
  CHECK_THROWS_WITH(program.set("u_misspelt", 1.0f), Catch::Contains("no uniform 'u_misspelt'"));
  CHECK_THROWS_WITH(program.set("u_pair.usde", 1.0f), Catch::Contains("tests/unused_uniforms.comp"));
}
