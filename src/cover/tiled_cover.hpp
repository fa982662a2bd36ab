#pragma once
// A cover computed in tiles (cube_tiles.hpp; docs/scale.md). Each tile's passes up to the
// density run on their own (TileRunner), on one machine or many; the coverage then needs every
// tile's densities: TiledCoverage calibrates from them, handed over tile by tile, and remaps
// each tile. The result equals the whole map's to the bit.
#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include "cover/coverage_remap.hpp"
#include "cover/cube_tiles.hpp"
#include "cover/global_cover.hpp"

namespace nephele::cover {

// What a tile's passes leave for the coverage: its densities and its share of the reductions.
struct TileDensity {
  int index = 0;
  CubeRegion region;                  // the tile with its halo
  std::vector<float> density;         // its owned rows, row by row from the first (N texels a row)
  std::vector<float> cloud_top;       // the density pass's cloud-top heights there, km (cloud_properties.glsl)
  std::vector<float> cover_contrast;  // and its cover contrast (cover_density.glsl)
  float density_min = 0.0f, density_max = 0.0f;
  DiagnosisSums diagnosis;
  std::vector<PassTiming> timings;
};

// The region of a tile's owned rows alone (no halo): what its density and cover maps hold.
CubeRegion owned_region(const CubeRegion& tile);

// Runs tiles of one cover one after another, with one set of compiled programs.
class TileRunner {
 public:
  TileRunner(const CoverParameters& parameters, const CubeTiling& tiling);
  TileDensity run(int index);
  const CoverParameters& parameters() const { return cover_->parameters(); }
  // Called with a pass's name as it starts.
  void on_pass(std::function<void(const std::string&)> callback) { cover_->on_pass(std::move(callback)); }

 private:
  CubeTiling tiling_;
  std::unique_ptr<GlobalCover> cover_;
};

// A tile's owned densities, loaded (from memory or a file) when the coverage asks for them.
using LoadTileDensity = std::function<std::vector<float>(int index)>;

// The cover's three fields over a region of texels or pixels, each a plane of floats: the remap's
// for a tile's owned rows (as TileDensity::density), or whole maps.
struct CoverPlanes {
  std::vector<float> cover, optical_thickness, cloud_top;
  // The planes in the order of the files' channels (io::cover_channels: Y, tau, cloud_top).
  static constexpr int count = 3;
  std::vector<float>& operator[](int channel) {
    return channel == 0 ? cover : channel == 1 ? optical_thickness : cloud_top;
  }
  const std::vector<float>& operator[](int channel) const { return const_cast<CoverPlanes&>(*this)[channel]; }
};

class TiledCoverage {
 public:
  TiledCoverage(const CoverParameters& parameters, const CubeTiling& tiling);
  // The thresholds from every tile's densities (each loaded two or three times: one pass over
  // the tiles per histogram), with the range the tiles' density passes reduced.
  const CoverageCalibration& calibrate(std::pair<float, float> range, const LoadTileDensity& load);
  // Each tile's fields in turn (its owned rows, as TileDensity::density) to `take`, from its
  // densities, cloud tops and cover contrasts; then the achieved fractions.
  const CoverageCalibration& remap(const LoadTileDensity& load, const LoadTileDensity& load_cloud_top,
                                   const LoadTileDensity& load_contrast,
                                   const std::function<void(int index, const CoverPlanes& cover)>& take);
  const CoverageCalibration& calibration() const { return coverage_.result(); }
  const std::optional<BandCalibration>& bands() const { return coverage_.bands(); }

 private:
  // A 2D array of one tile's owned rows, its densities written in.
  const gpu::Texture& upload(int index, const std::vector<float>& density);
  CoverParameters parameters_;
  CubeTiling tiling_;
  CoverageRemap coverage_;
  gpu::Texture density_, cover_, optical_thickness_, cloud_top_, contrast_;
};

}  // namespace nephele::cover
