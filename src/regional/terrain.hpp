#pragma once
// The ground around a viewpoint: an elevation raster (read by src/io/elevation_files), the
// substitute relief of the hills it does not resolve, and the height field the renderer marches
// (shaders/lib/terrain.glsl). docs/terrain.md explains the frame and the sources.
#include <optional>
#include <string>
#include <vector>

#include "shader_math/shader_math.hpp"

namespace nephele::regional {

// Elevations (m above sea level) on a latitude-longitude lattice: row r at latitude
// south_deg + r step_deg, column c at longitude west_deg + c step_deg.
struct ElevationRaster {
  double south_deg = 0, west_deg = 0, step_deg = 1;
  int rows = 0, columns = 0;
  std::vector<float> heights;  // rows * columns, row 0 southmost
  std::string source;          // what it was read from, for messages
  // Bilinear between the four samples around the point (longitude taken modulo 360);
  // nullopt outside the lattice.
  std::optional<double> at(double latitude_deg, double longitude_deg) const;
};

// A hill too small for the raster, given a substitute relief: a Gaussian bump of standard
// deviation sigma_m added to the raster so that the summit reaches its known elevation.
struct Hill {
  std::string name;
  double latitude_deg, longitude_deg, summit_m, sigma_m;
};
// Gurten and Bantiger (docs/terrain.md: a labelled substitute, not survey data).
const std::vector<Hill>& substitute_hills();

// The renderer's height field: size x size altitudes above the sphere of radius earth_radius_m
// that touches the camera's vertical, texel (i, j) at the tangent-plane coordinate
// ((2 i + 1) / size - 1, (2 j + 1) / size - 1) * extent_m east and north of the camera (the
// horizontal coordinate of terrain.glsl). Sea and lake floors are raised to sea level.
struct TerrainGrid {
  int size = 0;
  double extent_m = 0;
  std::vector<float> altitudes;  // row j = 0 southmost, column i = 0 westmost
  float top_m = 0;               // highest altitude
  std::string source;            // raster and hills, for messages and the sidecar
  // terrain_ceilings(altitudes, size, ceiling_window): what lets the march step over ground it
  // is well above (the green channel of terrain.glsl's TerrainTexture).
  std::vector<float> ceilings;
  int ceiling_window = 0;
  double texel_m() const { return 2 * extent_m / size; }
  // How far (m, horizontally) the bilinear ceiling bounds the ground: the window less 2 texels
  // (1 for the bilinear taps of the ceiling, 1 for those of the ground; docs/terrain.md).
  double reach_m() const { return ceiling_window > 2 ? (ceiling_window - 2) * texel_m() : 0.0; }
};

// Texels of the ceiling's window on each side (terrain_grid's choice; docs/terrain.md).
constexpr int terrain_ceiling_window = 8;

// The ceiling of a size x size height field: at each texel the highest altitude of the texels
// within `window` texels of it along both axes (the square of side 2 window + 1, cut at the
// edges). Separable: a running maximum along rows, then along columns.
std::vector<float> terrain_ceilings(const std::vector<float>& altitudes, int size, int window);

// What the marcher and its C++ twin take of a grid.
glsl::TerrainParams terrain_params(const TerrainGrid& grid);
glsl::TerrainSource terrain_source(const TerrainGrid& grid);

// Samples the raster (plus the hills) under every texel; the geodesy (the texel's latitude,
// longitude and ellipsoidal height) is GeographicLib's local Cartesian frame at the camera.
TerrainGrid terrain_grid(double latitude_deg, double longitude_deg, double height_m, double earth_radius_m,
                         const ElevationRaster& raster, const std::vector<Hill>& hills, int size, double extent_m);

// Elevation angle (degrees above the horizontal) of the highest ground seen from the camera in
// an azimuth (degrees clockwise from north), ignoring refraction: the largest angle of the
// ground points along the geodesic, each placed on the ellipsoid at its raster elevation
// (plus the hills) by GeographicLib, out to max_distance_m in steps of step_m. The reference
// the renderer's horizon is tested against. distance_m: where that ground lies.
double horizon_elevation_deg(double latitude_deg, double longitude_deg, double height_m, double azimuth_deg,
                             const ElevationRaster& raster, const std::vector<Hill>& hills, double max_distance_m,
                             double step_m, double* distance_m = nullptr);

}  // namespace nephele::regional
