#pragma once
// Where the water is, from GSHHG's full-resolution shorelines (Debian's gmt-gshhg-full installs
// /usr/share/gmt-gshhg/binned_GSHHS_f.nc; Wessel and Smith 1996, "A global, self-consistent,
// hierarchical, high-resolution shoreline database", J. Geophys. Res. 101, version 2.3.7):
// the orbit view's coasts and lakes (docs/orbit_view.md, Coasts and lakes).
#include <string>

#include "core/image.hpp"

namespace nephele::io {

inline const char* const gshhg_shorelines_default_path = "/usr/share/gmt-gshhg/binned_GSHHS_f.nc";

// A latitude and longitude window rastered as an equirect: pixel (i, j) covers longitudes
// west + [i, i + 1) (east - west) / width and latitudes north - [j, j + 1) (north - south) / height
// (degrees; row 0 northernmost). west may be below -180 or east above 180 (the window wraps).
struct GeoWindow {
  double south_deg = -90.0, north_deg = 90.0, west_deg = -180.0, east_deg = 180.0;
  int width = 0, height = 0;
};

// The share of each pixel of `window` that is water: the sea, lakes (with the double-lined
// rivers' lakes) and the ponds on islands in lakes, GSHHG's even levels (0 sea, 1 land, 2 lake,
// 3 island in a lake, 4 pond on such an island). Antarctica is bounded by its ice front, so the
// ice shelves are land. Each pixel's share is the water's length along `subrows` parallels
// across it, exact along each, so that coasts are antialiased. One channel, window.width x
// window.height.
// Throws std::invalid_argument for a bad window (non-finite, south > north, west > east, wider
// than 360, no pixels) and std::runtime_error naming the file for I/O problems or an
// inconsistent file.
core::ImageData read_gshhg_water(const std::string& path, const GeoWindow& window, int subrows = 4);

}  // namespace nephele::io
