#pragma once
// The pixel tiles of an orbit frame that can show anything: those whose rays can meet the
// atmosphere's sphere (the ground, the cloud shell and the air all lie inside it). The orbit pass
// draws only these; a ray that misses the air sees black, clear space (radiance and opacity 0),
// which the cleared image already holds. On llvmpipe a work group runs every instruction of
// orbit.comp for each group of lanes whatever its branches decide, so a tile of space cost as
// much as one of cloud before (docs/orbit_view.md, "Cost").
#include <glm/glm.hpp>

#include <vector>

namespace nephele::render {

// orbit.comp's work group: one tile of ORBIT_TILE x ORBIT_TILE pixels (its own ORBIT_TILE;
// tests/test_orbit.cpp checks that the compiled program's work group is this).
inline constexpr int ORBIT_TILE = 8;

// The tiles across (x) and down (y) a width x height image, the last ones partly outside it.
glm::ivec2 tile_grid(int width, int height);

// The view as orbit.comp sets up its rays: the camera `position` (m, from the planet's centre),
// the unit vectors forward, right and up, tan of half the horizontal field of view and the image
// size. A pixel's ray is normalize(forward + x right + y up) with x = (2u - 1) tan_half and
// y = (1 - 2v) (height / width) tan_half, (u, v) its centre over the image.
struct TileView {
  glm::dvec3 position, forward, right, up;
  double tan_half_fov = 1;
  int width = 1, height = 1;
};

// The unit ray through the point (px, py) of the image, in pixels from its top left corner (a
// pixel's centre at + 0.5).
glm::dvec3 view_ray(const TileView& view, double px, double py);

// Where the unit ray from `position` along d enters the sphere of `radius_m` about the planet's
// centre: the nearer root t of |position + t d| = radius_m, or a negative value where the ray
// misses it (or meets it only behind).
double sphere_entry(const glm::dvec3& position, const glm::dvec3& d, double radius_m);

// The tiles (column, row; tile units, row 0 at the top) that hold a pixel whose ray can meet the
// sphere of `radius_m` about the planet's centre, in row order. Conservative: a tile is kept where
// the angle between its central ray and the sphere's centre is at most the sphere's angular radius
// plus the largest angle from that ray to the tile's corner rays and a margin for the shader's
// float rounding; so every pixel that meets the sphere is drawn. All tiles when the camera is
// inside the sphere.
std::vector<glm::uvec2> tiles_meeting_sphere(const TileView& view, double radius_m);

// Every tile of a width x height image (the whole frame), in row order.
std::vector<glm::uvec2> all_tiles(int width, int height);

// The tiles of `tiles` that hold a pixel of the image rows [first_row, first_row + row_count)
// (a band of the viewer's refinement), in their order; all of them when row_count is 0.
std::vector<glm::uvec2> tiles_in_rows(const std::vector<glm::uvec2>& tiles, int first_row, int row_count);

}  // namespace nephele::render
