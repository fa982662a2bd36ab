#include "io/planet_textures.hpp"

#include <cmath>
#include <algorithm>
#include <array>
#include <future>
#include <system_error>
#include <utility>

#include "core/error.hpp"
#include "core/parallel_rows.hpp"
#include "io/elevation_files.hpp"
#include "io/export_presets.hpp"
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

// The fraction of open water in each pixel of a 1080 x 540 equirect (a third of a degree: the glint
// is a lobe hundreds of km wide), from the 16 ETOPO5 samples (a twelfth of a degree apart)
// nearest the pixel's points on a 4 x 4 grid:
// below sea level is water. Land below sea level (the Caspian and Dead Sea depressions' shores)
// counts as water: a few hundred pixels.
core::ImageData etopo5_water(const regional::ElevationRaster& raster) {
  const int width = 1080, height = 540;
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

// The ground's slopes (east, north: metres of rise per metre) on a 2160 x 1080 equirect (a sixth of
// a degree, 18.5 km at the equator: half ETOPO5's resolution, finer than the day map's 20 km; at
// ETOPO5's own the slopes came out only 1.3-1.4 times steeper, for four times the texels), by
// central differences of ETOPO5's heights at the pixels' centres (bilinear), the sea floor taken
// as sea level: the sea is flat. East steps shrink towards the poles with cos(lat), which is held
// at 0.05 or more (the last 3 degrees) so that the differences stay finite.
core::ImageData etopo5_relief(const regional::ElevationRaster& raster) {
  const int width = 2160, height = 1080;
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
  core::ImageData relief{width, height, 2, std::vector<float>(std::size_t(width) * height * 2, 0.0f)};
  core::parallel_rows(height, [&](int begin, int end) {
    for (int j = begin; j < end; ++j) {
      const double lat = (90.0 - (j + 0.5) * 180.0 / height) * M_PI / 180.0;
      const double east_step = step * std::max(std::cos(lat), 0.05);
      const int north = std::max(j - 1, 0), south = std::min(j + 1, height - 1);
      const float* row = &ground[std::size_t(j) * width];
      for (int i = 0; i < width; ++i) {
        const double east = row[(i + 1) % width] - row[(i + width - 1) % width];
        const double northward = ground[std::size_t(north) * width + i] - ground[std::size_t(south) * width + i];
        float* out = &relief.pixels[(std::size_t(j) * width + i) * 2];
        out[0] = float(east / (2.0 * east_step));
        out[1] = float(northward / ((south - north) * step));
      }
    }
  });
  return relief;
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

PlanetTextures read_planet_textures(const std::string& day, const std::string& night, const std::string& option) {
  PlanetTextures out;
  out.water_source = "none";
  out.relief_source = "none";
  std::error_code error;
  // The night map is decoded on a thread of its own while the day map and ETOPO5 are read.
  const std::string night_file = !night.empty() ? night
                                 : day.empty() && std::filesystem::is_regular_file(default_night_texture, error)
                                     ? std::string(default_night_texture)
                                     : std::string();
  std::future<decltype(out.images.night)> night_image;
  if (!night_file.empty())
    night_image =
        std::async(std::launch::async, [&night_file] { return read_equirect(night_file, "--night-texture"); });
  if (!day.empty()) {
    out.images.day = read_equirect(day, option);
    out.day_source = day;
    if (out.images.day.width != 2 * out.images.day.height)
      out.warnings.push_back(option + ": '" + day + "' is " + std::to_string(out.images.day.width) + " x " +
                             std::to_string(out.images.day.height) + ", not 2:1; it is stretched over the sphere");
  } else if (std::filesystem::is_regular_file(default_earth_texture, error)) {
    out.images.day = read_equirect(default_earth_texture, option);
    out.day_source = default_earth_texture;
    if (std::filesystem::is_regular_file(etopo5_default_path, error)) {
      const std::shared_ptr<const regional::ElevationRaster> raster = whole_etopo5(etopo5_default_path, "ETOPO5");
      out.images.water = etopo5_water(*raster);
      out.water_source = etopo5_default_path;
      out.images.relief = etopo5_relief(*raster);
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
    out.night_source = night_file;
  } else {
    out.night_source = "none";
  }
  return out;
}

render::CoverCube read_cover_cube(const std::filesystem::path& directory) {
  CoverFaces faces = read_cover_faces(directory);
  return {faces.size, std::move(faces.texels), std::move(faces.optical_thickness), std::move(faces.cloud_top)};
}

}  // namespace nephele::io
