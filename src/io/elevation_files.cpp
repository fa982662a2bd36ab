#include "io/elevation_files.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>

#include "core/error.hpp"
#include "core/input_file.hpp"
#include "io/land_cover_files.hpp"
#include "render/cloud_renderer.hpp"

namespace nephele::io {
namespace {

constexpr std::uint64_t etopo5_header_bytes = 52552;
constexpr int etopo5_rows = 2161, etopo5_columns = 4320;
constexpr double etopo5_step_deg = 1.0 / 12.0;

float big_endian_float(const unsigned char* b) {
  const std::uint32_t bits =
      (std::uint32_t(b[0]) << 24) | (std::uint32_t(b[1]) << 16) | (std::uint32_t(b[2]) << 8) | b[3];
  float f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

}  // namespace

std::shared_ptr<const regional::ElevationRaster> whole_etopo5(const std::string& path, const std::string& field) {
  static std::mutex guard;
  static std::map<std::string, std::weak_ptr<const regional::ElevationRaster>> held;
  const std::lock_guard<std::mutex> lock(guard);
  if (auto raster = held[path].lock()) return raster;
  auto raster = std::make_shared<const regional::ElevationRaster>(read_etopo5(path, -90.0, 90.0, field));
  held[path] = raster;
  return raster;
}

regional::ElevationRaster read_etopo5(const std::string& path, double south_deg, double north_deg,
                                      const std::string& field) {
  const std::string allowed = "the ETOPO5 netCDF of ferret-datasets (" + std::string(etopo5_default_path) + ")";
  const std::uint64_t expected = etopo5_header_bytes + std::uint64_t(etopo5_rows) * etopo5_columns * 4;
  std::uint64_t bytes = 0;
  try {
    bytes = core::regular_file_size(path);
  } catch (const core::InputFileError& e) {
    throw core::InputError(field, path, allowed, std::string("cannot be read: ") + e.what());
  }
  if (bytes != expected)
    throw core::InputError(field, path, allowed,
                           "has " + std::to_string(bytes) + " bytes, not " + std::to_string(expected));
  std::ifstream in(path, std::ios::binary);
  std::string header(etopo5_header_bytes, '\0');
  if (!in.read(header.data(), header.size()) || header.compare(0, 4, std::string("CDF\x01", 4)) != 0 ||
      header.find("ETOPO05_X") == std::string::npos || header.find("ETOPO05_Y") == std::string::npos)
    throw core::InputError(field, path, allowed, "is not ETOPO5 (no netCDF header naming ETOPO05_X and ETOPO05_Y)");
  // The coordinate variables end the header, big-endian doubles: 4320 longitudes from 0 east,
  // then 2161 latitudes from -90 to 90. The lattice assumed below must be theirs.
  const std::size_t latitudes = etopo5_header_bytes - std::size_t(etopo5_rows) * 8;
  auto coordinate = [&](std::size_t offset) {
    unsigned char b[8];
    std::memcpy(b, header.data() + offset, 8);
    std::uint64_t bits = 0;
    for (unsigned char c : b) bits = (bits << 8) | c;
    double d;
    std::memcpy(&d, &bits, sizeof d);
    return d;
  };
  if (coordinate(latitudes - std::size_t(etopo5_columns) * 8) != 0.0 || coordinate(latitudes) != -90.0 ||
      coordinate(etopo5_header_bytes - 8) != 90.0)
    throw core::InputError(field, path, allowed, "has other coordinates than ETOPO5 (0 E first, -90 to 90 N)");
  const int first = std::clamp(static_cast<int>(std::floor((south_deg + 90.0) * 12.0)), 0, etopo5_rows - 1);
  const int last = std::clamp(static_cast<int>(std::ceil((north_deg + 90.0) * 12.0)), first, etopo5_rows - 1);
  regional::ElevationRaster raster;
  raster.south_deg = -90.0 + first * etopo5_step_deg;
  raster.west_deg = 0.0;
  raster.step_deg = etopo5_step_deg;
  raster.rows = last - first + 1;
  raster.columns = etopo5_columns + 1;
  raster.source = "ETOPO5 (" + path + ")";
  raster.heights.resize(static_cast<size_t>(raster.rows) * raster.columns);
  std::vector<unsigned char> row(etopo5_columns * 4);
  in.seekg(static_cast<std::streamoff>(etopo5_header_bytes + std::uint64_t(first) * etopo5_columns * 4));
  for (int r = 0; r < raster.rows; ++r) {
    if (!in.read(reinterpret_cast<char*>(row.data()), static_cast<std::streamsize>(row.size())))
      throw core::InputError(field, path, allowed, "could not be read to its end");
    float* out = raster.heights.data() + static_cast<size_t>(r) * raster.columns;
    for (int c = 0; c < etopo5_columns; ++c) {
      const float h = big_endian_float(&row[4 * c]);
      // Everest is 8849 m, the Challenger Deep -10935 m: anything else is not elevation.
      if (!std::isfinite(h) || h < -11000.0f || h > 9000.0f)
        throw core::InputError(field, path, allowed, "holds " + std::to_string(h) + " m, not an elevation");
      out[c] = h;
    }
    out[etopo5_columns] = out[0];
  }
  return raster;
}

namespace {

// The grid does not depend on the camera's height: the tangent plane's east and north
// coordinates of a point are the same at any height above its origin (regional::TangentPlane),
// so it is made at height 0 and kept while the camera climbs or descends.
std::shared_ptr<const regional::TerrainGrid> make_terrain(const std::string& setting, double latitude_deg,
                                                          double longitude_deg, std::string* warning,
                                                          const std::string& field, const GroundOptions& options) {
  std::string path = setting;
  if (setting == "etopo5") {
    path = etopo5_default_path;
    std::error_code error;
    if (!std::filesystem::exists(path, error)) {
      if (warning)
        *warning = "no elevation data at " + path + " (install ferret-datasets): the ground is the bare sphere";
      return nullptr;
    }
  }
  // The rows the square reaches, with a margin: its corner lies extent * sqrt(2) away.
  const double reach_deg = terrain_grid_extent_m * 1.5 / 111000.0;
  const regional::ElevationRaster raster = read_etopo5(path, latitude_deg - reach_deg, latitude_deg + reach_deg, field);
  std::string land_warning;
  std::shared_ptr<const regional::LandCoverGrid> land_cover =
      load_land_cover(options.land_cover, latitude_deg, longitude_deg, 0.0, &land_warning, options.land_field);
  const double reach_lon = reach_deg / std::max(std::cos(latitude_deg * M_PI / 180), 0.1);
  const regional::TerrainDetail detail =
      regional::terrain_detail(raster, latitude_deg - reach_deg, latitude_deg + reach_deg, longitude_deg - reach_lon,
                               longitude_deg + reach_lon, options.detail);
  auto made = std::make_shared<regional::TerrainGrid>(regional::terrain_grid(
      latitude_deg, longitude_deg, 0.0, render::osculating_earth_radius(latitude_deg), raster,
      regional::substitute_hills(), terrain_grid_size, terrain_grid_extent_m, land_cover.get(), detail));
  made->land = land_cover;
  if (warning) *warning = land_warning;
  return made;
}

// The camera stands where the four middle texels meet; below their mean it looks out from
// underground (ETOPO5 fills valleys: Bern's old town at 540 m lies under 700 m of it).
std::string underground_warning(const regional::TerrainGrid& grid, double height_m) {
  const std::size_t n = grid.size, middle = n / 2;
  const double ground = (grid.altitudes[(middle - 1) * n + middle - 1] + grid.altitudes[(middle - 1) * n + middle] +
                         grid.altitudes[middle * n + middle - 1] + grid.altitudes[middle * n + middle]) /
                        4;
  if (ground <= height_m) return "";
  return "the camera at " + std::to_string(int(std::lround(height_m))) + " m is below the terrain there (" +
         std::to_string(int(std::lround(ground))) + " m, " + grid.raster_source +
         " smooths valleys): raise its height or use --terrain flat";
}

}  // namespace

std::shared_ptr<const regional::TerrainGrid> load_terrain(const std::string& setting, double latitude_deg,
                                                          double longitude_deg, double height_m, std::string* warning,
                                                          const std::string& field, const GroundOptions& options) {
  if (setting == "flat") return nullptr;
  // The last ground made is kept for the process: the viewer's sources and the tests ask for
  // the same place again and again (about 1.4 s each on two cores), at any height.
  static std::mutex mutex;
  static std::string last_key, last_warning;
  static std::shared_ptr<const regional::TerrainGrid> last;
  std::ostringstream key;
  key.precision(17);
  key << setting << '\n'
      << latitude_deg << ' ' << longitude_deg << '\n'
      << field << '\n'
      << options.land_cover << '\n'
      << options.land_field << '\n'
      << options.detail;
  const std::lock_guard<std::mutex> lock(mutex);
  if (!last || key.str() != last_key) {
    std::string made_warning;
    last = make_terrain(setting, latitude_deg, longitude_deg, &made_warning, field, options);
    last_key = key.str();
    last_warning = made_warning;
  }
  if (warning) {
    *warning = last_warning;
    if (last) {
      const std::string below = underground_warning(*last, height_m);
      if (!below.empty()) *warning = (warning->empty() ? "" : *warning + "; ") + below;
    }
  }
  return last;
}

}  // namespace nephele::io
