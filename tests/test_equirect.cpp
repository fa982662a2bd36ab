// Equirectangular export: orientation, geodetic rows, agreement with the cube map.
#include <catch2/catch.hpp>

#include <cmath>

#include "cover/equirect.hpp"
#include "gl_support.hpp"
#include "shader_math/shader_math.hpp"
#include "tolerances.hpp"

using namespace nephele;
using namespace nephele::glsl;

namespace {

// The rows are computed in double (GeographicLib) and stored as float: half an ulp of values
// below 1 (2^-24 = 6e-8) from the double formula, whose own rounding (tan near the poles, at
// most 1e-13 here) is negligible; 1e-6 is 16x looser than that (kept as set).
constexpr double kRowDirection = 1e-6;
static_assert(kRowDirection >= nephele::test::kUlp);

}  // namespace

TEST_CASE("equirect rows are geodetic latitudes turned into geocentric directions", "[fast][equirect]") {
  const int height = 180;
  const auto rows = cover::geodetic_row_directions(height);
  // WGS84: tan(geocentric) = (1 - f)^2 tan(geodetic) on the surface, f = 1/298.257223563.
  const double f = 1 / 298.257223563;
  for (int j = 0; j < height; ++j) {
    const double geodetic = (90.0 - 180.0 * (j + 0.5) / height) * M_PI / 180;
    const double geocentric = std::atan((1 - f) * (1 - f) * std::tan(geodetic));
    CHECK(rows[j].x == Approx(std::cos(geocentric)).epsilon(0).margin(kRowDirection));
    CHECK(rows[j].y == Approx(std::sin(geocentric)).epsilon(0).margin(kRowDirection));
  }
  CHECK(rows.front().y > 0.0f);  // north up
}

TEST_CASE("equirect export puts longitude -180 at the left edge and north at the top", "[equirect]") {
  test::test_context();
  const int size = 32, width = 128, height = 64;
  // Three cube maps holding the x, y and z components of the texel direction.
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<float> texels(6 * size * size);
    for (int face = 0; face < 6; ++face)
      for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i) texels[(face * size + j) * size + i] = texel_direction(face, i, j, size)[axis];
    gpu::Texture cube = gpu::Texture::cube(size, GL_R32F);
    cube.write(texels);
    const auto map = cover::equirect_from_cube(cube, width, height);
    const auto rows = cover::geodetic_row_directions(height);
    double worst = 0;
    for (int j = 0; j < height; ++j)
      for (int i = 0; i < width; ++i) {
        const double lon = 2 * M_PI * (i + 0.5) / width - M_PI;
        const double expected[3] = {rows[j].x * std::cos(lon), rows[j].x * std::sin(lon), rows[j].y};
        worst = std::max(worst, std::abs(map[j * width + i] - expected[axis]));
      }
    // Bilinear interpolation of a smooth unit-sphere function: error below (texel / 2)^2 times
    // its curvature (<= 3 on the face plane), texel = 2 / size on faces of half-width 1.
    INFO("axis " << axis << " largest error " << worst);
    CHECK(worst < 3.0 * (1.0 / size) * (1.0 / size) * 2.0);
  }
}

TEST_CASE("cube maps resampled together give each map's own equirect map, interleaved, in any tiling", "[equirect]") {
  // Three maps of different content resampled in one pass (one footprint a pixel for all) against
  // each alone: the same arithmetic on the same texels, so the same bits; and tiles of 7 pixels,
  // which split rows and columns, the same bits again.
  test::test_context();
  const int size = 16, width = 64, height = 32;
  std::vector<gpu::Texture> cubes;
  for (int k = 0; k < 3; ++k) {
    std::vector<float> texels(6 * size * size);
    for (size_t t = 0; t < texels.size(); ++t) texels[t] = std::sin(0.37f * float(t) * float(k + 1)) + float(k);
    cubes.push_back(gpu::Texture::cube(size, GL_R32F));
    cubes.back().write(texels);
  }
  const std::vector<const gpu::Texture*> all = {&cubes[0], &cubes[1], &cubes[2]};
  const auto together = cover::equirect_from_cubes(all, width, height);
  const auto tiled = cover::equirect_from_cubes(all, width, height, 7);
  REQUIRE(together.size() == 3u * width * height);
  CHECK(tiled == together);
  for (int k = 0; k < 3; ++k) {
    const auto alone = cover::equirect_from_cube(cubes[k], width, height);
    int differing = 0;
    for (size_t p = 0; p < alone.size(); ++p) differing += alone[p] == together[3 * p + k] ? 0 : 1;
    INFO("map " << k);
    CHECK(differing == 0);
  }
}
