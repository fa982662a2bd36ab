#pragma once
// What covers the ground of the views near the ground (docs/terrain.md, Land cover): lakes and
// rivers as mapped, built-up areas from the towns' municipal boundaries and their distance to
// the town centre, rasterised into the texture terrain.glsl's land functions sample. Forest,
// fields and snow are procedural in the shader (by slope, altitude, season and noise).
#include <string>
#include <utility>
#include <vector>

namespace nephele::regional {

struct GeoPoint {
  double latitude_deg = 0, longitude_deg = 0;  // WGS84
};

// A polygon as closed rings (the last point joins the first): outer rings, holes and the
// islands in holes alike; a point is inside when it lies inside an odd number of them.
struct GeoPolygon {
  std::string name;
  std::vector<std::vector<GeoPoint>> rings;
  double surface_m = 0;  // lakes: the water's surface above sea level
};

// A river as its centre line and half its width.
struct GeoLine {
  std::string name;
  double half_width_m = 0;
  std::vector<GeoPoint> points;
};

// A town whose built-up area is its municipality within radius_m of its centre (docs/terrain.md).
struct Town {
  std::string name;
  GeoPoint centre;
  double radius_m;
};
// Bern and its neighbours, and the towns of the Plateau around it (docs/terrain.md gives the
// coordinates' sources).
const std::vector<Town>& towns();

struct Settlement {
  Town town;
  GeoPolygon municipality;  // the municipality that contains the town's centre
};

struct LandFeatures {
  std::vector<GeoPolygon> lakes;
  std::vector<GeoLine> rivers;
  std::vector<Settlement> settlements;
  std::string source;  // what they were read from, for the render's passes and the sidecar
};

// Even-odd test in latitude and longitude (straight edges there; the features' edges are tens
// of metres long, so the difference from geodesic edges is far below a texel).
bool contains(const GeoPolygon& polygon, GeoPoint point);

// The land cover in the renderer's horizontal coordinate (the height field's, docs/terrain.md):
// two square levels of size x size texels centred on the camera, the near one (fine, for the
// rivers and streets close by) and the far one (the lakes out to the Alps). Texel (i, j) of a
// level of half-size E sits at ((2 i + 1) / size - 1, (2 j + 1) / size - 1) E, like the height
// field's. Each array is level-major, then rows (south first), then columns:
//   water  signed distance (m) to the nearest shore or river bank, negative in the water,
//          clamped to +-band(level) (bilinear, its zero contour is the shore within a fraction
//          of a texel, finer than the texel grid)
//   urban  built-up fraction, 0 to 1
//   lake_surface  (far level only, for the height field) the surface (m above sea level) of
//          the lake a texel lies in or nearest to within the band; NaN elsewhere
constexpr int land_cover_levels = 2;
struct LandCoverGrid {
  int size = 0;
  double extent_m[land_cover_levels] = {0, 0};
  std::vector<float> water, urban, lake_surface;
  std::string source;
  bool empty() const { return size == 0; }
  double texel_m(int level) const { return 2 * extent_m[level] / size; }
  // How far from the shore the distances are exact: 8 texels (and how far the height field's
  // shores slope down to a lake).
  double band_m(int level) const { return 8 * texel_m(level); }
  size_t index(int level, int i, int j) const { return (static_cast<size_t>(level) * size + j) * size + i; }
  // The far level's water distance and lake surface at a horizontal coordinate, bilinear and
  // nearest (what the height field is carved with); {band, NaN} outside the level.
  std::pair<double, double> far_lake(double x, double y) const;
};

// Rasterises the features for a camera (the frame of terrain_grid). Rivers narrower than a
// level's texel are left out of that level: their zero contour would break into dots.
LandCoverGrid land_cover_grid(double latitude_deg, double longitude_deg, double height_m, double earth_radius_m,
                              const LandFeatures& features, int size, double near_extent_m, double far_extent_m);

}  // namespace nephele::regional

namespace nephele::regional {

// The seasonal snow line (m above sea level) of the northern Swiss Alps on a day of the year
// (1 to 366): a cosine between 1000 m in mid-February and 3000 m in mid-August
// (docs/terrain.md gives its sources; a climatology, not the day's snow).
double seasonal_snow_line_m(int day_of_year);

// The stage of the Plateau's arable crops on a day of the year: 0 bare soil (ploughed, October
// to March), 1 green (from late March to early May, held to late June), 2 ripe (July to August,
// before the harvest), back to 0 by late September; linear between (docs/terrain.md).
double seasonal_crop_stage(int day_of_year);

}  // namespace nephele::regional
