#pragma once
// Land cover of the ground views from files (docs/terrain.md, Land cover): the lakes and
// municipalities of swiss-maps' TopoJSON (scripts/install-data.sh installs it) and the rivers
// of GSHHG, rasterised for a camera by regional::land_cover_grid.
#include <memory>
#include <string>

#include "regional/land_cover.hpp"

namespace nephele::io {

// Where scripts/install-data.sh installs swiss-maps 4.7.0's TopoJSON of 2026.
inline const char* const swiss_maps_default_path = "/usr/local/share/nephele/swiss-maps/ch-combined.json";

// The lakes (named by the Federal Statistical Office's lake numbers) and, for each of
// regional::towns(), the municipality that contains its centre, from a swiss-maps TopoJSON
// (objects `lakes` and `municipalities`, quantised arcs in WGS84 longitude and latitude).
// Throws core::InputError naming `field` and the file when it is not such a file.
regional::LandFeatures read_swiss_maps(const std::string& path, const std::string& field = "--land-cover");

// The rivers of a GSHHG river file (river_files.hpp) within radius_m of a point, as centre lines
// with the half width drawn for their class (docs/terrain.md).
std::vector<regional::GeoLine> read_rivers(const std::string& path, double latitude_deg, double longitude_deg,
                                           double radius_m);

// The land cover for a camera from the `land_cover` setting (params::scene::land_cover): "none"
// gives none; "swiss-maps" the installed file (none, and `warning` says why, when it is
// absent); anything else the path of a swiss-maps TopoJSON. The rivers come from GSHHG's
// installed file where there is one (`warning` says so where not).
std::shared_ptr<const regional::LandCoverGrid> load_land_cover(const std::string& setting, double latitude_deg,
                                                               double longitude_deg, double height_m,
                                                               std::string* warning = nullptr,
                                                               const std::string& field = "--land-cover");

// The land cover's levels for the renders: 1024 texels a side, the near level 40 km square
// (40 m texels: the Aare through Bern), the far level the height field's 300 km square (293 m
// texels: the lakes out to the Alps). 21 MB on the host, 8 MB on the GPU.
constexpr int land_cover_size = 1024;
constexpr double land_cover_near_extent_m = 20480.0;
constexpr double land_cover_far_extent_m = 150000.0;

}  // namespace nephele::io
