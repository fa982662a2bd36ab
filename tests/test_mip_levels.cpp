// Mip chains made on the CPU (src/core/mip_levels.cpp): level sizes as OpenGL's, the 2 x 2 mean
// for even sizes, area weights for odd ones, and the image's mean kept at every level.
#include <catch2/catch.hpp>

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "core/mip_levels.hpp"

using namespace nephele;

namespace {

double mean(const std::vector<float>& v, int channels, int channel) {
  double sum = 0;
  for (size_t k = channel; k < v.size(); k += channels) sum += v[k];
  return sum / double(v.size() / channels);
}

}  // namespace

TEST_CASE("a mip level of an even image is the mean of the 2 x 2 texels below each texel", "[fast][mip]") {
  // 4 x 2, two channels: channel 0 counts texels, channel 1 is 10 x that.
  std::vector<float> image;
  for (int k = 0; k < 8; ++k) image.insert(image.end(), {float(k), 10.0f * k});
  const std::vector<float> level = core::next_mip_level(image, 4, 2, 2);
  REQUIRE(level.size() == 2 * 2 * 1);
  // Texel (0, 0) covers 0, 1 (row 0) and 4, 5 (row 1): mean 2.5; texel (1, 0): 2, 3, 6, 7: 4.5.
  CHECK(level[0] == Approx(2.5).epsilon(1e-7));
  CHECK(level[1] == Approx(25.0).epsilon(1e-7));
  CHECK(level[2] == Approx(4.5).epsilon(1e-7));
  CHECK(level[3] == Approx(45.0).epsilon(1e-7));
}

TEST_CASE("a mip level of an odd side weights the texels by the share of each footprint they cover", "[fast][mip]") {
  // 3 x 1 to 1 x 1: the one texel covers all three, each with weight 1/3.
  CHECK(core::next_mip_level({1.0f, 2.0f, 6.0f}, 3, 1, 1)[0] == Approx(3.0).epsilon(1e-7));
  // 5 x 1 to 2 x 1: footprints [0, 2.5) and [2.5, 5): (a + b + c/2) / 2.5 and (c/2 + d + e) / 2.5.
  const std::vector<float> level = core::next_mip_level({1.0f, 2.0f, 3.0f, 4.0f, 5.0f}, 5, 1, 1);
  REQUIRE(level.size() == 2);
  CHECK(level[0] == Approx((1 + 2 + 1.5) / 2.5).epsilon(1e-7));
  CHECK(level[1] == Approx((1.5 + 4 + 5) / 2.5).epsilon(1e-7));
}

TEST_CASE("a mip chain has OpenGL's level sizes and keeps the image's mean and a constant", "[fast][mip]") {
  const int width = 1080, height = 540, levels = 11;  // the water mask's size: odd from level 3 on
  std::vector<float> image(static_cast<size_t>(width) * height * 2);
  for (size_t k = 0; k < image.size(); k += 2) {
    image[k] = float((k * 2654435761u) % 1000u) / 1000.0f;  // scattered values in [0, 1)
    image[k + 1] = 0.25f;
  }
  const auto chain = core::mip_levels(image, width, height, 2, levels);
  REQUIRE(chain.size() == size_t(levels - 1));
  const double mean0 = mean(image, 2, 0);
  int w = width, h = height;
  for (int level = 1; level < levels; ++level) {
    w = std::max(1, w / 2);
    h = std::max(1, h / 2);
    INFO("level " << level << ": " << w << " x " << h);
    const std::vector<float>& texels = chain[size_t(level - 1)];
    REQUIRE(texels.size() == size_t(w) * size_t(h) * 2);
    // Area weights sum to one over each footprint and the footprints tile the image, so the
    // mean is kept up to float's rounding of each level's values (relative 6e-8 a level).
    CHECK(mean(texels, 2, 0) == Approx(mean0).epsilon(1e-6));
    for (size_t k = 1; k < texels.size(); k += 2) REQUIRE(texels[k] == Approx(0.25f).epsilon(1e-6));
  }
  CHECK(w == 1);
  CHECK(h == 1);
}

TEST_CASE("a mip level refuses texels that do not match its size", "[fast][mip]") {
  CHECK_THROWS_AS(core::next_mip_level(std::vector<float>(5), 2, 2, 1), std::invalid_argument);
  CHECK_THROWS_AS(core::next_mip_level({}, 0, 1, 1), std::invalid_argument);
}
