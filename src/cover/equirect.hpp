#pragma once
// Equirectangular export of a one-channel cube map (GPU resampling).
#include <glm/glm.hpp>

#include <vector>

#include "gpu/textures.hpp"

namespace nephele::cover {

// For each of `height` rows (top = north): (cos, sin) of the geocentric latitude of the point
// on the WGS84 ellipsoid at the row's geodetic latitude (GeographicLib::Geocentric).
// Equirectangular maps of the Earth are indexed by geodetic latitude; the cover is indexed by
// direction from the Earth's centre.
std::vector<glm::vec2> geodetic_row_directions(int height);

// Resamples `cube` (GL_R32F) to width x height; longitude -180 deg at the left edge.
std::vector<float> equirect_from_cube(const gpu::Texture& cube, int width, int height);

}  // namespace nephele::cover
