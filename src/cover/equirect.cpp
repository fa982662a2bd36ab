#include "cover/equirect.hpp"

#include <GeographicLib/Geocentric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "gpu/shader_bindings.hpp"
#include "gpu/compute_program.hpp"
#include "gpu/storage_buffer.hpp"

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

std::vector<PixelTile> equirect_tiles(int width, int height, int max_tile, int max_rows) {
  const int rows = max_rows > 0 ? std::min(max_rows, max_tile) : max_tile;
  std::vector<PixelTile> tiles;
  for (int y = 0; y < height; y += rows)
    for (int x = 0; x < width; x += max_tile)
      tiles.push_back({x, y, std::min(max_tile, width - x), std::min(rows, height - y)});
  return tiles;
}

std::vector<float> equirect_from_cubes(const std::vector<const gpu::Texture*>& cubes, int width, int height,
                                       int max_tile, gpu::DeviceTimer* device) {
  const int channels = static_cast<int>(cubes.size());
  if (channels < 1 || channels > max_equirect_channels)
    throw std::invalid_argument("equirect_from_cubes: 1 to 3 cube maps, not " + std::to_string(channels));
  if (max_tile <= 0) {
    GLint max_side = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_side);
    max_tile = std::min(default_equirect_tile, static_cast<int>(max_side));
  }
  // A tile's pixels are one storage block, of at most equirect_tile_bytes (and the driver's block
  // size): the block is read straight into the map, so a larger one would only hold more memory.
  GLint64 max_block = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &max_block);
  max_block = std::min<GLint64>(max_block, equirect_tile_bytes);
  const std::int64_t tile_width = std::min(max_tile, width);
  const int max_rows = static_cast<int>(
      std::max<std::int64_t>(1, std::min<std::int64_t>(max_tile, max_block / (tile_width * channels * 4))));
  gpu::ComputeProgram program("cover/equirect.comp", {{"CHANNELS", std::to_string(channels)}});
  const std::vector<glm::vec2> rows = geodetic_row_directions(height);
  const gpu::StorageBuffer directions(rows.size() * sizeof(glm::vec2), rows.data());
  directions.bind(shader_bindings::cover_equirect::row_directions);
  for (int c = 0; c < channels; ++c)
    cubes[static_cast<size_t>(c)]->bind_image(shader_bindings::cover_equirect::source_cubes + c, GL_READ_ONLY);
  program.set("u_width", width);
  std::vector<float> pixels(static_cast<size_t>(width) * static_cast<size_t>(height) * static_cast<size_t>(channels));
  const std::vector<PixelTile> tiles = equirect_tiles(width, height, max_tile, max_rows);
  gpu::StorageBuffer tile_pixels;
  std::vector<float> part;
  for (const PixelTile& tile : tiles) {
    const size_t floats = static_cast<size_t>(tile.width) * static_cast<size_t>(tile.height) * channels;
    gpu::reserve(tile_pixels, floats * sizeof(float));
    tile_pixels.bind(shader_bindings::cover_equirect::equirect_tile);
    program.set("u_tile_size", glm::ivec2(tile.width, tile.height));
    program.set("u_origin_x", tile.x);
    program.set("u_origin_y", tile.y);
    if (device) device->begin();
    program.dispatch_covering(tile.width, tile.height, 1);
    if (device) device->end();
    const size_t row = static_cast<size_t>(width) * channels;
    float* first = pixels.data() + static_cast<size_t>(tile.y) * row + static_cast<size_t>(tile.x) * channels;
    // A tile as wide as the map is a run of the map's rows: read in place.
    if (tile.width == width) {
      tile_pixels.read(first, floats * sizeof(float));
      continue;
    }
    part.resize(floats);
    tile_pixels.read(part.data(), floats * sizeof(float));
    const size_t tile_row = static_cast<size_t>(tile.width) * channels;
    for (int r = 0; r < tile.height; ++r)
      std::copy_n(part.begin() + static_cast<std::ptrdiff_t>(r * tile_row), tile_row, first + r * row);
  }
  return pixels;
}

std::vector<float> equirect_from_cube(const gpu::Texture& cube, int width, int height, int max_tile,
                                      gpu::DeviceTimer* device) {
  return equirect_from_cubes({&cube}, width, height, max_tile, device);
}

std::vector<float> equirect_from_faces(int face_size, const std::vector<float>& texels, int width, int height) {
  gpu::Texture cube = gpu::Texture::cube(face_size, GL_R32F);
  cube.write(texels);
  return equirect_from_cube(cube, width, height);
}

}  // namespace nephele::cover
