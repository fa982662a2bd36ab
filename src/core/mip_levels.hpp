#pragma once
// Mip chains made on the CPU: a texture's level 0 halved level by level, each texel the mean of
// the texels it covers. Where a GPU makes them quickly, llvmpipe's glGenerateTextureMipmap
// compiles a blit shader for each format and target it meets (100-200 ms each), while this takes
// about 20 ms for a 2048 x 1024 RGBA map (docs/orbit_view.md, "Cost").
#include <vector>

namespace nephele::core {

// One level down: a width x height image of `channels` interleaved floats (row-major) to
// max(1, width / 2) x max(1, height / 2) (OpenGL's level sizes, rounded down). Each texel is the
// area-weighted mean of the source over its footprint: the 2 x 2 texels below it for even sizes;
// for an odd size the footprint is s / floor(s / 2) texels wide and the texels at its ends count
// by the share they lie in it. So the image's mean is kept at every level.
std::vector<float> next_mip_level(const std::vector<float>& texels, int width, int height, int channels);

// The levels 1 .. levels - 1 of a width x height image (level 0 not included).
std::vector<std::vector<float>> mip_levels(const std::vector<float>& level0, int width, int height, int channels,
                                           int levels);

}  // namespace nephele::core
