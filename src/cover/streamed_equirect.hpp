#pragma once
// The equirect map of a one-channel cube map too large for the GPU's memory (a cover assembled
// from tiles beyond the memory budget, io/cover_assembly.cpp; docs/scale.md): made band by band
// of rows on the CPU, by the C++ twin of the GPU resampler's functions (equirect_mapping.glsl,
// cube_sampling.glsl), from faces the caller maps from files (the kernel pages in the rows a
// band reads; a band of rows of the map reads rows of the polar and +-Y faces near its latitude
// but every row of the +-X faces, whose rows run along longitude). The values are the GPU's
// map's up to float rounding (the same operations; the GPU contracts and rounds its own way).
#include <array>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "cover/equirect.hpp"

namespace nephele::cover {

// Receives the map's rows [first_row, first_row + rows), width floats a row, in order.
using TakeMapRows = std::function<void(int first_row, int rows, const std::vector<float>& pixels)>;

// The width x height map (longitude -180 deg at the left edge, rows of geodetic latitude, as
// equirect_from_cube) of the cube map whose faces (GL order, face_size^2 floats, rows from
// t = 0) are `faces`, in bands of `band_rows` rows, each sampled by all hardware threads.
void streamed_equirect(int face_size, const float* const faces[6], int width, int height, const TakeMapRows& take,
                       int band_rows = 64);
// The same for several channels' faces at once (faces[c] the six faces of channel c): the rows
// hand over the channels interleaved, faces.size() floats a pixel.
using FacePointers = std::array<const float*, 6>;
void streamed_equirect(int face_size, const std::vector<FacePointers>& faces, int width, int height,
                       const TakeMapRows& take, int band_rows = 64);

// The pixels of `region` of such a map `width` wide whose rows' directions are `rows`
// (geodetic_row_directions of its height), row by row into `out` (region.width floats a row):
// the tiles of virtual textures (io/export_simulators.cpp, celestia).
void equirect_region(int face_size, const float* const faces[6], int width, const std::vector<glm::vec2>& rows,
                     const PixelTile& region, float* out);

}  // namespace nephele::cover
