#include "cover/equirect.hpp"

#include <GeographicLib/Geocentric.hpp>

#include <algorithm>
#include <cmath>

#include "gpu/shader_bindings.hpp"
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

std::vector<PixelTile> equirect_tiles(int width, int height, int max_tile) {
  std::vector<PixelTile> tiles;
  for (int y = 0; y < height; y += max_tile)
    for (int x = 0; x < width; x += max_tile)
      tiles.push_back({x, y, std::min(max_tile, width - x), std::min(max_tile, height - y)});
  return tiles;
}

std::vector<float> equirect_from_cube(const gpu::Texture& cube, int width, int height, int max_tile,
                                      gpu::DeviceTimer* device) {
  if (max_tile <= 0) {
    GLint max_side = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_side);
    max_tile = std::min(default_equirect_tile, static_cast<int>(max_side));
  }
  gpu::ComputeProgram program("cover/equirect.comp");
  const std::vector<glm::vec2> rows = geodetic_row_directions(height);
  GLuint buffer = 0;
  glCreateBuffers(1, &buffer);
  glNamedBufferStorage(buffer, static_cast<GLsizeiptr>(rows.size() * sizeof(glm::vec2)), rows.data(), 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, shader_bindings::cover_equirect::row_directions, buffer);
  cube.bind_image(shader_bindings::cover_equirect::source_cube, GL_READ_ONLY);
  program.set("u_width", width);
  std::vector<float> pixels(static_cast<size_t>(width) * static_cast<size_t>(height));
  for (const PixelTile& tile : equirect_tiles(width, height, max_tile)) {
    gpu::Texture target = gpu::Texture::plane(tile.width, tile.height, GL_R32F);
    target.bind_image(shader_bindings::cover_equirect::equirect, GL_WRITE_ONLY);
    program.set("u_origin_x", tile.x);
    program.set("u_origin_y", tile.y);
    if (device) device->begin();
    program.dispatch_covering(tile.width, tile.height, 1);
    if (device) device->end();
    gpu::image_barrier();
    const std::vector<float> part = target.read();
    for (int r = 0; r < tile.height; ++r)
      std::copy_n(part.begin() + static_cast<std::ptrdiff_t>(r) * tile.width, tile.width,
                  pixels.begin() + (static_cast<std::ptrdiff_t>(tile.y + r) * width + tile.x));
  }
  glDeleteBuffers(1, &buffer);
  return pixels;
}

std::vector<float> equirect_from_faces(int face_size, const std::vector<float>& texels, int width, int height) {
  gpu::Texture cube = gpu::Texture::cube(face_size, GL_R32F);
  cube.write(texels);
  return equirect_from_cube(cube, width, height);
}

}  // namespace nephele::cover
