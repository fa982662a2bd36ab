#pragma once
// Elevation data for the ground of the views near the ground (docs/terrain.md): ETOPO5 as the
// Debian package ferret-datasets installs it, cut to the latitudes around a viewpoint, and the
// height field the renderer marches.
#include <memory>
#include <string>

#include "regional/terrain.hpp"

namespace nephele::io {

// Where ferret-datasets (scripts/debian-packages.txt) installs ETOPO5.
inline const char* const etopo5_default_path = "/usr/share/ferret-vis/data/etopo5.cdf";

// The rows of ETOPO5 from south_deg to north_deg (whole rows: all longitudes, the first column
// repeated at 360 degrees so that the lattice wraps). The file must be the 5-arc-minute netCDF
// of ferret-datasets: a 52552-byte header naming ETOPO05_X and ETOPO05_Y, then big-endian
// float32 [2161][4320], row j at latitude -90 + j/12, column i at longitude i/12 east.
// Throws core::InputError naming `field` (the option or scene key) and the file otherwise.
regional::ElevationRaster read_etopo5(const std::string& path, double south_deg, double north_deg,
                                      const std::string& field = "--terrain");

// All of ETOPO5 at `path` (read_etopo5 from pole to pole), shared while anyone holds it: the
// orbit view's water and relief (read_planet_textures) and the cover's land/ocean mask
// (surface_from_option) both derive from the whole globe, and a caller that needs both holds
// the raster across them so that the file (37 MB of samples) is read once. Nobody holding it,
// the next call reads the file again: a process keeps no copy it no longer uses.
std::shared_ptr<const regional::ElevationRaster> whole_etopo5(const std::string& path, const std::string& field);

// The ground for a camera from the `terrain` setting (params::scene::terrain): "flat" or an
// absent default file gives none (the bare sphere; `warning` then says why when the default
// was meant), "etopo5" the packaged file, anything else an ETOPO5 file of that path.
// `warning` also says when the camera is below the ground under it. The land cover
// (io::load_land_cover of `ground.land_cover`) comes with the ground and carves its lakes into
// it; the fractal detail (regional::TerrainDetail of `ground.detail`) is fitted to the raster
// within the height field's reach.
struct GroundOptions {
  std::string land_cover = "none";  // params::scene::land_cover
  std::string land_field = "--land-cover";
  double detail = 0;  // params::scene::terrain_detail
};
std::shared_ptr<const regional::TerrainGrid> load_terrain(const std::string& setting, double latitude_deg,
                                                          double longitude_deg, double height_m,
                                                          std::string* warning = nullptr,
                                                          const std::string& field = "--terrain",
                                                          const GroundOptions& ground = {});

// The height field's size and half-extent for the renders: 300 km square, 390 m texels, enough
// for the substitute hills' widths and the Alps' main ridge from Bern.
constexpr int terrain_grid_size = 768;
constexpr double terrain_grid_extent_m = 150000.0;

}  // namespace nephele::io
