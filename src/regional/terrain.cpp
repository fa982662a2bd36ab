#include "regional/terrain.hpp"

#include <GeographicLib/Geodesic.hpp>
#include <GeographicLib/GeodesicLine.hpp>
#include <GeographicLib/LocalCartesian.hpp>

#include <algorithm>
#include <cmath>

namespace nephele::regional {

std::optional<double> ElevationRaster::at(double latitude_deg, double longitude_deg) const {
  const double v = (latitude_deg - south_deg) / step_deg;
  double u = std::fmod(longitude_deg - west_deg, 360.0);
  if (u < 0) u += 360.0;
  u /= step_deg;
  if (v < 0 || v > rows - 1 || u < 0 || u > columns - 1) return std::nullopt;
  const int r = std::min(static_cast<int>(v), rows - 2), c = std::min(static_cast<int>(u), columns - 2);
  const double fv = v - r, fu = u - c;
  auto h = [&](int rr, int cc) { return double(heights[static_cast<size_t>(rr) * columns + cc]); };
  return (1 - fv) * ((1 - fu) * h(r, c) + fu * h(r, c + 1)) + fv * ((1 - fu) * h(r + 1, c) + fu * h(r + 1, c + 1));
}

const std::vector<Hill>& substitute_hills() {
  // Summits and elevations as in sites.cpp (docs/layers.md gives the sources). The widths are
  // chosen, not measured: the slopes fall by about 300 m over 2 to 3 km, as on the national map
  // (Gurten to Wabern, Bantiger to Bolligen).
  static const std::vector<Hill> hills = {
      {"Gurten", 46.91722, 7.44361, 858.0, 1100.0},
      {"Bantiger", 46.97916, 7.52917, 947.0, 1300.0},
  };
  return hills;
}

namespace {

// Elevation above sea level at a point: the raster (sea level where it has none or lies below
// it) plus each hill's bump, whose height brings the raster at the summit up to the summit.
struct Relief {
  const ElevationRaster& raster;
  std::vector<double> bump;  // per hill: summit minus the raster there
  const std::vector<Hill>& hills;

  Relief(const ElevationRaster& r, const std::vector<Hill>& h) : raster(r), hills(h) {
    for (const Hill& hill : hills)
      bump.push_back(hill.summit_m - raster.at(hill.latitude_deg, hill.longitude_deg).value_or(0.0));
  }
  // distance_m(k): the point's distance from hill k.
  template <class Distance>
  double at(double latitude_deg, double longitude_deg, const Distance& distance_m) const {
    double h = std::max(raster.at(latitude_deg, longitude_deg).value_or(0.0), 0.0);
    for (size_t k = 0; k < hills.size(); ++k) {
      const double d = distance_m(k) / hills[k].sigma_m;
      if (d < 6) h += bump[k] * std::exp(-0.5 * d * d);
    }
    return h;
  }
};

}  // namespace

TerrainGrid terrain_grid(double latitude_deg, double longitude_deg, double height_m, double earth_radius_m,
                         const ElevationRaster& raster, const std::vector<Hill>& hills, int size, double extent_m) {
  TerrainGrid grid;
  grid.size = size;
  grid.extent_m = extent_m;
  grid.source = raster.source;
  for (const Hill& h : hills) grid.source += " + substitute " + h.name;
  grid.altitudes.resize(static_cast<size_t>(size) * size);
  const GeographicLib::LocalCartesian frame(latitude_deg, longitude_deg, height_m);
  const double R = earth_radius_m;
  // The camera's frame: east, north, up, the sphere's centre R + height below the camera.
  auto plane_of = [&](double x, double y, double z) {
    const double qx = x, qy = y, qz = z + R + height_m;
    const double n = std::sqrt(qx * qx + qy * qy + qz * qz);
    return std::pair<double, double>(R * qx / n, R * qy / n);
  };
  std::vector<std::pair<double, double>> hill_xy;
  for (const Hill& h : hills) {
    double x, y, z;
    frame.Forward(h.latitude_deg, h.longitude_deg, 0.0, x, y, z);
    hill_xy.push_back(plane_of(x, y, z));
  }
  const Relief relief(raster, hills);
  float top = 0;
  for (int j = 0; j < size; ++j) {
    const double y = ((2.0 * j + 1) / size - 1) * extent_m;
    for (int i = 0; i < size; ++i) {
      const double x = ((2.0 * i + 1) / size - 1) * extent_m;
      // The sphere's point under (x, y), and its latitude, longitude and ellipsoidal height.
      const double z = std::sqrt(std::max(R * R - x * x - y * y, 0.0)) - R - height_m;
      double lat, lon, h_sphere;
      frame.Reverse(x, y, z, lat, lon, h_sphere);
      const double h =
          relief.at(lat, lon, [&](size_t k) { return std::hypot(x - hill_xy[k].first, y - hill_xy[k].second); });
      const float altitude = static_cast<float>(h - h_sphere);
      grid.altitudes[static_cast<size_t>(j) * size + i] = altitude;
      top = std::max(top, altitude);
    }
  }
  grid.top_m = top;
  grid.ceiling_window = terrain_ceiling_window;
  grid.ceilings = terrain_ceilings(grid.altitudes, size, grid.ceiling_window);
  return grid;
}

std::vector<float> terrain_ceilings(const std::vector<float>& altitudes, int size, int window) {
  const auto index = [size](int i, int j) { return static_cast<size_t>(j) * size + i; };
  std::vector<float> rows(altitudes.size()), out(altitudes.size());
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      float m = altitudes[index(i, j)];
      for (int k = std::max(i - window, 0); k <= std::min(i + window, size - 1); ++k)
        m = std::max(m, altitudes[index(k, j)]);
      rows[index(i, j)] = m;
    }
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      float m = rows[index(i, j)];
      for (int k = std::max(j - window, 0); k <= std::min(j + window, size - 1); ++k)
        m = std::max(m, rows[index(i, k)]);
      out[index(i, j)] = m;
    }
  return out;
}

glsl::TerrainParams terrain_params(const TerrainGrid& grid) {
  // The shell the march searches reaches a metre above the highest texel.
  return {1, static_cast<float>(grid.extent_m), grid.top_m + 1.0f, static_cast<float>(grid.texel_m()),
          static_cast<float>(grid.reach_m())};
}

glsl::TerrainSource terrain_source(const TerrainGrid& grid) {
  return {{grid.size, 1, grid.altitudes.data()}, {grid.size, 1, grid.ceilings.data()}};
}

double horizon_elevation_deg(double latitude_deg, double longitude_deg, double height_m, double azimuth_deg,
                             const ElevationRaster& raster, const std::vector<Hill>& hills, double max_distance_m,
                             double step_m, double* distance_m) {
  const GeographicLib::Geodesic& g = GeographicLib::Geodesic::WGS84();
  const GeographicLib::GeodesicLine line = g.Line(latitude_deg, longitude_deg, azimuth_deg);
  const GeographicLib::LocalCartesian frame(latitude_deg, longitude_deg, height_m);
  const Relief relief(raster, hills);
  double best = -90.0;
  for (double s = step_m; s <= max_distance_m; s += step_m) {
    double lat, lon;
    line.Position(s, lat, lon);
    const double h = relief.at(lat, lon, [&](size_t k) {
      double d = 0;
      g.Inverse(lat, lon, hills[k].latitude_deg, hills[k].longitude_deg, d);
      return d;
    });
    double x, y, z;
    frame.Forward(lat, lon, h, x, y, z);
    const double elevation = std::atan2(z, std::hypot(x, y)) * 180.0 / M_PI;
    if (elevation > best) {
      best = elevation;
      if (distance_m) *distance_m = s;
    }
  }
  return best;
}

}  // namespace nephele::regional
