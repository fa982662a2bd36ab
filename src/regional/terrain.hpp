#pragma once
// The ground around a viewpoint: an elevation raster (read by src/io/elevation_files), the
// substitute relief of the hills it does not resolve, and the height field the renderer marches
// (shaders/lib/terrain.glsl). docs/terrain.md explains the frame and the sources.
#include <GeographicLib/LocalCartesian.hpp>

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "regional/land_cover.hpp"
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
  // The lattice cell holding a point: its south-west sample (row, column) and the point's
  // lattice coordinates u (columns from west_deg), v (rows from south_deg); nullopt outside.
  struct Cell {
    int row, column;
    double u, v;
  };
  std::optional<Cell> cell(double latitude_deg, double longitude_deg) const;
  float sample(int row, int column) const { return heights[static_cast<size_t>(row) * columns + column]; }
  // The same heights as at() for a grid of points whose rows share their latitude and whose
  // columns share their longitude: each longitude's cell found once (columns_at), then a row at
  // a time (row_at), `outside` where at() gives nullopt. A global mask's millions of samples
  // take a tenth of the time of as many at() calls.
  struct Columns {
    std::vector<int> column;  // the cell's western sample, -1 outside the lattice
    std::vector<double> u;    // the lattice coordinate (columns from west_deg)
  };
  Columns columns_at(const std::vector<double>& longitudes_deg) const;
  void row_at(double latitude_deg, const Columns& columns, double outside, double* out) const;
};

// The renderer's horizontal coordinate (m east and north, docs/terrain.md, Frame) of geographic
// points seen from a camera: the point in GeographicLib's local Cartesian frame at the camera,
// projected from the centre of the sphere of radius earth_radius_m under the camera.
class TangentPlane {
 public:
  TangentPlane(double latitude_deg, double longitude_deg, double height_m, double earth_radius_m)
      : frame_(latitude_deg, longitude_deg, height_m), radius_m_(earth_radius_m), height_m_(height_m) {}
  std::pair<double, double> of(double latitude_deg, double longitude_deg, double ellipsoid_height_m = 0) const;
  // The same for a point given in the local Cartesian frame (m east, north, up of the camera).
  std::pair<double, double> of_local(double x, double y, double z) const;
  const GeographicLib::LocalCartesian& frame() const { return frame_; }

 private:
  GeographicLib::LocalCartesian frame_;
  double radius_m_, height_m_;
};

// Relief finer than the raster's cells (docs/terrain.md, Detail): three octaves of gradient
// noise at a half, a quarter and an eighth of a cell, whose amplitudes continue the raster's own
// structure function S(lag) = rms(h(x + lag) - h(x)) ~ lag^H below the cell (H fitted between
// one and two cells around the camera), scaled by each cell's own relief (the range of its four
// samples over the mean range), so that the Alps get rugged and the Plateau stays gentle. One
// factor, measured on the region's surface, brings the whole surface's S at a half, a quarter
// and an eighth of a cell onto the power law (the octaves overlap, and the bilinear surface has
// its own share).
// Defined in the raster's lattice coordinates, the same for every camera. Never moves a
// summit: it vanishes at raster samples higher than their eight neighbours and never lifts a
// point above the highest sample of its cell.
struct TerrainDetail {
  double strength = 0;      // 0: none (the raster's bilinear surface), 1: the fitted amplitudes
  double hurst = 1;         // H
  double cell_rms_m = 0;    // S(one cell)
  double mean_range_m = 1;  // the mean of the cells' ranges (max - min of their four samples)
  double scale = 1;         // the measured factor on the octaves' amplitudes
  static constexpr int octaves = 3;
  // Detail (m) at a point of a cell whose four samples are h00, h10, h01, h11 (fu, fv its
  // position in the cell; summit00.. whether each sample is a summit).
  double at(double u, double v, double fu, double fv, const double corners[4], const bool summits[4]) const;
};
// The detail's statistics from the raster's samples between two latitudes and longitudes.
TerrainDetail terrain_detail(const ElevationRaster& raster, double south_deg, double north_deg, double west_deg,
                             double east_deg, double strength);

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
  std::string raster_source;     // the elevation data alone (what smooths valleys, in warnings)
  // terrain_ceilings(altitudes, size, ceiling_window): what lets the march step over ground it
  // is well above (the green channel of terrain.glsl's TerrainTexture).
  std::vector<float> ceilings;
  int ceiling_window = 0;
  // What covers it (lakes, rivers, towns; io::load_land_cover); none: the procedural cover alone.
  std::shared_ptr<const LandCoverGrid> land;
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

// What the marcher and its C++ twin take of a grid (its land cover's levels too; the snow line
// is the summer solstice's until the renderer sets the day's).
glsl::TerrainParams terrain_params(const TerrainGrid& grid);
glsl::TerrainSource terrain_source(const TerrainGrid& grid);
glsl::LandCoverSource land_cover_source(const LandCoverGrid& land);
// The bare sphere's.
glsl::TerrainParams no_terrain_params();

// Samples the raster (plus the hills) under every texel; the geodesy (the texel's latitude,
// longitude and ellipsoidal height) is GeographicLib's local Cartesian frame at the camera.
// With detail (strength > 0), the relief below the raster's cells is added (before the lakes).
// With land cover, the ground within a lake is its surface, and the shores slope down to it over
// the land cover's band (the raster's 9 km cells fill the lakes' basins; docs/terrain.md).
TerrainGrid terrain_grid(double latitude_deg, double longitude_deg, double height_m, double earth_radius_m,
                         const ElevationRaster& raster, const std::vector<Hill>& hills, int size, double extent_m,
                         const LandCoverGrid* land = nullptr, const TerrainDetail& detail = {});

// Elevation angle (degrees above the horizontal) of the highest ground seen from the camera in
// an azimuth (degrees clockwise from north), ignoring refraction: the largest angle of the
// ground points along the geodesic, each placed on the ellipsoid at its raster elevation
// (plus the hills) by GeographicLib, out to max_distance_m in steps of step_m. The reference
// the renderer's horizon is tested against. distance_m: where that ground lies.
double horizon_elevation_deg(double latitude_deg, double longitude_deg, double height_m, double azimuth_deg,
                             const ElevationRaster& raster, const std::vector<Hill>& hills, double max_distance_m,
                             double step_m, double* distance_m = nullptr, const TerrainDetail& detail = {});

// Elevation (m above sea level) of the relief at a point: the raster (bilinear, sea level where
// it has none), plus the detail; the hills left out (they need the point's distances).
double relief_elevation(const ElevationRaster& raster, const TerrainDetail& detail, double latitude_deg,
                        double longitude_deg);

}  // namespace nephele::regional
