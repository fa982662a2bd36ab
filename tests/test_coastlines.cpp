// GSHHG's shorelines rastered as the share of water (io/coastline_files.hpp).
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "io/coastline_files.hpp"

using namespace nephele;

namespace {

void require_gshhg() {
  if (!std::filesystem::exists(io::gshhg_shorelines_default_path))
    FAIL("gmt-gshhg-full is not installed (scripts/debian-packages.txt)");
}

// The water's share at a point: one pixel of 0.002 degrees (about 200 m) centred on it.
float water_at(double lat, double lon) {
  io::GeoWindow window{lat - 0.001, lat + 0.001, lon - 0.001, lon + 0.001, 1, 1};
  return io::read_gshhg_water(io::gshhg_shorelines_default_path, window).pixels[0];
}

}  // namespace

TEST_CASE("GSHHG's shorelines put the sea, lakes and ice shelves where they are, islands in lakes on land",
          "[fast][terrain]") {
  require_gshhg();
  // Points well inside each (kilometres from any shore); the levels of the hierarchy alternate
  // water and land: sea (0), land (1), lake (2), island in a lake (3).
  CHECK(water_at(46.95, 7.45) == 0.0f);    // Bern
  CHECK(water_at(46.45, 6.55) == 1.0f);    // Lake Geneva
  CHECK(water_at(46.90, 6.85) == 1.0f);    // Lake Neuchatel
  CHECK(water_at(42.0, 50.5) == 1.0f);     // the Caspian Sea, a lake
  CHECK(water_at(48.0, -88.9) == 0.0f);    // Isle Royale, an island in Lake Superior
  CHECK(water_at(47.7, -87.5) == 1.0f);    // Lake Superior
  CHECK(water_at(40.0, -30.0) == 1.0f);    // the Atlantic
  CHECK(water_at(23.0, 12.0) == 0.0f);     // the Sahara
  CHECK(water_at(-81.5, -175.0) == 0.0f);  // the Ross Ice Shelf: Antarctica ends at its ice front
  CHECK(water_at(-75.0, 0.0) == 0.0f);     // Antarctica's inland ice
}

TEST_CASE("the water's share of the whole globe is the ocean's 70.8 percent and the lakes'", "[fast][terrain]") {
  require_gshhg();
  // The ocean covers 361.1 of the Earth's 510.1 million km2 (0.708); lakes add about 0.005
  // (the Caspian alone 0.0007). Area-weighted over a 720 x 360 raster of the globe.
  const io::GeoWindow world{-90, 90, -180, 180, 720, 360};
  const core::ImageData water = io::read_gshhg_water(io::gshhg_shorelines_default_path, world);
  double wet = 0, area = 0;
  for (int j = 0; j < water.height; ++j) {
    const double weight = std::cos((89.75 - 0.5 * j) * M_PI / 180.0);
    for (int i = 0; i < water.width; ++i) {
      const float share = water.pixels[std::size_t(j) * water.width + i];
      REQUIRE(share >= 0.0f);
      REQUIRE(share <= 1.0f);
      wet += weight * share;
      area += weight;
    }
  }
  CHECK(wet / area == Approx(0.713).margin(0.006));
}

TEST_CASE("a pixel across a straight shore holds the water's share of its width", "[fast][terrain]") {
  require_gshhg();
  // A row of pixels across the coast: the share rises from land to sea monotonically through
  // one pixel or a few, never outside [0, 1]; the window's pixels that lie wholly at sea are 1.
  // 40 N from Portugal's coast (9.0 W) out to 10.5 W.
  const io::GeoWindow window{39.995, 40.005, -10.5, -8.5, 400, 1};
  const core::ImageData water = io::read_gshhg_water(io::gshhg_shorelines_default_path, window, 8);
  CHECK(water.pixels.front() == 1.0f);
  CHECK(water.pixels.back() == 0.0f);
  int partial = 0;
  for (float v : water.pixels) partial += v > 0.0f && v < 1.0f ? 1 : 0;
  CHECK(partial >= 1);
  CHECK(partial <= 8);
}

TEST_CASE("a shoreline window that is not a window is refused", "[fast][terrain]") {
  require_gshhg();
  for (const io::GeoWindow& bad : {io::GeoWindow{40, 30, 0, 10, 4, 4}, io::GeoWindow{30, 40, 10, 0, 4, 4},
                                   io::GeoWindow{30, 40, 0, 10, 0, 4}, io::GeoWindow{30, 40, -200, 200, 4, 4}})
    CHECK_THROWS_AS(io::read_gshhg_water(io::gshhg_shorelines_default_path, bad), std::invalid_argument);
  CHECK_THROWS_AS(io::read_gshhg_water("/nonexistent/binned_GSHHS_f.nc", io::GeoWindow{30, 40, 0, 10, 4, 4}),
                  std::runtime_error);
}
