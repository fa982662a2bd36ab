// The land cover of the ground views (docs/terrain.md, Land cover): the rasterised lakes,
// rivers and towns, the lakes carved into the height field, the season's snow line, the files
// they come from, and where the lakes appear in a render from Gurten.
#include <GeographicLib/Geodesic.hpp>
#include <GeographicLib/LocalCartesian.hpp>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/error.hpp"
#include "core/time.hpp"
#include "gl_support.hpp"
#include "io/elevation_files.hpp"
#include "io/land_cover_files.hpp"
#include "io/river_files.hpp"
#include "regional/land_cover.hpp"
#include "regional/sites.hpp"
#include "regional/terrain.hpp"
#include "render/cloud_renderer.hpp"
#include "shader_math/shader_math.hpp"
#include "tolerances.hpp"

using namespace nephele;

namespace {

constexpr double camera_lat = 46.91722, camera_lon = 7.44361, camera_height = 860.0;  // Gurten

double earth_radius() { return render::osculating_earth_radius(camera_lat); }

// A point `east` and `north` metres from the camera (on the ellipsoid), by the geodesic.
regional::GeoPoint offset(double east, double north) {
  double lat, lon;
  GeographicLib::Geodesic::WGS84().Direct(camera_lat, camera_lon, std::atan2(east, north) * 180 / M_PI,
                                          std::hypot(east, north), lat, lon);
  return {lat, lon};
}

// A rectangular lake from (west, south) to (east, north), metres from the camera.
regional::GeoPolygon rectangle(const std::string& name, double west, double south, double east, double north,
                               double surface) {
  return {name, {{offset(west, south), offset(east, south), offset(east, north), offset(west, north)}}, surface};
}

// Distance from p to the segment a-b in the plane.
double segment_distance(std::pair<double, double> p, std::pair<double, double> a, std::pair<double, double> b) {
  const double dx = b.first - a.first, dy = b.second - a.second;
  const double t = std::clamp(((p.first - a.first) * dx + (p.second - a.second) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
  return std::hypot(p.first - a.first - t * dx, p.second - a.second - t * dy);
}

double centre(const regional::LandCoverGrid& g, int level, int k) {
  return ((2.0 * k + 1) / g.size - 1) * g.extent_m[level];
}

bool have_swiss_maps() { return std::filesystem::exists(io::swiss_maps_default_path); }

}  // namespace

TEST_CASE("day_of_year counts from 1 on the first of January, in UTC", "[fast][terrain]") {
  CHECK(core::day_of_year(core::parse_utc_time("2026-01-01T00:00Z")) == 1);
  CHECK(core::day_of_year(core::parse_utc_time("2026-06-21T23:59Z")) == 172);
  CHECK(core::day_of_year(core::parse_utc_time("2024-12-31T12:00Z")) == 366);
  CHECK(core::day_of_year(core::parse_utc_time("2025-12-31T12:00Z")) == 365);
}

TEST_CASE("the seasonal snow line is lowest in mid-February and highest half a year later", "[fast][terrain]") {
  CHECK(regional::seasonal_snow_line_m(45) == Approx(1000.0).margin(1e-9));
  CHECK(regional::seasonal_snow_line_m(228) == Approx(3000.0).margin(0.1));  // 182.6 days on
  for (int day = 1; day <= 366; ++day) {
    CHECK(regional::seasonal_snow_line_m(day) >= 1000.0 - 1e-9);
    CHECK(regional::seasonal_snow_line_m(day) <= 3000.0 + 1e-9);
  }
}

TEST_CASE("a lake's texels hold the distance to its shore, negative inside, clamped beyond the band",
          "[fast][terrain]") {
  // A 3 x 2 km lake 5 km east of the camera, with a 600 m island (a ring inside the ring).
  regional::LandFeatures features;
  features.lakes.push_back(rectangle("lake", 4000, -1000, 7000, 1000, 560));
  features.lakes[0].rings.push_back(rectangle("island", 5200, -300, 5800, 300, 0).rings[0]);
  const int size = 256;
  const regional::LandCoverGrid g =
      regional::land_cover_grid(camera_lat, camera_lon, camera_height, earth_radius(), features, size, 10240, 40960);
  REQUIRE(g.texel_m(0) == Approx(80.0));
  const regional::TangentPlane plane(camera_lat, camera_lon, camera_height, earth_radius());
  std::vector<std::vector<std::pair<double, double>>> rings;
  for (const auto& ring : features.lakes[0].rings) {
    rings.emplace_back();
    for (const auto& p : ring) rings.back().push_back(plane.of(p.latitude_deg, p.longitude_deg));
  }
  for (int level = 0; level < regional::land_cover_levels; ++level) {
    const double band = g.band_m(level);
    int inside = 0, near_shore = 0;
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i) {
        const std::pair<double, double> p{centre(g, level, i), centre(g, level, j)};
        double d = 1e30;
        bool wet = false;
        for (const auto& ring : rings)
          for (size_t k = 0; k < ring.size(); ++k) {
            const auto a = ring[k], b = ring[(k + 1) % ring.size()];
            d = std::min(d, segment_distance(p, a, b));
            if ((a.second > p.second) != (b.second > p.second) &&
                a.first + (p.second - a.second) * (b.first - a.first) / (b.second - a.second) > p.first)
              wet = !wet;
          }
        const double expected = wet ? -std::min(d, band) : std::min(d, band);
        INFO("level " << level << " texel " << i << ", " << j << " at " << p.first << ", " << p.second);
        // Float texels of distances below a few km: 1 mm.
        REQUIRE(g.water[g.index(level, i, j)] == Approx(expected).margin(1e-3));
        inside += wet;
        near_shore += d < band;
      }
    // The lake less the island, 5.64 km2: texel centres miscount at most a strip half a texel
    // wide along the shores (12.4 km).
    const double t = g.texel_m(level);
    CHECK(std::abs(inside * t * t - 5.64e6) <= 12400.0 * t / 2);
    CHECK(near_shore > 0);
  }
  // The lake's surface for the height field: inside, and within the far level's band outside.
  const auto [in_distance, in_surface] = g.far_lake(5500, 800);
  CHECK(in_distance < 0);
  CHECK(in_surface == 560.0);
  CHECK(std::isnan(g.far_lake(-5000, 0).second));
}

TEST_CASE("a river is drawn at its width where the level resolves it, and left out where it does not",
          "[fast][terrain]") {
  regional::LandFeatures features;
  features.rivers.push_back({"river", 25.0, {offset(-3000, 2000), offset(3000, 2000)}});
  const regional::LandCoverGrid g =
      regional::land_cover_grid(camera_lat, camera_lon, camera_height, earth_radius(), features, 256, 2560, 40960);
  const regional::TangentPlane plane(camera_lat, camera_lon, camera_height, earth_radius());
  const auto a = plane.of(features.rivers[0].points[0].latitude_deg, features.rivers[0].points[0].longitude_deg);
  const auto b = plane.of(features.rivers[0].points[1].latitude_deg, features.rivers[0].points[1].longitude_deg);
  // Near level (20 m texels): the distance to the centre line less 25 m along the whole river.
  int wet = 0;
  for (int j = 0; j < g.size; ++j)
    for (int i = 0; i < g.size; ++i) {
      const std::pair<double, double> p{centre(g, 0, i), centre(g, 0, j)};
      const double expected = std::min(segment_distance(p, a, b) - 25.0, g.band_m(0));
      REQUIRE(g.water[g.index(0, i, j)] == Approx(expected).margin(1e-3));
      wet += expected < 0;
    }
  // A 50 m river across the level's 256 columns of 20 m texels: 2 or 3 texel centres a column.
  CHECK(wet >= 2 * g.size);
  CHECK(wet <= 3 * g.size);
  // Far level (320 m texels): a 50 m river would break into dots, so it is not there.
  CHECK(*std::min_element(g.water.begin() + g.size * g.size, g.water.end()) == Approx(g.band_m(1)));
}

TEST_CASE("built-up land fills a town's municipality within its radius", "[fast][terrain]") {
  regional::LandFeatures features;
  const regional::Town town{"town", offset(0, 0), 2000};
  // The municipality: 3 km east and west, but only 1 km north of the centre.
  features.settlements.push_back({town, rectangle("municipality", -3000, -3000, 3000, 1000, 0)});
  const regional::LandCoverGrid g =
      regional::land_cover_grid(camera_lat, camera_lon, camera_height, earth_radius(), features, 128, 5120, 40960);
  // The texel whose centre is nearest (x, y), and its centre's distance from the town's.
  double distance = 0;
  auto urban_at = [&](double x, double y) {
    const int i = int((x / g.extent_m[0] + 1) * g.size / 2), j = int((y / g.extent_m[0] + 1) * g.size / 2);
    distance = std::hypot(centre(g, 0, i), centre(g, 0, j));
    return g.urban[g.index(0, i, j)];
  };
  CHECK(urban_at(0, 0) == 1.0f);        // the centre
  CHECK(urban_at(-800, -500) == 1.0f);  // within 60 % of the radius
  CHECK(urban_at(0, 1500) == 0.0f);     // within the radius, outside the municipality
  CHECK(urban_at(2600, -500) == 0.0f);  // in the municipality, beyond the radius
  // Within the fading ring: (2000 m - d) / 800 m, d the centre's distance (the camera, the
  // town's centre, is where the four middle texels meet, up to the plane's rounding).
  const float edge = urban_at(1600, 0);
  CHECK(edge == Approx((2000 - distance) / 800).margin(1e-3));
}

TEST_CASE("lakes are carved into the height field at their surface and the shores slope down to it",
          "[fast][terrain]") {
  // A raster at 800 m everywhere and a lake at 560 m.
  regional::ElevationRaster raster{45.0, 5.0, 0.05, 60, 80, std::vector<float>(60 * 80, 800.0f), "flat 800 m"};
  regional::LandFeatures features;
  features.lakes.push_back(rectangle("lake", 4000, -1000, 7000, 1000, 560));
  const auto land = std::make_shared<regional::LandCoverGrid>(
      regional::land_cover_grid(camera_lat, camera_lon, camera_height, earth_radius(), features, 256, 2560, 20480));
  const regional::TerrainGrid plain =
      regional::terrain_grid(camera_lat, camera_lon, camera_height, earth_radius(), raster, {}, 128, 20480);
  const regional::TerrainGrid carved =
      regional::terrain_grid(camera_lat, camera_lon, camera_height, earth_radius(), raster, {}, 128, 20480, land.get());
  int lake_texels = 0;
  for (int j = 0; j < 128; ++j)
    for (int i = 0; i < 128; ++i) {
      const double x = ((2.0 * i + 1) / 128 - 1) * 20480, y = ((2.0 * j + 1) / 128 - 1) * 20480;
      const auto [distance, surface] = land->far_lake(x, y);
      const size_t k = size_t(j) * 128 + i;
      const double lowered = plain.altitudes[k] - carved.altitudes[k];
      INFO("texel " << i << ", " << j << ": distance to the shore " << distance);
      if (distance <= 0) {
        // The altitude above the sphere differs from the elevation by the same amount in both.
        CHECK(lowered == Approx(800.0 - 560.0).margin(1e-3));
        ++lake_texels;
      } else if (distance >= land->band_m(1)) {
        CHECK(lowered == 0.0);
      } else {
        CHECK(lowered >= 0.0);
        CHECK(lowered <= 240.0 + 1e-3);
      }
    }
  CHECK(lake_texels > 0);
  CHECK(carved.source.find("lakes of") != std::string::npos);
}

TEST_CASE("swiss-maps' lakes and towns are read where they are", "[fast][terrain]") {
  if (!have_swiss_maps()) FAIL("swiss-maps is not installed (scripts/install-data.sh)");
  const regional::LandFeatures f = io::read_swiss_maps(io::swiss_maps_default_path);
  auto lake = [&](const std::string& name) {
    const auto it = std::find_if(f.lakes.begin(), f.lakes.end(), [&](const auto& l) { return l.name == name; });
    REQUIRE(it != f.lakes.end());
    return *it;
  };
  // Points in the lakes (the middle of Lake Thun off Merligen, of Lake Biel, of Lake Morat) and
  // on their shores' towns (Thun's station, Biel's, Murten's old town).
  CHECK(regional::contains(lake("Thunersee"), {46.69, 7.74}));
  CHECK(!regional::contains(lake("Thunersee"), {46.7548, 7.6297}));
  CHECK(regional::contains(lake("Bielersee"), {47.08, 7.17}));
  CHECK(!regional::contains(lake("Bielersee"), {47.1325, 7.2432}));
  CHECK(regional::contains(lake("Murtensee"), {46.93, 7.08}));
  CHECK(!regional::contains(lake("Murtensee"), {46.9283, 7.1169}));
  CHECK(lake("Thunersee").surface_m == 558.0);
  // Bern's municipality holds the Zytglogge, not Gurten (which is Koeniz's).
  const auto bern =
      std::find_if(f.settlements.begin(), f.settlements.end(), [](const auto& s) { return s.town.name == "Bern"; });
  REQUIRE(bern != f.settlements.end());
  CHECK(regional::contains(bern->municipality, bern->town.centre));
  CHECK(!regional::contains(bern->municipality, {camera_lat, camera_lon}));
  CHECK(f.settlements.size() == regional::towns().size());
}

TEST_CASE("GSHHG's rivers run the Aare through Bern", "[fast][terrain]") {
  if (!std::filesystem::exists(io::gshhg_rivers_default_path))
    FAIL("gmt-gshhg-full is not installed (scripts/debian-packages.txt)");
  const auto rivers = io::read_rivers(io::gshhg_rivers_default_path, 46.95, 7.45, 20000);
  REQUIRE(!rivers.empty());
  // The Aare's loop round the old town (46.947 N, 7.447 E): WDB II's vertices lie about 380 m
  // apart and a few hundred metres off, so within 1 km.
  double nearest = 1e30, width = 0;
  for (const auto& river : rivers)
    for (const auto& p : river.points) {
      const double d = regional::geodesic_distance_m(46.947, 7.447, p.latitude_deg, p.longitude_deg);
      if (d < nearest) nearest = d, width = river.half_width_m;
    }
  CHECK(nearest < 1000.0);
  CHECK(width == 25.0);  // class 3, "additional rivers"
}

TEST_CASE("a land cover file that is not swiss-maps' TopoJSON is bad input naming the option and the file",
          "[fast][terrain]") {
  const std::string path = (std::filesystem::temp_directory_path() / "nephele-not-topojson.json").string();
  for (const char* text : {"{\"type\": \"FeatureCollection\"}", "not json", "{\"type\": \"Topology\", \"arcs\": []}"}) {
    std::ofstream(path) << text;
    try {
      io::read_swiss_maps(path, "--land-cover");
      FAIL("no error for " << text);
    } catch (const core::InputError& e) {
      CHECK(e.field() == "--land-cover");
      CHECK(std::string(e.what()).find(path) != std::string::npos);
    }
  }
  std::filesystem::remove(path);
}

TEST_CASE("rendered from Bantiger, Lake Neuchatel appears where its shores lie", "[terrain][render]") {
  // From Gurten no mapped lake is in sight over ETOPO5's relief (the Belpberg and Laengenberg
  // hide Lake Thun); from Bantiger's platform Lake Neuchatel is, 45 km west (docs/terrain.md).
  const double camera_lat = 46.977794, camera_lon = 7.528642, camera_height = 975.2;
  if (!have_swiss_maps()) FAIL("swiss-maps is not installed (scripts/install-data.sh)");
  if (!std::filesystem::exists(io::etopo5_default_path)) FAIL("ferret-datasets is not installed");
  test::test_context();
  // The lakes alone (no rivers, no towns), so that the image differs from a dry one only where
  // it shows a lake; the same carved heights for both.
  regional::LandFeatures features = io::read_swiss_maps(io::swiss_maps_default_path);
  features.settlements.clear();
  const double R = render::osculating_earth_radius(camera_lat);
  auto wet = std::make_shared<regional::LandCoverGrid>(
      regional::land_cover_grid(camera_lat, camera_lon, camera_height, R, features, 1024, io::land_cover_near_extent_m,
                                io::land_cover_far_extent_m));
  // The same without water, and all water: a pixel's share of lake is where it lies between.
  auto dry = std::make_shared<regional::LandCoverGrid>(*wet);
  std::fill(dry->water.begin(), dry->water.end(), 1.0e4f);
  auto flooded = std::make_shared<regional::LandCoverGrid>(*wet);
  std::fill(flooded->water.begin(), flooded->water.end(), -1.0e4f);
  const regional::ElevationRaster raster = io::read_etopo5(io::etopo5_default_path, 44.5, 49.5);
  regional::TerrainGrid grid =
      regional::terrain_grid(camera_lat, camera_lon, camera_height, R, raster, regional::substitute_hills(),
                             io::terrain_grid_size, io::terrain_grid_extent_m, wet.get());
  grid.land = wet;
  const auto with_lakes = std::make_shared<const regional::TerrainGrid>(grid);
  grid.land = dry;
  const auto without = std::make_shared<const regional::TerrainGrid>(grid);
  grid.land = flooded;
  const auto all_water = std::make_shared<const regional::TerrainGrid>(grid);

  regional::WeatherField field{4, 160000.0, std::vector<float>(regional::coverage_channels * 16, 0.0f)};
  render::RenderSettings settings;
  settings.sky_steps = 4;
  const double time = 1782032400;  // 2026-06-21 09:00 UTC
  const GeographicLib::LocalCartesian frame(camera_lat, camera_lon, camera_height);
  for (const std::string name : {"Lac de Neuchatel"}) {
    const auto lake =
        *std::find_if(features.lakes.begin(), features.lakes.end(), [&](const auto& l) { return l.name == name; });
    // The geodesic azimuths of the lake's shore points from the camera.
    double least = 360, most = -360, reference = 0;
    for (const auto& ring : lake.rings)
      for (const auto& p : ring) {
        double s, a1, a2;
        GeographicLib::Geodesic::WGS84().Inverse(camera_lat, camera_lon, p.latitude_deg, p.longitude_deg, s, a1, a2);
        const double a = a1 < 0 ? a1 + 360 : a1;
        least = std::min(least, a), most = std::max(most, a);
      }
    reference = 0.5 * (least + most);
    // A view over the lake's azimuths and 2 degrees either side, 0.05 degrees a pixel, from 2
    // degrees below the horizontal to just above it.
    render::Camera camera;
    camera.latitude_deg = camera_lat;
    camera.longitude_deg = camera_lon;
    camera.height_m = camera_height;
    camera.heading_deg = reference;
    camera.pitch_deg = -0.8;
    camera.fov_deg = most - least + 4;
    camera.width = int(std::ceil(camera.fov_deg / 0.05));
    camera.height = 40;
    settings.terrain = with_lakes;
    const render::RenderResult a = render::render_clouds(camera, {}, field, time, settings);
    settings.terrain = without;
    const render::RenderResult b = render::render_clouds(camera, {}, field, time, settings);
    settings.terrain = all_water;
    const render::RenderResult c = render::render_clouds(camera, {}, field, time, settings);
    const glsl::MarchParams m = render::march_params(camera, {}, field, time, settings);
    const glsl::TerrainParams t = regional::terrain_params(*with_lakes);
    const glsl::TerrainSource source = regional::terrain_source(*with_lakes);
    // The image's lake: pixels at least half water (the antialiased shore's middle is the shore),
    // between the dry render and the flooded one in the blue channel. The geodesic lake: pixels whose
    // ray (the marcher's C++ twin) meets the ground at a point that GeographicLib places inside
    // the lake's polygon.
    double image_least = 360, image_most = -360, geo_least = 360, geo_most = -360;
    int image_pixels = 0, geo_pixels = 0;
    for (int row = 0; row < camera.height; ++row)
      for (int column = 0; column < camera.width; ++column) {
        const glm::vec3 d = glsl::view_direction(glm::ivec2(column, row), glm::ivec2(camera.width, camera.height), m);
        double azimuth = std::atan2(d.x, d.y) * 180 / M_PI;
        if (azimuth < 0) azimuth += 360;
        const size_t k = (size_t(row) * camera.width + column) * 4;
        const float land = b.radiance.pixels[k + 2], water = c.radiance.pixels[k + 2];
        if (std::abs(water - land) > 1e-3f * land && (a.radiance.pixels[k + 2] - land) / (water - land) >= 0.5f) {
          image_least = std::min(image_least, azimuth), image_most = std::max(image_most, azimuth);
          ++image_pixels;
        }
        int loops = 0;
        const glm::vec3 o(0.0f, 0.0f, float(R + camera_height));
        const float s = glsl::terrain_hit(o, d, float(R), 1.0e6f, t, loops, source);
        if (s <= 0) continue;
        const glm::vec3 q = o + s * d;
        double lat, lon, h;
        frame.Reverse(q.x, q.y, q.z - (R + camera_height), lat, lon, h);
        if (regional::contains(lake, {lat, lon})) {
          geo_least = std::min(geo_least, azimuth), geo_most = std::max(geo_most, azimuth);
          ++geo_pixels;
        }
      }
    INFO(name << ": shore azimuths " << least << " to " << most << " deg; in the image " << image_least << " to "
              << image_most << " deg (" << image_pixels << " pixels); geodesic " << geo_least << " to " << geo_most
              << " deg (" << geo_pixels << " pixels)");
    REQUIRE(geo_pixels > 0);
    REQUIRE(image_pixels > 0);
    CHECK(std::abs(image_least - geo_least) <= 1.0);
    CHECK(std::abs(image_most - geo_most) <= 1.0);
    CHECK(image_least >= least - 1.0);
    CHECK(image_most <= most + 1.0);
    // Pixel by pixel the same lake, up to the shore's pixels.
    CHECK(std::abs(image_pixels - geo_pixels) <= geo_pixels / 10);
  }
}

TEST_CASE("the crops are bare in winter, green in spring and ripe in summer", "[fast][terrain]") {
  CHECK(regional::seasonal_crop_stage(15) == 0.0);           // January: ploughed
  CHECK(regional::seasonal_crop_stage(150) == 1.0);          // end of May: green
  CHECK(regional::seasonal_crop_stage(172) == 1.0);          // the solstice
  CHECK(regional::seasonal_crop_stage(215) == 2.0);          // early August: ripe
  CHECK(regional::seasonal_crop_stage(300) == 0.0);          // end of October: ploughed again
  CHECK(regional::seasonal_crop_stage(105) == Approx(0.5));  // half way to green
}
