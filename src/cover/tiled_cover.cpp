#include "cover/tiled_cover.hpp"

#include <algorithm>
#include <stdexcept>

namespace nephele::cover {

namespace {

// A tile's values (its densities or cloud tops) must be one per owned texel.
void check_tile_values(int index, const std::vector<float>& values, const CubeRegion& owned, const char* what) {
  if (values.size() != static_cast<std::size_t>(owned.owned_texels()))
    throw std::invalid_argument("TiledCoverage: tile " + std::to_string(index) + " has " +
                                std::to_string(values.size()) + " " + what + ", not " +
                                std::to_string(owned.owned_texels()));
}

}  // namespace

CubeRegion owned_region(const CubeRegion& tile) {
  CubeRegion region = tile;
  region.first_row = tile.first_row + tile.owned_begin;
  region.rows = tile.owned_rows();
  region.owned_begin = 0;
  region.owned_end = region.rows;
  return region;
}

TileRunner::TileRunner(const CoverParameters& parameters, const CubeTiling& tiling)
    : tiling_(tiling), cover_(std::make_unique<GlobalCover>(parameters, tiling.tile(0))) {}

TileDensity TileRunner::run(int index) {
  const CubeRegion region = tiling_.tile(index);
  const CubeRegion& current = cover_->region();
  if (current.face != region.face || current.first_row != region.first_row || current.rows != region.rows)
    cover_->set_tile(region);
  const std::size_t before = cover_->timings().size();
  cover_->run();
  TileDensity tile;
  tile.index = index;
  tile.region = region;
  std::tie(tile.density_min, tile.density_max) = cover_->density_range();
  tile.diagnosis = cover_->diagnosis_sums();
  const std::vector<float> all = cover_->density_field().read();
  const std::size_t row = static_cast<std::size_t>(region.face_size);
  const auto owned = [&](const std::vector<float>& texels) {
    return std::vector<float>(texels.begin() + static_cast<std::ptrdiff_t>(region.owned_begin * row),
                              texels.begin() + static_cast<std::ptrdiff_t>(region.owned_end * row));
  };
  tile.density = owned(all);
  tile.cloud_top = owned(cover_->cloud_top_field().read());
  tile.cover_contrast = owned(cover_->cover_contrast_field().read());
  tile.timings.assign(cover_->timings().begin() + static_cast<std::ptrdiff_t>(before), cover_->timings().end());
  return tile;
}

TiledCoverage::TiledCoverage(const CoverParameters& parameters, const CubeTiling& tiling)
    : parameters_(resolved_curl(parameters)), tiling_(tiling), coverage_(parameters_) {}

const gpu::Texture& TiledCoverage::upload(int index, const std::vector<float>& density) {
  const CubeRegion region = owned_region(tiling_.tile(index));
  check_tile_values(index, density, region, "densities");
  if (density_.height() != region.rows) {
    density_ = gpu::Texture::layered(region.face_size, region.rows, 1, GL_R32F);
    cover_ = gpu::Texture::layered(region.face_size, region.rows, 1, GL_R32F);
    optical_thickness_ = gpu::Texture::layered(region.face_size, region.rows, 1, GL_R32F);
    cloud_top_ = gpu::Texture::layered(region.face_size, region.rows, 1, GL_R32F);
    contrast_ = gpu::Texture::layered(region.face_size, region.rows, 1, GL_R32F);
  }
  density_.write(density);
  return density_;
}

const CoverageCalibration& TiledCoverage::calibrate(std::pair<float, float> range, const LoadTileDensity& load) {
  const DensityParts parts = [&](const std::function<void(const DensityPart&)>& use) {
    for (int index = 0; index < tiling_.count; ++index) {
      const gpu::Texture& density = upload(index, load(index));
      use(DensityPart{density, owned_region(tiling_.tile(index))});
    }
  };
  coverage_.calibrate(parts, range);
  return coverage_.result();
}

const CoverageCalibration& TiledCoverage::remap(const LoadTileDensity& load, const LoadTileDensity& load_cloud_top,
                                                const LoadTileDensity& load_contrast,
                                                const std::function<void(int index, const CoverPlanes& cover)>& take) {
  coverage_.begin_remap();
  for (int index = 0; index < tiling_.count; ++index) {
    const gpu::Texture& density = upload(index, load(index));
    const CubeRegion region = owned_region(tiling_.tile(index));
    // The density pass's other planes of the tile, one value per owned texel.
    const auto write_plane = [&](const gpu::Texture& texture, const LoadTileDensity& load_plane, const char* what) {
      const std::vector<float> values = load_plane(index);
      check_tile_values(index, values, region, what);
      texture.write(values);
    };
    write_plane(cloud_top_, load_cloud_top, "cloud tops");
    write_plane(contrast_, load_contrast, "cover contrasts");
    coverage_.remap(density, contrast_, {cover_, optical_thickness_, cloud_top_}, region);
    take(index, CoverPlanes{cover_.read(), optical_thickness_.read(), cloud_top_.read()});
  }
  return coverage_.finish_remap();
}

}  // namespace nephele::cover
