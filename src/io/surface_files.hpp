#pragma once
// The land/ocean mask of --surface (docs/climate.md, "Land and ocean"): ETOPO5 of
// ferret-datasets (land where the elevation is above sea level), another ETOPO5 netCDF, or an
// equirect image of the land fraction.
#include <memory>
#include <string>

#include "cover/surface_bias.hpp"

namespace nephele::io {

// --surface's value: "none" gives null; "etopo5" the packaged file; a path ending in .cdf or
// .nc an ETOPO5 file; any other path an image (OpenImageIO) whose first channel is the land
// fraction in [0, 1], longitude -180 at the left edge, north up. The result is on the bias
// grid (cover::surface_bias_columns x rows, area averages). Throws core::InputError naming
// --surface and the file (missing, unreadable, or values outside [0, 1]).
std::shared_ptr<const cover::SurfaceMask> surface_from_option(const std::string& value);

}  // namespace nephele::io
