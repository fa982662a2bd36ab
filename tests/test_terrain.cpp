// The ground of the views near the ground: ETOPO5 as read, the height field built from it with
// the substitute hills, and the horizon the renderer sees against the one computed from the
// elevation data (docs/terrain.md).
#include <catch2/catch.hpp>

#include <GeographicLib/Geodesic.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <random>
#include <vector>

#include "core/error.hpp"
#include "gl_support.hpp"
#include "io/elevation_files.hpp"
#include "march_tolerance.hpp"
#include "regional/sites.hpp"
#include "regional/terrain.hpp"
#include "render/cloud_renderer.hpp"
#include "shader_math/shader_math.hpp"
#include "tolerances.hpp"

using namespace nephele;

namespace {

constexpr double gurten_lat = 46.91722, gurten_lon = 7.44361, eye_height = 860.0;  // 2 m above the summit
constexpr double eiger_lat = 46.5776, eiger_lon = 7.9974;                          // 3967 m
constexpr double chasseral_lat = 47.1328, chasseral_lon = 7.0586;                  // 1607 m, the Jura

bool have_etopo5() { return std::filesystem::exists(io::etopo5_default_path); }

const regional::ElevationRaster& raster() {
  static const regional::ElevationRaster r = io::read_etopo5(io::etopo5_default_path, 44.0, 50.0);
  return r;
}

const regional::TerrainGrid& gurten_grid() {
  static const std::shared_ptr<const regional::TerrainGrid> grid =
      io::load_terrain("etopo5", gurten_lat, gurten_lon, eye_height);
  return *grid;
}

double azimuth_deg(double lat, double lon) {
  double s, a1, a2;
  GeographicLib::Geodesic::WGS84().Inverse(gurten_lat, gurten_lon, lat, lon, s, a1, a2);
  return a1;
}

// The highest pitch (degrees) at which a ray from the camera in an azimuth meets the ground, by
// bisection over rays cast with the marcher's C++ twin (terrain.glsl).
double cast_horizon_deg(const regional::TerrainGrid& g, double azimuth) {
  using namespace glsl;
  const float R = float(render::osculating_earth_radius(gurten_lat));
  const TerrainParams t = regional::terrain_params(g);
  const TerrainSource source = regional::terrain_source(g);
  const vec3 o(0.0f, 0.0f, R + float(eye_height));
  auto hits = [&](double pitch_deg) {
    const double p = pitch_deg * M_PI / 180, a = azimuth * M_PI / 180;
    const vec3 d(float(std::cos(p) * std::sin(a)), float(std::cos(p) * std::cos(a)), float(std::sin(p)));
    int loops = 0;
    return terrain_hit(o, d, R, 1.0e6f, t, loops, source) > 0.0f;
  };
  double below = -5.0, above = 10.0;
  REQUIRE(hits(below));
  REQUIRE(!hits(above));
  while (above - below > 1e-5) {
    const double middle = 0.5 * (below + above);
    (hits(middle) ? below : above) = middle;
  }
  return 0.5 * (below + above);
}

// The steepest slope of the raster's bilinear surface between two latitudes and longitudes:
// its largest sample-to-sample difference over the sample spacing (metres).
double steepest_slope(const regional::ElevationRaster& r, double south, double north, double west, double east) {
  double steepest = 0;
  const double dy = r.step_deg * 111132.0;
  for (int row = 0; row + 1 < r.rows; ++row) {
    const double lat = r.south_deg + row * r.step_deg;
    if (lat < south || lat > north) continue;
    const double dx = dy * std::cos(lat * M_PI / 180);
    for (int c = 0; c + 1 < r.columns; ++c) {
      const double lon = r.west_deg + c * r.step_deg;
      if (lon < west || lon > east) continue;
      const float h = r.heights[size_t(row) * r.columns + c];
      steepest = std::max({steepest, std::abs(r.heights[size_t(row) * r.columns + c + 1] - h) / dx,
                           std::abs(r.heights[size_t(row + 1) * r.columns + c] - h) / dy});
    }
  }
  return steepest;
}

// How far the ray-cast horizon may lie from the elevation data's, in degrees, for ground at
// distance_m. The height field resamples the raster's bilinear surface at texel centres; a
// bilinear interpolation of those is a convex combination of values within sqrt(2) Delta of the
// point, so it differs from the raster by at most L sqrt(2) Delta (L the raster's steepest slope
// around Bern and the Alps). The reference's samples, step_m apart, miss the highest point by at
// most L step / 2. At the distance these heights are angles; rounding (kPosition at the Earth's
// radius) adds kPosition / D.
double horizon_tolerance_deg(const regional::TerrainGrid& g, double distance_m, double step_m) {
  static const double L = steepest_slope(raster(), 46.0, 47.6, 6.5, 8.5);
  return (L * std::sqrt(2.0) * g.texel_m() + L * step_m / 2 + test::kPosition) / distance_m * 180 / M_PI;
}

// A clear sky from Gurten rendered with and without the ground: no layer is marched, so the
// pixels differ only where the ground shows.
struct ClearView {
  render::Camera camera;
  render::RenderResult with, bare;
  glsl::MarchParams m;
  glm::vec3 direction(int column, int row) const {
    return glsl::view_direction(glm::ivec2(column, row), glm::ivec2(camera.width, camera.height), m);
  }
  double elevation_deg(int column, int row) const { return std::asin(direction(column, row).z) * 180 / M_PI; }
  // The first row from the top whose pixel shows the ground in a column; -1 where none does.
  int first_ground_row(int column) const {
    for (int row = 0; row < camera.height; ++row) {
      const size_t k = (size_t(row) * camera.width + column) * 4;
      if (std::abs(with.radiance.pixels[k] - bare.radiance.pixels[k]) > 1e-6f * std::abs(bare.radiance.pixels[k]))
        return row;
    }
    return -1;
  }
};

ClearView clear_view_from_gurten(const std::shared_ptr<const regional::TerrainGrid>& grid, double heading, double pitch,
                                 double fov, int width, int height) {
  regional::WeatherField field{4, 160000.0, std::vector<float>(regional::coverage_channels * 16, 0.0f)};
  render::RenderSettings settings;
  settings.sky_steps = 4;
  ClearView view;
  view.camera.latitude_deg = gurten_lat;
  view.camera.longitude_deg = gurten_lon;
  view.camera.height_m = eye_height;
  view.camera.heading_deg = heading;
  view.camera.pitch_deg = pitch;
  view.camera.fov_deg = fov;
  view.camera.width = width;
  view.camera.height = height;
  const double time = 1782036000;  // 2026-06-21 10:00 UTC
  settings.terrain = grid;
  view.with = render::render_clouds(view.camera, {}, field, time, settings);
  settings.terrain = nullptr;
  view.bare = render::render_clouds(view.camera, {}, field, time, settings);
  view.m = render::march_params(view.camera, {}, field, time, settings);
  return view;
}

}  // namespace

TEST_CASE("ETOPO5 reads Bern's plateau, the Bernese Alps and the Atlantic where they are", "[fast][terrain]") {
  if (!have_etopo5()) FAIL("ferret-datasets is not installed (scripts/debian-packages.txt)");
  const auto& r = raster();
  // The samples next to Bern as the file holds them (row 1643 is 46.91667 N, column 89 is
  // 7.41667 E): 610 m, 713 m a row north (1644), the plateau at row 1645 560 m; between
  // samples bilinear. (Lattice coordinates are rounded: a micrometre's margin.)
  CHECK(*r.at(-90.0 + 1643 / 12.0, 89 / 12.0) == Approx(610.0).epsilon(0).margin(1e-6));
  CHECK(*r.at(-90.0 + 1645 / 12.0, 89 / 12.0) == Approx(560.0).epsilon(0).margin(1e-6));
  CHECK(*r.at(-90.0 + 1643.5 / 12.0, 89 / 12.0) == Approx((610.0 + 713.0) / 2).epsilon(0).margin(1e-6));
  // The Eiger region: the highest cells of the Bernese Oberland exceed 2500 m but are below the
  // 3967 m summit (5' cells average the relief).
  CHECK(*r.at(eiger_lat, eiger_lon) > 2500.0);
  CHECK(*r.at(eiger_lat, eiger_lon) < 3967.0);
  // Longitude wraps: 359.99 E is next to 0 E.
  CHECK(r.at(46.0, -0.01).has_value());
  const regional::ElevationRaster ocean = io::read_etopo5(io::etopo5_default_path, -1.0, 1.0);
  CHECK(*ocean.at(0.0, -30.0) < -2000.0);
}

TEST_CASE("the whole ETOPO5 is read once while held and let go when nobody holds it", "[fast][terrain]") {
  if (!have_etopo5()) FAIL("ferret-datasets is not installed (scripts/debian-packages.txt)");
  std::weak_ptr<const regional::ElevationRaster> released;
  {
    const auto held = io::whole_etopo5(io::etopo5_default_path, "--surface");
    // A second reader (the land/ocean mask beside the orbit view's water) gets the same raster.
    CHECK(io::whole_etopo5(io::etopo5_default_path, "--surface").get() == held.get());
    // From pole to pole, every column: read_etopo5's whole lattice.
    const regional::ElevationRaster whole = io::read_etopo5(io::etopo5_default_path, -90.0, 90.0);
    CHECK(held->rows == whole.rows);
    CHECK(held->columns == whole.columns);
    CHECK(held->heights == whole.heights);
    released = held;
  }
  // Nobody holds it: the process keeps no copy.
  CHECK(released.expired());
}

TEST_CASE("a raster's heights a row at a time are at()'s to the bit, inside and outside the lattice",
          "[fast][terrain]") {
  // A lattice of 5 x 7 samples from 10 S, 20 W, 2 degrees apart (up to 2 N, 8 W), heights from a
  // hash; points inside, on its last row and column, beyond it and wrapped by 360 degrees.
  regional::ElevationRaster raster;
  raster.south_deg = -10;
  raster.west_deg = -20;
  raster.step_deg = 2;
  raster.rows = 5;
  raster.columns = 7;
  for (int k = 0; k < raster.rows * raster.columns; ++k) raster.heights.push_back(float((k * 7919) % 101) - 30.0f);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> lon(-25.0, -5.0), lat(-12.0, 4.0);
  std::vector<double> longitudes{-20.0, -8.0, 340.0, -8.0001, -20.0001};
  for (int k = 0; k < 40; ++k) longitudes.push_back(lon(random));
  const regional::ElevationRaster::Columns columns = raster.columns_at(longitudes);
  std::vector<double> row(longitudes.size());
  std::vector<double> latitudes{-10.0, 2.0, 2.0001, -10.0001};
  for (int k = 0; k < 20; ++k) latitudes.push_back(lat(random));
  int inside = 0;
  for (double latitude : latitudes) {
    raster.row_at(latitude, columns, -999.0, row.data());
    for (size_t k = 0; k < longitudes.size(); ++k) {
      INFO("latitude " << latitude << " longitude " << longitudes[k]);
      const std::optional<double> expected = raster.at(latitude, longitudes[k]);
      CHECK(row[k] == expected.value_or(-999.0));
      inside += expected.has_value();
    }
  }
  CHECK(inside > 100);  // most points lie inside: the comparison is not of -999 alone
}

TEST_CASE("an elevation file that is not ETOPO5 is bad input naming the option and the file", "[fast][terrain]") {
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "nephele_not_etopo5.cdf";
  std::ofstream(path) << "CDF\x01 not the data";
  try {
    io::read_etopo5(path.string(), 46.0, 47.0, "--terrain");
    FAIL("no error");
  } catch (const core::InputError& e) {
    CHECK(std::string(e.what()).find("--terrain") != std::string::npos);
    CHECK(std::string(e.what()).find(path.string()) != std::string::npos);
  }
  CHECK_THROWS_AS(io::read_etopo5((path.string() + ".absent"), 46.0, 47.0), core::InputError);
  std::filesystem::remove(path);
  // "flat" asks for no terrain at all.
  CHECK(io::load_terrain("flat", gurten_lat, gurten_lon, eye_height) == nullptr);
}

TEST_CASE("a camera below the smoothed ground is warned about, one on Gurten is not", "[fast][terrain]") {
  if (!have_etopo5()) FAIL("ferret-datasets is not installed (scripts/debian-packages.txt)");
  std::string warning;
  // Bern's old town (540 m) lies under ETOPO5's 700 m there.
  CHECK(io::load_terrain("etopo5", 46.94806, 7.44750, 542.0, &warning) != nullptr);
  CHECK(warning.find("below the terrain") != std::string::npos);
  warning.clear();
  CHECK(io::load_terrain("etopo5", gurten_lat, gurten_lon, eye_height, &warning) != nullptr);
  CHECK(warning.empty());
  // The same place 2 km up: the same ground (kept, not made again), and no warning.
  const auto low = io::load_terrain("etopo5", 46.94806, 7.44750, 542.0);
  warning.clear();
  CHECK(io::load_terrain("etopo5", 46.94806, 7.44750, 2542.0, &warning) == low);
  CHECK(warning.empty());
}

TEST_CASE("the height field about a camera is the same at any camera height", "[fast][terrain]") {
  if (!have_etopo5()) FAIL("ferret-datasets is not installed (scripts/debian-packages.txt)");
  // A point's east and north coordinates in the tangent plane do not change as its origin moves
  // up the normal; the grid made 20 km up differs from the one at the ground only where the
  // double altitude rounds to the other float (one ulp of the largest altitude at most) and by
  // the frame's trigonometry (nanometres).
  const auto at = [&](double height_m) {
    return regional::terrain_grid(gurten_lat, gurten_lon, height_m, 6366000.0, raster(), regional::substitute_hills(),
                                  64, 40000.0);
  };
  const regional::TerrainGrid ground = at(0.0), high = at(20000.0);
  REQUIRE(ground.altitudes.size() == high.altitudes.size());
  double worst = 0, largest = 0;
  for (std::size_t k = 0; k < ground.altitudes.size(); ++k) {
    worst = std::max(worst, double(std::abs(ground.altitudes[k] - high.altitudes[k])));
    largest = std::max(largest, double(std::abs(ground.altitudes[k])));
  }
  REQUIRE(largest > 500.0);  // the Gurten's ground, not an empty grid
  CHECK(worst <= largest * std::ldexp(1.0, -23) + 1e-6);
}

TEST_CASE("the substitute hills bring Gurten and Bantiger up to their summits", "[fast][terrain]") {
  if (!have_etopo5()) FAIL("ferret-datasets is not installed (scripts/debian-packages.txt)");
  const auto& g = gurten_grid();
  const glsl::TerrainSource source = regional::terrain_source(g);
  const glsl::TerrainParams t = regional::terrain_params(g);
  // Bilinear interpolation between texels Delta apart lowers a peak of curvature A / sigma^2
  // along each axis by at most Delta^2 / 8 of the curvatures' sum.
  for (const auto& hill : regional::substitute_hills()) {
    const double relief = hill.summit_m - *raster().at(hill.latitude_deg, hill.longitude_deg);
    const double peak_loss = g.texel_m() * g.texel_m() / 8 * 2 * relief / (hill.sigma_m * hill.sigma_m);
    // The summit's horizontal coordinate in the camera's frame (metres east and north).
    double s, a1, a2;
    GeographicLib::Geodesic::WGS84().Inverse(gurten_lat, gurten_lon, hill.latitude_deg, hill.longitude_deg, s, a1, a2);
    const glsl::vec2 xy(float(s * std::sin(a1 * M_PI / 180)), float(s * std::cos(a1 * M_PI / 180)));
    INFO(hill.name << ": relief above the raster " << relief << " m, peak loss bound " << peak_loss << " m");
    const double altitude = glsl::terrain_altitude(xy, t, source);
    // The sphere lies below the ellipsoid by s^2 / 2 (1/R_sphere - 1/R_ellipsoid) (under a metre
    // within 10 km): absorbed by a metre's margin.
    CHECK(altitude <= hill.summit_m + 1.0);
    CHECK(altitude >= hill.summit_m - peak_loss - 1.0);
  }
}

TEST_CASE("from Gurten the ray-cast horizon towards the Eiger and the Jura matches the elevation data",
          "[fast][terrain]") {
  if (!have_etopo5()) FAIL("ferret-datasets is not installed (scripts/debian-packages.txt)");
  const auto& g = gurten_grid();
  const double step = 100.0;
  for (const auto& [name, lat, lon] : {std::tuple<const char*, double, double>{"Eiger", eiger_lat, eiger_lon},
                                       {"Chasseral (Jura)", chasseral_lat, chasseral_lon}}) {
    const double azimuth = azimuth_deg(lat, lon);
    double distance = 0;
    const double reference = regional::horizon_elevation_deg(gurten_lat, gurten_lon, eye_height, azimuth, raster(),
                                                             regional::substitute_hills(), 140000.0, step, &distance);
    const double cast = cast_horizon_deg(g, azimuth);
    const double tolerance = horizon_tolerance_deg(g, distance, step);
    INFO(name << ": azimuth " << azimuth << ", reference " << reference << " deg at " << distance << " m, cast " << cast
              << " deg, tolerance " << tolerance << " deg");
    CHECK(cast == Approx(reference).epsilon(0).margin(tolerance));
    // The bare sphere's horizon from 860 m lies acos(R / (R + h)) below the horizontal: the
    // ground stands above it in both directions.
    const double sphere_dip = -std::acos(6.367e6 / (6.367e6 + eye_height)) * 180 / M_PI;
    CHECK(cast > sphere_dip + 0.5);
  }
  // The Alps stand higher on the horizon than the Jura.
  CHECK(cast_horizon_deg(g, azimuth_deg(eiger_lat, eiger_lon)) >
        cast_horizon_deg(g, azimuth_deg(chasseral_lat, chasseral_lon)) + 0.5);
}

TEST_CASE("rendered from Gurten, the ground meets the sky where the elevation data put the horizon",
          "[terrain][render]") {
  if (!have_etopo5()) FAIL("ferret-datasets is not installed (scripts/debian-packages.txt)");
  test::test_context();
  const auto grid = io::load_terrain("etopo5", gurten_lat, gurten_lon, eye_height);
  for (const auto& [name, lat, lon] : {std::tuple<const char*, double, double>{"Eiger", eiger_lat, eiger_lon},
                                       {"Chasseral (Jura)", chasseral_lat, chasseral_lon}}) {
    // A narrow column of pixels about the bare sphere's horizon and the reference's: 0.19
    // degrees a pixel, 9 degrees tall.
    const ClearView view = clear_view_from_gurten(grid, azimuth_deg(lat, lon), 0.5, 1.5, 8, 48);
    const render::Camera& camera = view.camera;
    double distance = 0;
    const double reference =
        regional::horizon_elevation_deg(gurten_lat, gurten_lon, eye_height, camera.heading_deg, raster(),
                                        regional::substitute_hills(), 140000.0, 100.0, &distance);
    const double tolerance = horizon_tolerance_deg(*grid, distance, 100.0);
    // The first row from the top where the ground shows: its ray meets the ground, the row
    // above it does not, so the horizon lies between their elevations (within the height
    // field's tolerance).
    const int column = camera.width / 2;
    const int first = view.first_ground_row(column);
    REQUIRE(first > 0);
    auto elevation = [&](int row) { return view.elevation_deg(column, row); };
    INFO(name << ": reference " << reference << " deg, ground from row " << first << " at " << elevation(first)
              << " deg, row above at " << elevation(first - 1) << " deg");
    CHECK(reference >= elevation(first) - tolerance);
    CHECK(reference <= elevation(first - 1) + tolerance);
    // Above the bare sphere's horizon (0.94 degrees below the horizontal from 860 m).
    CHECK(elevation(first) > -0.9);
  }
}

TEST_CASE("the terrain ceiling is the highest altitude of its window and bounds the bilinear ground within reach",
          "[fast][terrain]") {
  // A random field: the running maxima against brute force.
  const int size = 23, window = 3;
  std::vector<float> heights;
  std::uint32_t state = 12345;
  for (int k = 0; k < size * size; ++k) {
    state = state * 1664525u + 1013904223u;
    heights.push_back(float(state >> 8) / float(1 << 24) * 1000.0f);
  }
  const auto ceilings = regional::terrain_ceilings(heights, size, window);
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      float highest = 0;
      for (int b = std::max(j - window, 0); b <= std::min(j + window, size - 1); ++b)
        for (int a = std::max(i - window, 0); a <= std::min(i + window, size - 1); ++a)
          highest = std::max(highest, heights[size_t(b) * size + a]);
      CHECK(ceilings[size_t(j) * size + i] == highest);
    }
  if (!have_etopo5()) FAIL("ferret-datasets is not installed (scripts/debian-packages.txt)");
  // Around Gurten: from any point, the ground within reach never rises above the point's
  // bilinear ceiling (both sampled as the GPU does; float rounding of the interpolation, a few
  // ulp of 4000 m, is the only allowance).
  const auto& g = gurten_grid();
  REQUIRE(g.ceiling_window == regional::terrain_ceiling_window);
  const glsl::TerrainParams t = regional::terrain_params(g);
  const glsl::TerrainSource source = regional::terrain_source(g);
  CHECK(t.reach == Approx((g.ceiling_window - 2) * g.texel_m()));
  int checked = 0;
  for (int k = 0; k < 4000; ++k) {
    state = state * 1664525u + 1013904223u;
    const float x = (float(state >> 8) / float(1 << 24) * 2 - 1) * 1.1f * t.extent;
    state = state * 1664525u + 1013904223u;
    const float y = (float(state >> 8) / float(1 << 24) * 2 - 1) * 1.1f * t.extent;
    state = state * 1664525u + 1013904223u;
    const float angle = float(state >> 8) / float(1 << 24) * 6.2831853f;
    state = state * 1664525u + 1013904223u;
    const float r = float(state >> 8) / float(1 << 24) * t.reach;
    const glsl::vec2 p(x, y), q = p + r * glsl::vec2(std::cos(angle), std::sin(angle));
    const float ground = glsl::terrain_altitude(q, t, source);
    const float ceiling = glsl::terrain_ceiling(p, t, source);
    INFO("p " << x << ", " << y << " offset " << r << " ground " << ground << " ceiling " << ceiling);
    CHECK(ground <= ceiling + 1e-3f);
    ++checked;
  }
  CHECK(checked == 4000);
}

TEST_CASE("the terrain march steps over ground it is well above and meets the ground as well as without the ceiling",
          "[fast][terrain]") {
  if (!have_etopo5()) FAIL("ferret-datasets is not installed (scripts/debian-packages.txt)");
  using namespace glsl;
  const auto& g = gurten_grid();
  const float R = float(render::osculating_earth_radius(gurten_lat));
  const vec3 o(0.0f, 0.0f, R + float(eye_height));
  const TerrainSource source = regional::terrain_source(g);
  const TerrainParams with = regional::terrain_params(g);
  TerrainParams without = with;
  without.reach = 0.0f;  // the march as it was: half the clearance, at most a texel
  long loops_with = 0, loops_without = 0;
  int rays = 0;
  for (int a = 0; a < 360; a += 10)
    for (double p = -4; p <= 20; p += 1) {
      const double pr = p * M_PI / 180, ar = a * M_PI / 180;
      const vec3 d(float(std::cos(pr) * std::sin(ar)), float(std::cos(pr) * std::cos(ar)), float(std::sin(pr)));
      int n1 = 0, n0 = 0;
      const float s1 = terrain_hit(o, d, R, 1.5e5f, with, n1, source);
      const float s0 = terrain_hit(o, d, R, 1.5e5f, without, n0, source);
      loops_with += n1;
      loops_without += n0;
      // The first ground point by 5 m steps (the texels are 390 m: no crossing hides between).
      float first = -1;
      for (float x = 0; x < 1.5e5f && p < 3; x += 5.0f)
        if (terrain_clearance(o + x * d, R, with, source) <= 0) {
          first = x;
          break;
        }
      INFO("azimuth " << a << " pitch " << p << ": first ground " << first << ", with the ceiling " << s1
                      << ", without " << s0);
      // Both marches find ground on the same rays.
      CHECK((s1 > 0) == (s0 > 0));
      // Where a grazing ray dips under the ground and out again within one step, a march may
      // bisect a later crossing of the same step: its resolution is its least step, 2 m + 1% of
      // the distance (plus the reference's 5 m). The ceiling's steps stay above all ground within
      // reach, so with them the hit is never further off than that or than the plain march's.
      if (s1 > 0 && first > 0) {
        const float resolution = 2.0f + 0.01f * first + 5.0f;
        CHECK(std::abs(s1 - first) <= std::max(std::abs(s0 - first), resolution));
      }
      ++rays;
    }
  INFO("rays " << rays << ", loops " << loops_with << " against " << loops_without);
  // Rays that rise, or look over the Plateau, spend most of their march well above the ground.
  CHECK(2 * loops_with < loops_without);
}

TEST_CASE("rendered from Gurten, the Alps' skyline follows the elevation data and peaks at the Jungfrau massif",
          "[terrain][render]") {
  if (!have_etopo5()) FAIL("ferret-datasets is not installed (scripts/debian-packages.txt)");
  test::test_context();
  const auto grid = io::load_terrain("etopo5", gurten_lat, gurten_lon, eye_height);
  // The Bernese Alps from the Bluemlisalp to beyond the Schreckhorn (azimuths 115 to 155
  // degrees), 0.05 degrees a pixel, elevations 0 to 3 degrees.
  const ClearView view = clear_view_from_gurten(grid, 135, 1.5, 40, 800, 60);
  const render::Camera& camera = view.camera;
  // Per column: the image's skyline (the elevation of the first row from the top that shows
  // ground) and the elevation data's (along the geodesic, 200 m steps).
  std::vector<double> azimuth(camera.width), image(camera.width), data(camera.width);
  for (int column = 0; column < camera.width; ++column) {
    const glm::vec3 top = view.direction(column, 0);
    azimuth[column] = std::atan2(top.x, top.y) * 180 / M_PI;
    const int first = view.first_ground_row(column);
    image[column] = first >= 0 ? view.elevation_deg(column, first) : -90;
    data[column] = regional::horizon_elevation_deg(gurten_lat, gurten_lon, eye_height, azimuth[column], raster(),
                                                   regional::substitute_hills(), 140000.0, 200.0);
  }
  // The data's peaks: the highest point within 1.5 degrees either side, standing at least 0.1
  // degrees above the lowest there (a massif, not a shoulder).
  // ETOPO5's 5' cells smooth the Bernese Alps into one dome whose top is the massif of the
  // Eiger, Moench and Jungfrau (Jungfrau 4158 m, 46.5367 N 7.9622 E): the image's highest
  // skyline (the middle of the columns that reach its highest row) stands within 1 degree of
  // the data's highest, and both within 1 degree of the massif's geodesic azimuths (from the
  // Eiger's to the Jungfrau's).
  const int top = int(std::max_element(data.begin(), data.end()) - data.begin());
  const double highest = *std::max_element(image.begin(), image.end());
  double sum = 0;
  int count = 0;
  for (int k = 0; k < camera.width; ++k)
    if (image[k] == highest) sum += azimuth[k], ++count;
  const double eiger = azimuth_deg(eiger_lat, eiger_lon), jungfrau = azimuth_deg(46.5367, 7.9622);
  INFO("data's highest skyline " << data[top] << " deg at azimuth " << azimuth[top] << " deg; image's " << highest
                                 << " deg at " << sum / count << " deg; the Eiger at " << eiger
                                 << " deg, the Jungfrau at " << jungfrau << " deg");
  CHECK(std::abs(sum / count - azimuth[top]) <= 1.0);
  for (const double peak : {sum / count, azimuth[top]}) {
    CHECK(peak >= eiger - 1.0);
    CHECK(peak <= jungfrau + 1.0);
  }
  // The whole skyline: within a row (0.05 degrees) and the height field's tolerance at the Alps'
  // distance (50 to 80 km) in every column.
  const double tolerance = 0.05 + horizon_tolerance_deg(*grid, 50000.0, 200.0);
  for (int k = 0; k < camera.width; ++k) {
    INFO("azimuth " << azimuth[k] << " deg: image " << image[k] << " deg, data " << data[k] << " deg");
    CHECK(std::abs(image[k] - data[k]) <= tolerance);
  }
}

TEST_CASE("the fractal detail never moves a summit nor lifts ground above its cell's highest sample",
          "[fast][terrain]") {
  if (!have_etopo5()) FAIL("ferret-datasets is not installed (scripts/debian-packages.txt)");
  const auto& r = raster();
  const regional::TerrainDetail detail = regional::terrain_detail(r, 45.6, 48.2, 5.5, 9.4, 1.0);
  REQUIRE(detail.cell_rms_m > 0);
  int summits = 0;
  for (int row = 1; row + 1 < r.rows; ++row)
    for (int c = 1; c + 1 < r.columns; ++c) {
      const double lat = r.south_deg + row * r.step_deg, lon = r.west_deg + c * r.step_deg;
      if (lat < 46.0 || lat > 47.8 || lon < 6.0 || lon > 9.0) continue;
      const float h = r.heights[size_t(row) * r.columns + c];
      bool summit = h > 0;
      for (int dr = -1; dr <= 1; ++dr)
        for (int dc = -1; dc <= 1; ++dc)
          if ((dr || dc) && r.heights[size_t(row + dr) * r.columns + c + dc] >= h) summit = false;
      if (!summit) continue;
      ++summits;
      // Lattice coordinates are rounded: a micrometre's margin.
      CHECK(regional::relief_elevation(r, detail, lat, lon) == Approx(h).epsilon(0).margin(1e-6));
    }
  CHECK(summits > 20);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> lat(46.0, 47.8), lon(6.0, 9.0);
  for (int k = 0; k < 20000; ++k) {
    const double a = lat(rng), b = lon(rng);
    const int row = int((a - r.south_deg) / r.step_deg), c = int((b - r.west_deg) / r.step_deg);
    double highest = 0;
    for (int dr = 0; dr <= 1; ++dr)
      for (int dc = 0; dc <= 1; ++dc)
        highest = std::max(highest, double(r.heights[size_t(row + dr) * r.columns + c + dc]));
    REQUIRE(regional::relief_elevation(r, detail, a, b) <= highest + 1e-9);
  }
}

TEST_CASE("the fractal detail continues the elevation data's structure function below its cells", "[fast][terrain]") {
  if (!have_etopo5()) FAIL("ferret-datasets is not installed (scripts/debian-packages.txt)");
  const auto& r = raster();
  // The region of the ground views around Bern: its fitted H and S(one cell).
  const regional::TerrainDetail detail = regional::terrain_detail(r, 45.6, 48.2, 5.5, 9.4, 1.0);
  const regional::TerrainDetail none = regional::terrain_detail(r, 45.6, 48.2, 5.5, 9.4, 0.0);
  INFO("fitted H " << detail.hurst << ", S(one cell) " << detail.cell_rms_m << " m");
  // S at lags of a half, a quarter and an eighth of a cell (north-south), over random points.
  const double cell = r.step_deg;
  auto structure = [&](const regional::TerrainDetail& d, double lag) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> lat(45.8, 48.0), lon(5.7, 9.2);
    double sum = 0;
    const int n = 40000;
    for (int k = 0; k < n; ++k) {
      const double a = lat(rng), b = lon(rng);
      const double dh = regional::relief_elevation(r, d, a + lag * cell, b) - regional::relief_elevation(r, d, a, b);
      sum += dh * dh;
    }
    return std::sqrt(sum / n);
  };
  for (const double lag : {0.5, 0.25, 0.125}) {
    const double expected = detail.cell_rms_m * std::pow(lag, detail.hurst);
    const double with = structure(detail, lag), without = structure(none, lag);
    INFO("lag " << lag << " cell: power law " << expected << " m, with detail " << with << " m, without " << without
                << " m");
    // The data's power law within a quarter (the octaves' rms is set for it; clamping at the
    // cells' highest samples and the summits' holes take a little); the bilinear surface alone
    // falls short, more so the shorter the lag (it is smooth: S ~ lag).
    CHECK(with == Approx(expected).epsilon(0.25));
    CHECK(without < 0.8 * expected);
  }
}
