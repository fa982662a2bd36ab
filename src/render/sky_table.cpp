#include "render/sky_table.hpp"

#include "core/parallel_rows.hpp"
#include "gpu/compute_program.hpp"
#include "gpu/shader_bindings.hpp"
#include "gpu/textures.hpp"

namespace nephele::render {

std::vector<glsl::vec4> multiple_scattering_table(float earth_radius, float ground_albedo) {
  const int n = glsl::MULTIPLE_SCATTERING_TABLE_SIZE;
  const std::vector<glsl::vec4> transmittances = transmittance_table(earth_radius);
  const glsl::TransmittanceTable transmittance{glsl::TRANSMITTANCE_TABLE_WIDTH, glsl::TRANSMITTANCE_TABLE_HEIGHT,
                                               transmittances.data()};
  std::vector<glsl::vec4> table(static_cast<size_t>(n) * n);
  // 1024 texels of MULTIPLE_SCATTERING_RINGS x _AZIMUTHS directions of _STEPS steps each (128 x 40).
  core::parallel_rows(n, [&](int begin, int end) {
    for (int j = begin; j < end; ++j) {
      for (int i = 0; i < n; ++i) {
        table[static_cast<size_t>(j) * n + i] =
            glsl::vec4(glsl::multiple_scattering_table_entry(transmittance, i, j, earth_radius, ground_albedo), 1.0f);
      }
    }
  });
  return table;
}

namespace {
// An empty GL_RGBA32F 2D texture of width x height, bilinear and clamped to its edges.
GLuint table_texture(int width, int height) {
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &id);
  glTextureStorage2D(id, 1, GL_RGBA32F, width, height);
  glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return id;
}
}  // namespace

GLuint multiple_scattering_texture(GLuint transmittance, float earth_radius, float ground_albedo) {
  const int n = glsl::MULTIPLE_SCATTERING_TABLE_SIZE;
  const GLuint id = table_texture(n, n);
  const gpu::ComputeProgram program("render/sky_table.comp");
  program.use();
  program.set("u_radius", earth_radius);
  program.set("u_ground_albedo", ground_albedo);
  glBindImageTexture(shader_bindings::render_sky_table::table_image, id, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  glBindTextureUnit(shader_bindings::render_sky_table::transmittance_table, transmittance);
  program.dispatch_covering(n, n, 1);
  gpu::image_barrier();  // includes the texture fetches of the orbit pass that reads it
  return id;
}

std::vector<glsl::vec4> transmittance_table(float earth_radius) {
  const int width = glsl::TRANSMITTANCE_TABLE_WIDTH, height = glsl::TRANSMITTANCE_TABLE_HEIGHT;
  std::vector<glsl::vec4> table(static_cast<size_t>(width) * height);
  core::parallel_rows(height, [&](int begin, int end) {
    for (int j = begin; j < end; ++j)
      for (int i = 0; i < width; ++i)
        table[static_cast<size_t>(j) * width + i] =
            glsl::vec4(glsl::transmittance_table_entry(i, j, earth_radius), 1.0f);
  });
  return table;
}

GLuint transmittance_texture(float earth_radius) {
  const int width = glsl::TRANSMITTANCE_TABLE_WIDTH, height = glsl::TRANSMITTANCE_TABLE_HEIGHT;
  const GLuint id = table_texture(width, height);
  const gpu::ComputeProgram program("render/transmittance_table.comp");
  program.use();
  program.set("u_radius", earth_radius);
  glBindImageTexture(shader_bindings::render_transmittance_table::table_image, id, 0, GL_FALSE, 0, GL_WRITE_ONLY,
                     GL_RGBA32F);
  program.dispatch_covering(width, height, 1);
  gpu::image_barrier();
  return id;
}

}  // namespace nephele::render
