#include "render/orbit_tiles.hpp"

#include <algorithm>
#include <cmath>

namespace nephele::render {

namespace {

// The margin (radians) for orbit.comp's float rays and sphere tests: float rounds a unit vector
// to about 6e-8 and the discriminant of its sphere test to about 1e-7 of b^2, so 2e-4 rad is some
// thousand times what the shader can err by, and a few hundredths of a pixel at 1280 pixels over
// 70 degrees: a tile or two more, never one less.
constexpr double kFloatMargin = 2.0e-4;

double angle_between(glm::dvec3 a, glm::dvec3 b) {
  // atan2 of |a x b| and a . b: accurate at small and large angles alike.
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

}  // namespace

glm::ivec2 tile_grid(int width, int height) {
  return {(width + ORBIT_TILE - 1) / ORBIT_TILE, (height + ORBIT_TILE - 1) / ORBIT_TILE};
}

std::vector<glm::uvec2> all_tiles(int width, int height) {
  std::vector<glm::uvec2> tiles;
  const glm::ivec2 grid = tile_grid(width, height);
  tiles.reserve(static_cast<size_t>(std::max(grid.x, 0)) * static_cast<size_t>(std::max(grid.y, 0)));
  for (int y = 0; y < grid.y; ++y)
    for (int x = 0; x < grid.x; ++x) tiles.emplace_back(unsigned(x), unsigned(y));
  return tiles;
}

glm::dvec3 view_ray(const TileView& view, double px, double py) {
  const double aspect = double(view.height) / double(view.width);
  const double x = (2.0 * px / view.width - 1.0) * view.tan_half_fov;
  const double y = (1.0 - 2.0 * py / view.height) * aspect * view.tan_half_fov;
  return glm::normalize(view.forward + x * view.right + y * view.up);
}

double sphere_entry(const glm::dvec3& position, const glm::dvec3& d, double radius_m) {
  const double b = glm::dot(position, d);
  const double discriminant = b * b - (glm::dot(position, position) - radius_m * radius_m);
  return discriminant < 0.0 ? -1.0 : -b - std::sqrt(discriminant);
}

std::vector<glm::uvec2> tiles_meeting_sphere(const TileView& view, double radius_m) {
  const double distance = glm::length(view.position);
  if (!(distance > radius_m)) return all_tiles(view.width, view.height);
  const glm::dvec3 centre = -view.position / distance;
  const double sphere_angle = std::asin(radius_m / distance);
  const auto ray = [&](double px, double py) { return view_ray(view, px, py); };
  std::vector<glm::uvec2> tiles;
  const glm::ivec2 grid = tile_grid(view.width, view.height);
  for (int ty = 0; ty < grid.y; ++ty)
    for (int tx = 0; tx < grid.x; ++tx) {
      // The tile's pixel centres span [x0, x1] x [y0, y1]; on the image plane the rays within an
      // angle of the central one form a convex region, so its corners bound the whole tile.
      const double x0 = tx * ORBIT_TILE + 0.5, x1 = std::min((tx + 1) * ORBIT_TILE, view.width) - 0.5;
      const double y0 = ty * ORBIT_TILE + 0.5, y1 = std::min((ty + 1) * ORBIT_TILE, view.height) - 0.5;
      const glm::dvec3 middle = ray(0.5 * (x0 + x1), 0.5 * (y0 + y1));
      double spread = 0.0;
      for (double px : {x0, x1})
        for (double py : {y0, y1}) spread = std::max(spread, angle_between(middle, ray(px, py)));
      if (angle_between(middle, centre) <= sphere_angle + spread + kFloatMargin)
        tiles.emplace_back(unsigned(tx), unsigned(ty));
    }
  return tiles;
}

std::vector<glm::uvec2> tiles_in_rows(const std::vector<glm::uvec2>& tiles, int first_row, int row_count) {
  if (row_count <= 0) return tiles;
  std::vector<glm::uvec2> kept;
  for (const glm::uvec2& tile : tiles) {
    const int top = int(tile.y) * ORBIT_TILE;
    if (top < first_row + row_count && top + ORBIT_TILE > first_row) kept.push_back(tile);
  }
  return kept;
}

}  // namespace nephele::render
