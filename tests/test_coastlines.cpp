// GSHHG's shorelines rastered as the share of water (io/coastline_files.hpp).
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <filesystem>
#include <stdexcept>

#include "io/coastline_files.hpp"
#include "io/planet_textures.hpp"

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

TEST_CASE("from low orbit the coasts are rastered for the ground in view, from high orbit not at all",
          "[fast][terrain]") {
  require_gshhg();
  // What add_view_coast needs of the maps: the sea's colour and the water map's width (ETOPO5's
  // 1080 texels, 37 km; the shorelines come in below a quarter of it, about 9 km a pixel).
  auto maps = [] {
    io::PlanetTextures textures;
    textures.images.sea_colour = true;
    textures.images.water = {1080, 540, 1, {}};
    textures.water_source = "etopo5";
    return textures;
  };
  const double R = 6371000.0, bern_lat = 46.95, bern_lon = 7.45;
  render::OrbitCamera camera;
  camera.latitude_deg = bern_lat, camera.longitude_deg = bern_lon, camera.altitude_m = 400000.0;
  camera.pitch_deg = -90, camera.fov_deg = 70, camera.width = 1280, camera.height = 720;
  io::PlanetTextures low = maps();
  io::add_view_coast(low, camera, R);
  const render::PlanetImages& p = low.images;
  REQUIRE(!p.coast.pixels.empty());
  CHECK(low.water_source.find(io::gshhg_shorelines_default_path) != std::string::npos);
  CHECK(p.coast.width <= 2048);
  CHECK(p.coast.height <= 2048);
  // The window holds the view (Bern below, Lake Geneva 90 km away) and lies within the horizon's
  // cap (19.7 degrees from 400 km) plus its one degree of margin.
  CHECK(p.coast_south_deg < 46.45);
  CHECK(p.coast_north_deg > bern_lat);
  CHECK(p.coast_west_deg < 6.55);
  CHECK(p.coast_east_deg > bern_lon);
  const double cap = std::acos(R / (R + camera.altitude_m)) * 180.0 / M_PI + 1.0;
  CHECK(p.coast_north_deg - bern_lat <= cap);
  CHECK(bern_lat - p.coast_south_deg <= cap);
  auto coast_at = [&](double lat, double lon) {
    const int i = int((lon - p.coast_west_deg) / (p.coast_east_deg - p.coast_west_deg) * p.coast.width);
    const int j = int((p.coast_north_deg - lat) / (p.coast_north_deg - p.coast_south_deg) * p.coast.height);
    return p.coast.pixels[std::size_t(j) * p.coast.width + i];
  };
  CHECK(coast_at(46.45, 6.55) == 1.0f);  // Lake Geneva
  CHECK(coast_at(bern_lat, bern_lon) == 0.0f);
  // From 12000 km (15 km pixels) the water map's coasts are as sharp as the view; and a named day
  // map, without the sea's colour, keeps its own water.
  camera.altitude_m = 1.2e7;
  io::PlanetTextures high = maps();
  io::add_view_coast(high, camera, R);
  CHECK(high.images.coast.pixels.empty());
  CHECK(high.water_source == "etopo5");
  camera.altitude_m = 400000.0;
  io::PlanetTextures named = maps();
  named.images.sea_colour = false;
  io::add_view_coast(named, camera, R);
  CHECK(named.images.coast.pixels.empty());
}
