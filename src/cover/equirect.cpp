#include "cover/equirect.hpp"

#include <GeographicLib/Geocentric.hpp>

#include <cmath>

#include "gpu/compute_program.hpp"

namespace nephele::cover {

std::vector<glm::vec2> geodetic_row_directions(int height) {
  const GeographicLib::Geocentric& earth = GeographicLib::Geocentric::WGS84();
  std::vector<glm::vec2> rows(static_cast<size_t>(height));
  for (int j = 0; j < height; ++j) {
    const double geodetic_latitude = 90.0 - 180.0 * (j + 0.5) / height;
    double x = 0, y = 0, z = 0;
    earth.Forward(geodetic_latitude, 0.0, 0.0, x, y, z);
    const double r = std::hypot(x, z);
    rows[j] = glm::vec2(static_cast<float>(x / r), static_cast<float>(z / r));
  }
  return rows;
}

std::vector<float> equirect_from_cube(const gpu::Texture& cube, int width, int height) {
  gpu::ComputeProgram program("cover/equirect.comp");
  gpu::Texture target = gpu::Texture::plane(width, height, GL_R32F);
  const std::vector<glm::vec2> rows = geodetic_row_directions(height);
  GLuint buffer = 0;
  glCreateBuffers(1, &buffer);
  glNamedBufferStorage(buffer, static_cast<GLsizeiptr>(rows.size() * sizeof(glm::vec2)), rows.data(), 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, buffer);
  cube.bind_image(0, GL_READ_ONLY);
  target.bind_image(1, GL_WRITE_ONLY);
  program.dispatch_covering(width, height, 1);
  gpu::image_barrier();
  std::vector<float> pixels = target.read();
  glDeleteBuffers(1, &buffer);
  return pixels;
}

}  // namespace nephele::cover
