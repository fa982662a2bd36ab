#include "io/planet_textures.hpp"

#include <cmath>
#include <algorithm>
#include <array>
#include <cstdio>
#include <future>
#include <system_error>
#include <utility>

#include "core/error.hpp"
#include "core/parallel_rows.hpp"
#include "io/coastline_files.hpp"
#include "io/elevation_files.hpp"
#include "render/orbit_tiles.hpp"
#include "io/export_presets.hpp"
#include "files/float_cache.hpp"
#include "files/image_files.hpp"

namespace nephele::io {
namespace {

float srgb_to_linear(float v) { return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f); }

// read() of the map at `path`, its failures as bad input of `option`.
template <class Read>
auto read_map(const std::string& path, const std::string& option, Read&& read) {
  try {
    return read();
  } catch (const std::exception& e) {
    throw core::InputError(option, path, "an equirect image file OpenImageIO reads (JPEG, PNG, EXR, ...)",
                           std::string("could not be read: ") + e.what());
  }
}

void check_map_width(const std::string& path, const std::string& option, int width) {
  if (width < 2) throw core::InputError(option, path, "an image of at least 2 x 1 pixels", "is too small");
}

core::ImageData read_equirect(const std::string& path, const std::string& option) {
  files::ImageHeader header;
  core::ImageData image = read_map(path, option, [&] { return files::read_image(path, 0, &header); });
  check_map_width(path, option, image.width);
  // Integer formats hold display-encoded (sRGB) colour; float formats hold linear values. An 8-bit
  // image has 256 values: each decoded once (the decoder's float for code n, and its linear value,
  // kept under n) instead of a pow per sample; other values are decoded as they come.
  if (!header.float_samples) {
    std::array<float, 256> code_value, linear;
    std::array<bool, 256> known{};
    for (size_t k = 0; k < image.pixels.size(); ++k) {
      if (k % size_t(image.channels) >= 3) continue;
      const float v = image.pixels[k];
      const long n = std::lround(v * 255.0f);
      if (n < 0 || n > 255) {
        image.pixels[k] = srgb_to_linear(v);
      } else if (known[size_t(n)] && code_value[size_t(n)] == v) {
        image.pixels[k] = linear[size_t(n)];
      } else {
        image.pixels[k] = srgb_to_linear(v);
        if (!known[size_t(n)]) {
          known[size_t(n)] = true;
          code_value[size_t(n)] = v;
          linear[size_t(n)] = image.pixels[k];
        }
      }
    }
  }
  return image;
}

constexpr int etopo5_water_width = 1080;   // etopo5_water's map, 2:1
constexpr int etopo5_relief_width = 2160;  // etopo5_relief's map, 2:1

// The fraction of open water in each pixel of a 1080 x 540 equirect (a third of a degree: the glint
// is a lobe hundreds of km wide), from the 16 ETOPO5 samples (a twelfth of a degree apart)
// nearest the pixel's points on a 4 x 4 grid:
// below sea level is water. Land below sea level (the Caspian and Dead Sea depressions' shores)
// counts as water: a few hundred pixels.
core::ImageData etopo5_water(const regional::ElevationRaster& raster) {
  const int width = etopo5_water_width, height = etopo5_water_width / 2;
  core::ImageData water{width, height, 1, std::vector<float>(std::size_t(width) * height, 0.0f)};
  const double per_degree = 1.0 / raster.step_deg;
  const int wrap = static_cast<int>(std::lround(360.0 * per_degree));
  // The grid's rows depend on the pixel's row alone and its columns on its column alone: found
  // once for each, not for each of the 16 points of every pixel.
  std::vector<int> rows(std::size_t(height) * 4), columns(std::size_t(width) * 4);
  for (int j = 0; j < height; ++j)
    for (int k = 0; k < 4; ++k) {
      const double lat = 90.0 - (j + 0.125 + 0.25 * k) * 180.0 / height;
      rows[std::size_t(j) * 4 + k] =
          std::clamp(static_cast<int>(std::lround((lat - raster.south_deg) * per_degree)), 0, raster.rows - 1);
    }
  for (int i = 0; i < width; ++i)
    for (int k = 0; k < 4; ++k) {
      const double lon = -180.0 + (i + 0.125 + 0.25 * k) * 360.0 / width;
      const int column = static_cast<int>(std::lround((lon - raster.west_deg) * per_degree)) % wrap;
      columns[std::size_t(i) * 4 + k] = (column + wrap) % wrap;
    }
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      int wet = 0;
      for (int k = 0; k < 16; ++k) {
        const int row = rows[std::size_t(j) * 4 + k / 4], column = columns[std::size_t(i) * 4 + k % 4];
        if (raster.heights[std::size_t(row) * raster.columns + column] < 0.0f) ++wet;
      }
      water.pixels[std::size_t(j) * width + i] = float(wet) / 16.0f;
    }
  return water;
}

// The default day map made ready for the sea's own colour (render::PlanetImages::sea_colour): its
// alpha is the share of a texel that is not ice (white: min(R, G, B) from 0.25 to 0.45, linear, and
// unsaturated: (max - min) / max below 0.2 to 0.35; the map's ice is pure white, its bright
// deserts' saturation 0.48 and more), and the colours of its open water (blue above 1.2 red: deep
// blue and the shallows' turquoise; no ice), which the shorelines replace by the sea's, are filled
// from the nearest land and ice, so that no sea colour bleeds onto the land beside a sharp coast.
// The fill pulls the mean of the kept texels down a pyramid of halvings: each water texel takes the
// mean of its smallest enclosing block that has one.
core::ImageData sea_free_day_map(const core::ImageData& day) {
  const int width = day.width, height = day.height, channels = day.channels;
  core::ImageData out{width, height, 4, std::vector<float>(std::size_t(width) * height * 4)};
  struct Level {
    int width, height;
    std::vector<float> sums;  // r, g, b, weight
  };
  std::vector<Level> levels{{width, height, std::vector<float>(std::size_t(width) * height * 4)}};
  for (std::size_t k = 0; k < std::size_t(width) * height; ++k) {
    const float* in = &day.pixels[k * std::size_t(channels)];
    const float r = in[0], g = channels > 1 ? in[1] : r, b = channels > 2 ? in[2] : r;
    const float lowest = std::min({r, g, b});
    const float saturation = 1.0f - lowest / std::max({r, g, b, 1.0e-6f});
    const float ice = glm::smoothstep(0.25f, 0.45f, lowest) * (1.0f - glm::smoothstep(0.2f, 0.35f, saturation));
    const bool open_water = b > 1.2f * r && ice < 0.5f;
    float* o = &out.pixels[k * 4];
    o[0] = r, o[1] = g, o[2] = b, o[3] = 1.0f - ice;
    float* sum = &levels[0].sums[k * 4];
    const float w = open_water ? 0.0f : 1.0f;
    sum[0] = w * r, sum[1] = w * g, sum[2] = w * b, sum[3] = w;
  }
  while (levels.back().width > 1 || levels.back().height > 1) {
    const Level& fine = levels.back();
    Level coarse{std::max(1, (fine.width + 1) / 2), std::max(1, (fine.height + 1) / 2), {}};
    coarse.sums.assign(std::size_t(coarse.width) * coarse.height * 4, 0.0f);
    for (int j = 0; j < fine.height; ++j)
      for (int i = 0; i < fine.width; ++i)
        for (int c = 0; c < 4; ++c)
          coarse.sums[(std::size_t(j / 2) * coarse.width + i / 2) * 4 + c] +=
              fine.sums[(std::size_t(j) * fine.width + i) * 4 + c];
    levels.push_back(std::move(coarse));
  }
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      if (levels[0].sums[(std::size_t(j) * width + i) * 4 + 3] > 0.0f) continue;
      for (std::size_t l = 1; l < levels.size(); ++l) {
        const Level& level = levels[l];
        const float* sum = &level.sums[(std::size_t(j >> l) * level.width + (i >> l)) * 4];
        if (sum[3] <= 0.0f) continue;
        float* o = &out.pixels[(std::size_t(j) * width + i) * 4];
        for (int c = 0; c < 3; ++c) o[c] = sum[c] / sum[3];
        break;
      }
    }
  return out;
}

// The ground's slopes (east, north: metres of rise per metre) on a 2160 x 1080 equirect (a sixth of
// a degree, 18.5 km at the equator: half ETOPO5's resolution, finer than the day map's 20 km; at
// ETOPO5's own the slopes came out only 1.3-1.4 times steeper, for four times the texels), by
// central differences of ETOPO5's heights at the pixels' centres (bilinear), the sea floor taken
// as sea level: the sea is flat. East steps shrink towards the poles with cos(lat), which is held
// at 0.05 or more (the last 3 degrees) so that the differences stay finite. The third channel is
// the slopes' root mean square over the 3 x 3 texels around: how rough the land is there, which
// sets the steepness of the relief the renderer draws below the texels (land_mosaic.glsl).
core::ImageData etopo5_relief(const regional::ElevationRaster& raster) {
  const int width = etopo5_relief_width, height = etopo5_relief_width / 2;
  std::vector<float> ground(std::size_t(width) * height);
  std::vector<double> longitudes;
  for (int i = 0; i < width; ++i) longitudes.push_back(-180.0 + (i + 0.5) * 360.0 / width);
  const regional::ElevationRaster::Columns columns = raster.columns_at(longitudes);
  core::parallel_rows(height, [&](int begin, int end) {
    std::vector<double> heights(static_cast<std::size_t>(width));
    for (int j = begin; j < end; ++j) {
      raster.row_at(90.0 - (j + 0.5) * 180.0 / height, columns, 0.0, heights.data());
      for (int i = 0; i < width; ++i)
        ground[std::size_t(j) * width + i] = float(std::max(heights[std::size_t(i)], 0.0));
    }
  });
  // Metres between rows (and columns at the equator) on the Earth's mean radius, the renderer's.
  const double step = M_PI / height * render::OrbitSettings{}.planet_radius_m;
  core::ImageData relief{width, height, 3, std::vector<float>(std::size_t(width) * height * 3, 0.0f)};
  core::parallel_rows(height, [&](int begin, int end) {
    for (int j = begin; j < end; ++j) {
      const double lat = (90.0 - (j + 0.5) * 180.0 / height) * M_PI / 180.0;
      const double east_step = step * std::max(std::cos(lat), 0.05);
      const int north = std::max(j - 1, 0), south = std::min(j + 1, height - 1);
      const float* row = &ground[std::size_t(j) * width];
      for (int i = 0; i < width; ++i) {
        const double east = row[(i + 1) % width] - row[(i + width - 1) % width];
        const double northward = ground[std::size_t(north) * width + i] - ground[std::size_t(south) * width + i];
        float* out = &relief.pixels[(std::size_t(j) * width + i) * 3];
        out[0] = float(east / (2.0 * east_step));
        out[1] = float(northward / ((south - north) * step));
      }
    }
  });
  // The squared slopes summed over each texel's row of three (wrapping in longitude), then over
  // three rows (two at the poles' edge rows).
  std::vector<float> across(std::size_t(width) * height);
  core::parallel_rows(height, [&](int begin, int end) {
    for (int j = begin; j < end; ++j) {
      const float* row = &relief.pixels[std::size_t(j) * width * 3];
      auto square = [&](int i) { return row[3 * i] * row[3 * i] + row[3 * i + 1] * row[3 * i + 1]; };
      for (int i = 0; i < width; ++i)
        across[std::size_t(j) * width + i] = square((i + width - 1) % width) + square(i) + square((i + 1) % width);
    }
  });
  core::parallel_rows(height, [&](int begin, int end) {
    for (int j = begin; j < end; ++j) {
      const int first = std::max(j - 1, 0), last = std::min(j + 1, height - 1);
      for (int i = 0; i < width; ++i) {
        float sum = 0.0f;
        for (int row = first; row <= last; ++row) sum += across[std::size_t(row) * width + i];
        relief.pixels[(std::size_t(j) * width + i) * 3 + 2] = std::sqrt(sum / float(3 * (last - first + 1)));
      }
    }
  });
  return relief;
}

}  // namespace

namespace {

// What identifies a source file's content for the cache: its path, size and modification time
// (nanoseconds); empty where it cannot be read, and then nothing is cached.
std::string file_identity(const std::string& path) {
  std::error_code error;
  const auto size = std::filesystem::file_size(path, error);
  if (error) return {};
  const auto time = std::filesystem::last_write_time(path, error);
  if (error) return {};
  return path + " " + std::to_string(size) + " " + std::to_string(time.time_since_epoch().count());
}

// The map `what` of `sources` (file identities; none empty): from the cache in `directory` where
// it holds it, else made by `make` and stored there. Without a directory, a program fingerprint or
// a source's identity it is made alone. The map's size is an entry of its own beside its values
// (key + " shape"), so that a map from the cache needs no header of its source read: that read
// would load the image codecs (files/image_codecs.hpp), and the context's driver, loading
// meanwhile, waits for them. `from_cache` (if given) gets `what`'s first word where the map came
// from the cache.
template <class Make>
core::ImageData cached_map(const std::filesystem::path& directory, const std::string& what,
                           const std::vector<std::string>& sources, Make&& make,
                           std::vector<std::string>* from_cache = nullptr) {
  const std::string program = files::program_fingerprint();
  bool cacheable = !directory.empty() && !program.empty();
  std::string key = "planet_map " + what + " 2";
  for (const std::string& source : sources) {
    cacheable = cacheable && !source.empty();
    key += " [" + source + "]";
  }
  if (!cacheable) return make();
  key += " program " + program;
  const std::string shape_key = key + " shape";
  const files::FloatCache cache(directory);
  if (const auto shape = cache.load(shape_key, 3)) {
    const float width = (*shape)[0], height = (*shape)[1], channels = (*shape)[2];
    if (width >= 1 && height >= 1 && channels >= 1 && channels <= 4 && width * height <= 1.0e9f)
      if (auto values = cache.load(key, std::size_t(width) * std::size_t(height) * std::size_t(channels))) {
        if (from_cache != nullptr) from_cache->push_back(what.substr(0, what.find(' ')));
        return core::ImageData{int(width), int(height), int(channels), std::move(*values)};
      }
  }
  core::ImageData image = make();
  if (image.width > 0 && image.height > 0 && image.channels > 0 && cache.store(key, image.pixels))
    cache.store(shape_key, {float(image.width), float(image.height), float(image.channels)});
  return image;
}

// The decoded map at `path` (read_equirect), through the cache.
core::ImageData cached_equirect(const std::filesystem::path& directory, const std::string& path,
                                const std::string& option, std::vector<std::string>* from_cache) {
  return cached_map(
      directory, "decoded", {file_identity(path)}, [&] { return read_equirect(path, option); }, from_cache);
}

}  // namespace

void check_planet_maps(const std::string& day, const std::string& night, const std::string& option) {
  for (const auto& [path, field] : {std::pair{day, option}, std::pair{night, std::string("--night-texture")}}) {
    if (path.empty()) continue;
    const files::ImageHeader header = read_map(path, field, [&] {
      files::ImageHeader h = files::read_image_header(path);
      files::check_image_budget(path, h);
      return h;
    });
    check_map_width(path, field, header.width);
  }
}

PlanetTextures read_planet_textures(const std::string& day, const std::string& night, const std::string& option,
                                    const std::filesystem::path& cache_directory) {
  PlanetTextures out;
  out.water_source = "none";
  out.relief_source = "none";
  std::error_code error;
  // The night map is decoded on a thread of its own while the day map and ETOPO5 are read.
  const std::string night_file = !night.empty() ? night
                                 : day.empty() && std::filesystem::is_regular_file(default_night_texture, error)
                                     ? std::string(default_night_texture)
                                     : std::string();
  std::vector<std::string> night_cached;  // the night map's thread's own list
  std::future<decltype(out.images.night)> night_image;
  if (!night_file.empty())
    night_image = std::async(std::launch::async, [&night_file, &cache_directory, &night_cached] {
      return cached_equirect(cache_directory, night_file, "--night-texture", &night_cached);
    });
  if (!day.empty()) {
    out.images.day = cached_equirect(cache_directory, day, option, &out.from_cache);
    out.day_source = day;
    if (out.images.day.width != 2 * out.images.day.height)
      out.warnings.push_back(option + ": '" + day + "' is " + std::to_string(out.images.day.width) + " x " +
                             std::to_string(out.images.day.height) + ", not 2:1; it is stretched over the sphere");
  } else if (std::filesystem::is_regular_file(default_earth_texture, error)) {
    out.images.day = cached_map(
        cache_directory, "sea_free_day", {file_identity(default_earth_texture)},
        [&] { return sea_free_day_map(read_equirect(default_earth_texture, option)); }, &out.from_cache);
    out.images.sea_colour = true;
    out.day_source = default_earth_texture;
    if (std::filesystem::is_regular_file(etopo5_default_path, error)) {
      // ETOPO5 is read only where a map derived from it is not in the cache.
      std::shared_ptr<const regional::ElevationRaster> raster;
      const auto etopo5 = [&]() -> const regional::ElevationRaster& {
        if (!raster) raster = whole_etopo5(etopo5_default_path, "ETOPO5");
        return *raster;
      };
      const std::string identity = file_identity(etopo5_default_path);
      out.images.water = cached_map(
          cache_directory, "etopo5_water", {identity}, [&] { return etopo5_water(etopo5()); }, &out.from_cache);
      out.water_source = etopo5_default_path;
      out.images.relief = cached_map(
          cache_directory, "etopo5_relief", {identity}, [&] { return etopo5_relief(etopo5()); }, &out.from_cache);
      out.relief_source = etopo5_default_path;
    } else {
      out.warnings.push_back(std::string(etopo5_default_path) +
                             " is missing (Debian package ferret-datasets): no water mask and no relief, so no sun "
                             "glint and flat ground");
    }
  } else {
    out.images = render::procedural_planet();
    out.day_source = "procedural";
    out.water_source = "procedural";
    out.warnings.push_back(std::string(default_earth_texture) +
                           " is missing (Debian package xplanet-images): a procedural ocean and land map stands in");
  }
  if (night_image.valid()) {
    out.images.night = night_image.get();
    for (const std::string& map : night_cached) out.from_cache.push_back("night_" + map);
    out.night_source = night_file;
  } else {
    out.night_source = "none";
  }
  return out;
}

namespace {

// A window's edges with texels of `texel_deg` (degrees north to south, and as long east to west
// at its middle latitude) or coarser, at most 2048 along either side (finer costs a second and
// more in the upload of its mips, for coasts a little sharper than a pixel).
GeoWindow window_of(double south, double north, double west, double east, double texel_deg) {
  const double mid = std::cos(0.5 * (south + north) * M_PI / 180.0);
  const double texel = std::max({texel_deg, (north - south) / 2048.0, (east - west) * mid / 2048.0});
  return GeoWindow{south,
                   north,
                   west,
                   east,
                   std::clamp(int(std::ceil((east - west) * mid / texel)), 1, 2048),
                   std::clamp(int(std::ceil((north - south) / texel)), 1, 2048)};
}

// How a render's sidecar names a coast window (appended to the water map's source).
std::string coast_source(const GeoWindow& window) {
  char text[200];
  std::snprintf(text, sizeof text, "%s within %.2f to %.2f N, %.2f to %.2f E (%d x %d)", gshhg_shorelines_default_path,
                window.south_deg, window.north_deg, window.west_deg, window.east_deg, window.width, window.height);
  return text;
}

}  // namespace

namespace {
double nearest_pixel_m(const render::OrbitCamera& camera) {
  return camera.altitude_m * 2.0 * std::tan(camera.fov_deg * M_PI / 360.0) / camera.width;
}
}  // namespace

bool coast_pixels_finer(const render::OrbitCamera& camera, double planet_radius_m, int water_width, double share) {
  return nearest_pixel_m(camera) <= share * 2.0 * M_PI * planet_radius_m / std::max(water_width, 1);
}

std::optional<GeoWindow> view_coast_window(const render::OrbitCamera& camera, double planet_radius_m, int water_width) {
  // The ground's finest pixel, straight below the camera, against the water map's texel (37 km):
  // from below a quarter of it (about 9 km: 400 and 2000 km, not 12000, where the raster of
  // nearly a hemisphere would add 0.6 s for coasts a little sharper than the map's).
  if (!coast_pixels_finer(camera, planet_radius_m, water_width, 0.25)) return std::nullopt;
  // The window: the latitudes and longitudes of the ground points a grid of the frame's rays
  // meets; a ray that misses the planet adds the ground below its nearest approach, which lies
  // beyond the horizon in its direction.
  const render::OrbitFrame frame = render::orbit_frame(camera, planet_radius_m);
  const render::TileView view{
      frame.position, frame.forward, frame.right, frame.up, std::tan(camera.fov_deg * M_PI / 360.0),
      camera.width,   camera.height};
  double south = 90, north = -90, west = 1e9, east = -1e9;
  constexpr int grid = 32;
  for (int b = 0; b <= grid; ++b)
    for (int a = 0; a <= grid; ++a) {
      const glm::dvec3 d = render::view_ray(view, double(a) / grid * camera.width, double(b) / grid * camera.height);
      const double entry = render::sphere_entry(frame.position, d, planet_radius_m);
      const double t = entry >= 0.0 ? entry : -glm::dot(frame.position, d);  // a miss: its nearest approach
      if (t < 0.0) continue;                                                 // behind the camera
      const glm::dvec3 ground = glm::normalize(frame.position + t * d);
      const double lat = std::asin(std::clamp(ground.z, -1.0, 1.0)) * 180.0 / M_PI;
      double lon = std::atan2(ground.y, ground.x) * 180.0 / M_PI;
      lon = camera.longitude_deg + std::remainder(lon - camera.longitude_deg, 360.0);  // about the camera's
      south = std::min(south, lat), north = std::max(north, lat);
      west = std::min(west, lon), east = std::max(east, lon);
    }
  if (south >= north || west >= east) return std::nullopt;
  // A margin of a degree, and a pole in view takes every longitude.
  south = std::max(south - 1.0, -90.0), north = std::min(north + 1.0, 90.0);
  west -= 1.0, east += 1.0;
  if (north >= 89.0 || south <= -89.0 || east - west >= 360.0) west = camera.longitude_deg - 180.0, east = west + 360.0;
  // Texels about as fine as the nearest pixels.
  return window_of(south, north, west, east, nearest_pixel_m(camera) / planet_radius_m * 180.0 / M_PI);
}

GeoWindow widened_coast_window(const GeoWindow& window, double share) {
  const double dlat = share * (window.north_deg - window.south_deg);
  const double dlon = share * (window.east_deg - window.west_deg);
  double west = window.west_deg, east = window.east_deg;
  if (east - west + 2 * dlon < 360.0) west -= dlon, east += dlon;
  return window_of(std::max(window.south_deg - dlat, -90.0), std::min(window.north_deg + dlat, 90.0), west, east,
                   (window.north_deg - window.south_deg) / window.height);
}

std::optional<std::string> missing_shorelines_warning() {
  std::error_code error;
  if (std::filesystem::is_regular_file(gshhg_shorelines_default_path, error)) return std::nullopt;
  return std::string(gshhg_shorelines_default_path) +
         " is missing (Debian package gmt-gshhg-full): coasts and lakes as sharp as ETOPO5's 18 km water map";
}

void add_view_coast(PlanetTextures& textures, const render::OrbitCamera& camera, double planet_radius_m,
                    const std::filesystem::path& cache_directory) {
  if (!textures.images.sea_colour) return;
  const std::optional<GeoWindow> window = view_coast_window(camera, planet_radius_m, textures.images.water.width);
  if (!window) return;
  if (const std::optional<std::string> warning = missing_shorelines_warning()) {
    textures.warnings.push_back(*warning);
    return;
  }
  // The window's raster through the cache: a view seen again (the same window) reads it.
  textures.images.coast = cached_map(
      cache_directory, "gshhg_water " + coast_source(*window), {file_identity(gshhg_shorelines_default_path)},
      [&] { return read_gshhg_water(gshhg_shorelines_default_path, *window); }, &textures.from_cache);
  textures.images.coast_south_deg = window->south_deg, textures.images.coast_north_deg = window->north_deg;
  textures.images.coast_west_deg = window->west_deg, textures.images.coast_east_deg = window->east_deg;
  textures.water_source += " and " + coast_source(*window);
}

render::CoverCube read_cover_cube(const std::filesystem::path& directory) {
  CoverFaces faces = read_cover_faces(directory);
  return {faces.size, std::move(faces.texels), std::move(faces.optical_thickness), std::move(faces.cloud_top)};
}

}  // namespace nephele::io
