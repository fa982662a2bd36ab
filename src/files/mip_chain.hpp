#pragma once
// Mip chains for the texture containers (KTX2, DDS): every level down to 1 x 1, each the area
// average of the level above. Coverage is linear data, so averaging the values is the right
// filter for a sampler that averages them again (docs/export.md, "Mip chains").
#include <cstddef>
#include <vector>

namespace nephele::files {

// An image and its mip levels in float. Level k is max(1, width >> k) x max(1, height >> k)
// texels (the sizes of OpenGL 4.5 section 8.14.3, KTX2 and DDS); it holds `layers` images of
// that size (6 for a cube: faces in GL order), each row-major from the top row, `channels`
// floats per texel.
struct MipChain {
  int width = 0, height = 0, layers = 1, channels = 1;
  std::vector<std::vector<float>> levels;

  int count() const { return static_cast<int>(levels.size()); }
  int level_width(int level) const { return width >> level > 0 ? width >> level : 1; }
  int level_height(int level) const { return height >> level > 0 ? height >> level : 1; }
  std::size_t image_floats(int level) const {
    return std::size_t(level_width(level)) * std::size_t(level_height(level)) * std::size_t(channels);
  }
  // The first float of image `layer` of `level`.
  const float* image(int level, int layer) const { return levels[level].data() + image_floats(level) * layer; }
};

// 1 + floor(log2(max(width, height))): the number of levels of a full chain.
int full_mip_count(int width, int height);

// The chain of `base` (layers images of width x height, `channels` per texel) with `levels`
// levels (0: the full chain). Each level's texel is the area-weighted mean of the texels of the
// level above that its footprint covers; the footprint is the exact size ratio, so an odd size
// (n to floor(n/2)) keeps the image's mean instead of dropping a row. Each layer is filtered on
// its own (cube faces are not blended across their edges, as texconv and libktx do).
MipChain build_mip_chain(std::vector<float> base, int width, int height, int layers, int channels, int levels = 0);

}  // namespace nephele::files
