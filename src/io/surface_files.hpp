#pragma once
// The land/ocean mask of --surface (docs/climate.md, "Land and ocean"): ETOPO5 of
// ferret-datasets (land where the elevation is above sea level), another ETOPO5 netCDF, or an
// equirect image of the land fraction.
#include <memory>
#include <string>

#include "cover/surface_bias.hpp"
#include "regional/scene.hpp"

namespace nephele::io {

// --surface's value (`field` names it in errors: the option or a scene file's key): "none"
// gives null; "etopo5" the packaged file (the default), or, where the package is not
// installed, null with *warning set (an error if `warning` is null) (as the ground views' --terrain etopo5 falls back
// to the bare sphere); a path ending in .cdf or .nc an ETOPO5 file; any other path an image (OpenImageIO) whose first
// channel is the land fraction in [0, 1], longitude -180 at the left edge, north up. The result is on the bias grid
// (cover::surface_bias_columns x rows, area averages) and is kept for the process by value, so that a viewer making a
// cover per frame reads the file once. Throws core::InputError naming `field` and the file (missing, unreadable, or
// values outside [0, 1]).
std::shared_ptr<const cover::SurfaceMask> surface_from_option(const std::string& value, std::string* warning,
                                                              const std::string& field = "--surface");

// The mask of a scene's global cover (its cover_surface, as above), null where the scene's
// weather files stand in for the cover (nothing is read then).
std::shared_ptr<const cover::SurfaceMask> scene_surface(const regional::Scene& scene, std::string* warning,
                                                        const std::string& field);

}  // namespace nephele::io
