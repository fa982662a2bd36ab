#pragma once
// Equirectangular export of a one-channel cube map (GPU resampling).
#include <glm/glm.hpp>

#include <vector>

#include "gpu/pass_timer.hpp"
#include "gpu/textures.hpp"

namespace nephele::cover {

// For each of `height` rows (top = north): (cos, sin) of the geocentric latitude of the point
// on the WGS84 ellipsoid at the row's geodetic latitude (GeographicLib::Geocentric).
// Equirectangular maps of the Earth are indexed by geodetic latitude; the cover is indexed by
// direction from the Earth's centre.
std::vector<glm::vec2> geodetic_row_directions(int height);

// A rectangle of pixels of the equirect map; x, y from its top-left corner.
struct PixelTile {
  int x = 0, y = 0, width = 0, height = 0;
};

// Tiles of at most max_tile x max_tile pixels covering width x height exactly once, row by row;
// at most max_rows high where it is above 0.
std::vector<PixelTile> equirect_tiles(int width, int height, int max_tile, int max_rows = 0);

// The export's tile edge: small enough for any driver's 2D texture limit (OpenGL 4.5 guarantees
// 16384) and for llvmpipe's 1 GiB per texture; 64 MiB of R32F per tile.
constexpr int default_equirect_tile = 4096;
// The largest storage block of a tile's pixels (16 MiB: 341 rows of a 1024 cover's map of three
// channels).
constexpr long equirect_tile_bytes = 16L << 20;

// Resamples `cubes` (1 to max_equirect_channels cube maps of GL_R32F) to width x height pixels of
// as many channels, interleaved (the image files' order); longitude -180 deg at the left edge.
// The map is made in tiles of at most max_tile (0: default_equirect_tile, capped by
// GL_MAX_TEXTURE_SIZE), shorter where a tile would exceed equirect_tile_bytes, and
// assembled here (a tile as wide as the map read in place), so that maps wider than the driver's
// limits (4 x 16384 for the largest cover) work; every pixel is computed from its place in the
// whole map, so any tiling gives the same bits.
// `device`, when given, measures the GPU time of the tiles' dispatches (not their read-backs).
constexpr int max_equirect_channels = 3;
std::vector<float> equirect_from_cubes(const std::vector<const gpu::Texture*>& cubes, int width, int height,
                                       int max_tile = 0, gpu::DeviceTimer* device = nullptr);
// The same for one cube map.
std::vector<float> equirect_from_cube(const gpu::Texture& cube, int width, int height, int max_tile = 0,
                                      gpu::DeviceTimer* device = nullptr);
// The same for six one-channel faces in host memory (GL order, rows from t = 0), uploaded as a
// cube map first; the resampler of the export presets (io::ExportOptions::resample_equirect).
std::vector<float> equirect_from_faces(int face_size, const std::vector<float>& texels, int width, int height);

}  // namespace nephele::cover
