#include "io/surface_files.hpp"

#include <filesystem>
#include <map>
#include <mutex>
#include <stdexcept>
#include <utility>

#include "core/error.hpp"
#include "core/parallel_rows.hpp"
#include "io/elevation_files.hpp"
#include "files/image_files.hpp"

namespace nephele::io {

namespace {

// Land fraction of each half-degree cell from 6 x 6 bilinear samples of the elevation (the
// 5-minute lattice's spacing): land where above sea level.
cover::SurfaceMask etopo5_mask(const std::string& path, const std::string& field) {
  const std::shared_ptr<const regional::ElevationRaster> held = whole_etopo5(path, field);
  const regional::ElevationRaster& raster = *held;
  cover::SurfaceMask mask{cover::surface_bias_columns, cover::surface_bias_rows, {}, path};
  mask.land.resize(static_cast<size_t>(mask.columns) * mask.rows);
  const int samples = 6;
  // 9.3 million bilinear samples on a grid of 6 columns and rows per cell (each longitude's lattice
  // cell found once): rows shared by the hardware threads (each writes its own).
  std::vector<double> longitudes;
  for (int i = 0; i < mask.columns; ++i)
    for (int a = 0; a < samples; ++a) longitudes.push_back(-180.0 + (i + (a + 0.5) / samples) * 360.0 / mask.columns);
  const regional::ElevationRaster::Columns columns = raster.columns_at(longitudes);
  core::parallel_rows(mask.rows, [&](int begin, int end) {
    std::vector<int> land(static_cast<size_t>(mask.columns));
    std::vector<double> heights(longitudes.size());
    for (int j = begin; j < end; ++j) {
      std::fill(land.begin(), land.end(), 0);
      for (int b = 0; b < samples; ++b) {
        raster.row_at(90.0 - (j + (b + 0.5) / samples) * 180.0 / mask.rows, columns, 0.0, heights.data());
        for (size_t k = 0; k < heights.size(); ++k) land[k / samples] += heights[k] > 0.0;
      }
      for (int i = 0; i < mask.columns; ++i)
        mask.land[static_cast<size_t>(j) * mask.columns + i] =
            static_cast<float>(land[size_t(i)]) / (samples * samples);
    }
  });
  return mask;
}

cover::SurfaceMask image_mask(const std::string& path, const std::string& field) {
  std::error_code error;
  if (!std::filesystem::exists(path, error))
    throw core::InputError(field, path, "an existing ETOPO5 netCDF or image file, or none or etopo5", "no such file");
  core::ImageData image;
  try {
    image = files::read_image(path);  // refuses FIFOs, devices and headers beyond the memory budget
  } catch (const std::exception& e) {
    throw core::InputError(field, path, "an image OpenImageIO reads (EXR, PNG, TIFF, ...), or an ETOPO5 netCDF",
                           e.what());
  }
  cover::SurfaceMask mask{image.width, image.height, {}, path};
  mask.land.resize(static_cast<size_t>(image.width) * image.height);
  for (size_t k = 0; k < mask.land.size(); ++k) {
    const float value = image.pixels[k * image.channels];
    if (!(value >= 0.0f && value <= 1.0f))
      throw core::InputError(field, path, "land fractions in [0, 1] in the first channel",
                             "pixel " + std::to_string(k % image.width) + ", " + std::to_string(k / image.width) +
                                 " holds " + std::to_string(value));
    mask.land[k] = value;
  }
  return cover::resample_surface(mask, cover::surface_bias_columns, cover::surface_bias_rows);
}

}  // namespace

std::shared_ptr<const cover::SurfaceMask> surface_from_option(const std::string& value, std::string* warning,
                                                              const std::string& field) {
  if (value == "none") return nullptr;
  std::error_code error;
  if (value == "etopo5" && warning && !std::filesystem::is_regular_file(etopo5_default_path, error)) {
    *warning = field + ": " + etopo5_default_path +
               " not found (Debian's ferret-datasets): the cover has no land/ocean mask, as with none";
    return nullptr;
  }
  static std::mutex guard;
  static std::map<std::string, std::shared_ptr<const cover::SurfaceMask>> loaded;
  const std::lock_guard<std::mutex> lock(guard);
  if (const auto found = loaded.find(value); found != loaded.end()) return found->second;
  const std::string path = value == "etopo5" ? std::string(etopo5_default_path) : value;
  const std::string extension = std::filesystem::path(path).extension().string();
  cover::SurfaceMask mask =
      extension == ".cdf" || extension == ".nc" ? etopo5_mask(path, field) : image_mask(path, field);
  mask.source = value;  // "etopo5" for the packaged file, the path otherwise (cover.json's record)
  const auto shared = std::make_shared<const cover::SurfaceMask>(std::move(mask));
  loaded.emplace(value, shared);
  return shared;
}

std::shared_ptr<const cover::SurfaceMask> scene_surface(const regional::Scene& scene, std::string* warning,
                                                        const std::string& field) {
  return scene.weather.empty() ? surface_from_option(scene.cover_surface, warning, field) : nullptr;
}

}  // namespace nephele::io
