#pragma once
// An image in memory: float pixels, row-major from the top row, channels interleaved. Every
// stage that makes pictures fills one; src/io writes them.
#include <vector>

namespace nephele::core {

struct ImageData {
  int width = 0, height = 0, channels = 0;
  std::vector<float> pixels;  // row-major from the top row, channels interleaved
};

}  // namespace nephele::core
