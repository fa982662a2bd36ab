// The binding points named in gpu/shader_bindings.hpp (generated from the shaders' text by
// cmake/shader_bindings.cmake) are the ones the driver reports for the compiled programs.
#include <catch2/catch.hpp>

#include <epoxy/gl.h>

#include <string>
#include <vector>

#include "gl_support.hpp"
#include "gpu/compute_program.hpp"
#include "gpu/shader_bindings.hpp"

using namespace nephele;

namespace {

// The unit of a sampler or image uniform, as the program reports it (-1: no such active uniform).
int uniform_binding(GLuint program, const std::string& name) {
  const GLint location = glGetUniformLocation(program, name.c_str());
  if (location < 0) return -1;
  GLint value = -1;
  glGetUniformiv(program, location, &value);
  return value;
}

// The binding point of a shader storage block (-1: no such active block).
int buffer_binding(GLuint program, const std::string& block) {
  const GLuint index = glGetProgramResourceIndex(program, GL_SHADER_STORAGE_BLOCK, block.c_str());
  if (index == GL_INVALID_INDEX) return -1;
  const GLenum property = GL_BUFFER_BINDING;
  GLint value = -1;
  glGetProgramResourceiv(program, GL_SHADER_STORAGE_BLOCK, index, 1, &property, 1, nullptr, &value);
  return value;
}

}  // namespace

TEST_CASE("the named binding points of the shaders are those the driver reports", "[gpu]") {
  test::test_context();
  namespace b = shader_bindings;
  struct Expected {
    const char* shader;
    const char* name;  // a uniform's name, or a buffer block's
    bool block;
    int point;  // from shader_bindings.hpp
  };
  const std::vector<Expected> expected = {
      {"cover/equirect.comp", "source_cubes", false, b::cover_equirect::source_cubes},
      {"cover/equirect.comp", "EquirectTile", true, b::cover_equirect::equirect_tile},
      {"cover/equirect.comp", "RowDirections", true, b::cover_equirect::row_directions},
      {"cover/cover_density.comp", "ItczCells", true, b::cover_cover_density::itcz_cells},
      {"cover/itcz_cells.comp", "ItczCells", true, b::cover_itcz_cells::itcz_cells},
      {"model/density.comp", "u_density", false, b::model_density::u_density},
      {"model/density.comp", "Primitives", true, b::model_density::primitives},
      {"model/density.comp", "Jobs", true, b::model_density::jobs},
      {"model/density.comp", "Indices", true, b::model_density::indices},
      {"render/orbit.comp", "radiance_image", false, b::render_orbit::radiance_image},
      {"render/orbit.comp", "day_texture", false, b::render_orbit::day_texture},
      {"render/orbit.comp", "night_texture", false, b::render_orbit::night_texture},
      {"render/orbit.comp", "cover_map", false, b::render_orbit::cover_map},
      {"render/orbit.comp", "water_texture", false, b::render_orbit::water_texture},
      {"render/orbit.comp", "Tiles", true, b::render_orbit::tiles},
  };
  for (const Expected& e : expected) {
    INFO(e.shader << ": " << e.name);
    const gpu::ComputeProgram program(e.shader);
    const int reported = e.block ? buffer_binding(program.id(), e.name) : uniform_binding(program.id(), e.name);
    CHECK(reported == e.point);
  }
}
