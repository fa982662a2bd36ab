#include "regional/terrain.hpp"

#include <GeographicLib/Geodesic.hpp>
#include <GeographicLib/GeodesicLine.hpp>
#include <GeographicLib/LocalCartesian.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/parallel_rows.hpp"

namespace nephele::regional {

std::optional<ElevationRaster::Cell> ElevationRaster::cell(double latitude_deg, double longitude_deg) const {
  const double v = (latitude_deg - south_deg) / step_deg;
  double u = std::fmod(longitude_deg - west_deg, 360.0);
  if (u < 0) u += 360.0;
  u /= step_deg;
  if (v < 0 || v > rows - 1 || u < 0 || u > columns - 1) return std::nullopt;
  return Cell{std::min(static_cast<int>(v), rows - 2), std::min(static_cast<int>(u), columns - 2), u, v};
}

std::optional<double> ElevationRaster::at(double latitude_deg, double longitude_deg) const {
  const std::optional<Cell> k = cell(latitude_deg, longitude_deg);
  if (!k) return std::nullopt;
  const int r = k->row, c = k->column;
  const double fv = k->v - r, fu = k->u - c;
  auto h = [&](int rr, int cc) { return double(sample(rr, cc)); };
  return (1 - fv) * ((1 - fu) * h(r, c) + fu * h(r, c + 1)) + fv * ((1 - fu) * h(r + 1, c) + fu * h(r + 1, c + 1));
}

ElevationRaster::Columns ElevationRaster::columns_at(const std::vector<double>& longitudes_deg) const {
  Columns out;
  out.column.reserve(longitudes_deg.size());
  out.u.reserve(longitudes_deg.size());
  for (double longitude : longitudes_deg) {
    // As cell() takes a longitude; the latitude is checked by row_at.
    double u = std::fmod(longitude - west_deg, 360.0);
    if (u < 0) u += 360.0;
    u /= step_deg;
    const bool inside = u >= 0 && u <= columns - 1;
    out.column.push_back(inside ? std::min(static_cast<int>(u), columns - 2) : -1);
    out.u.push_back(u);
  }
  return out;
}

void ElevationRaster::row_at(double latitude_deg, const Columns& columns_of, double outside, double* out) const {
  const size_t n = columns_of.column.size();
  const double v = (latitude_deg - south_deg) / step_deg;
  if (v < 0 || v > rows - 1) {
    std::fill(out, out + n, outside);
    return;
  }
  const int r = std::min(static_cast<int>(v), rows - 2);
  const double fv = v - r;
  for (size_t k = 0; k < n; ++k) {
    const int c = columns_of.column[k];
    if (c < 0) {
      out[k] = outside;
      continue;
    }
    // at()'s expression, term by term, so that the values agree to the bit.
    const double fu = columns_of.u[k] - c;
    auto h = [&](int rr, int cc) { return double(sample(rr, cc)); };
    out[k] = (1 - fv) * ((1 - fu) * h(r, c) + fu * h(r, c + 1)) + fv * ((1 - fu) * h(r + 1, c) + fu * h(r + 1, c + 1));
  }
}

std::pair<double, double> TangentPlane::of(double latitude_deg, double longitude_deg, double ellipsoid_height_m) const {
  double x, y, z;
  frame_.Forward(latitude_deg, longitude_deg, ellipsoid_height_m, x, y, z);
  return of_local(x, y, z);
}

std::pair<double, double> TangentPlane::of_local(double x, double y, double z) const {
  // The camera's frame: east, north, up, the sphere's centre R + height below the camera.
  const double qz = z + radius_m_ + height_m_;
  const double n = std::sqrt(x * x + y * y + qz * qz);
  return {radius_m_ * x / n, radius_m_ * y / n};
}

namespace {

// The rms of perlin_noise over a plane (its lattice's z = 0.5), measured once on 65536 points:
// what turns an octave's wanted rms into its amplitude.
double perlin_rms() {
  static const double rms = [] {
    const glsl::uvec3 key = glsl::noise_key(0x54455252u, 0u);
    double sum = 0;
    const int n = 256;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double v =
            glsl::perlin_noise(glsl::vec3((i + 0.37f) * 0.173f, (j + 0.61f) * 0.173f, 0.5f), glsl::ivec3(0), key);
        sum += v * v;
      }
    return std::sqrt(sum / (n * n));
  }();
  return rms;
}

}  // namespace

double TerrainDetail::at(double u, double v, double fu, double fv, const double corners[4],
                         const bool summits[4]) const {
  if (strength <= 0 || cell_rms_m <= 0) return 0;
  const double hi = std::max({corners[0], corners[1], corners[2], corners[3]});
  const double lo = std::min({corners[0], corners[1], corners[2], corners[3]});
  const double local = std::min((hi - lo) / mean_range_m, 3.0);
  // Vanishes at summits: a Gaussian hole a quarter of a cell wide round each.
  double guard = 1;
  const double cu[4] = {0, 1, 0, 1}, cv[4] = {0, 0, 1, 1};
  for (int k = 0; k < 4; ++k)
    if (summits[k]) {
      const double d2 = ((fu - cu[k]) * (fu - cu[k]) + (fv - cv[k]) * (fv - cv[k])) / (0.25 * 0.25);
      guard *= 1 - std::exp(-d2);
    }
  // Octave k has the wavelength of 2^-k cells and the rms S(1) 2^(-k H) / sqrt(2): the rms
  // difference of a noise at half its wavelength is about sqrt(2) times its rms. The lattice
  // repeats every 1024 cells (85 degrees), wrapped exactly.
  const double wu = u - 1024.0 * std::floor(u / 1024.0), wv = v - 1024.0 * std::floor(v / 1024.0);
  double sum = 0;
  // 2^(-k H) by repeated products (pow was a tenth of the height field's set-up).
  const double halving = std::exp2(-hurst);
  double falloff = 1;
  for (int k = 1; k <= octaves; ++k) {
    const double scale = std::ldexp(1.0, k);
    falloff *= halving;
    const double rms = cell_rms_m * falloff / std::sqrt(2.0);
    const int period = 1024 << k;
    sum += rms / perlin_rms() *
           glsl::perlin_noise(glsl::vec3(float(wu * scale), float(wv * scale), 0.5f), glsl::ivec3(period, period, 0),
                              glsl::noise_key(0x54455252u, static_cast<unsigned>(k)));
  }
  return strength * scale * local * guard * sum;
}

TerrainDetail terrain_detail(const ElevationRaster& raster, double south_deg, double north_deg, double west_deg,
                             double east_deg, double strength) {
  TerrainDetail detail;
  detail.strength = strength;
  auto h = [&](int r, int c) { return std::max(double(raster.sample(r, c)), 0.0); };
  double sum1 = 0, sum2 = 0, ranges = 0;
  long n1 = 0, n2 = 0, cells = 0;
  for (int r = 0; r + 2 < raster.rows; ++r) {
    const double lat = raster.south_deg + r * raster.step_deg;
    if (lat < south_deg || lat > north_deg) continue;
    for (int c = 0; c + 2 < raster.columns; ++c) {
      double lon = raster.west_deg + c * raster.step_deg;
      lon -= 360.0 * std::floor((lon - west_deg) / 360.0);
      if (lon > east_deg) continue;
      for (const auto& [dr, dc] : {std::pair<int, int>{0, 1}, {1, 0}}) {
        const double d1 = h(r + dr, c + dc) - h(r, c), d2 = h(r + 2 * dr, c + 2 * dc) - h(r, c);
        sum1 += d1 * d1, sum2 += d2 * d2;
        ++n1, ++n2;
      }
      ranges += std::max({h(r, c), h(r + 1, c), h(r, c + 1), h(r + 1, c + 1)}) -
                std::min({h(r, c), h(r + 1, c), h(r, c + 1), h(r + 1, c + 1)});
      ++cells;
    }
  }
  if (n1 == 0 || sum1 <= 0) return detail;
  detail.cell_rms_m = std::sqrt(sum1 / n1);
  detail.hurst = std::clamp(std::log2(std::sqrt(sum2 / n2) / detail.cell_rms_m), 0.3, 1.0);
  detail.mean_range_m = std::max(ranges / cells, 1.0);
  // The factor: at each lag the octaves must supply what the bilinear surface lacks of the
  // power law, S^2 = S_bilinear^2 + scale^2 S_octaves^2; the mean of the three lags' factors.
  // Measured north-south over a fixed lattice of 4096 points (the same for every run).
  TerrainDetail unit = detail;
  unit.strength = 1;
  unit.scale = 1;
  const TerrainDetail smooth;
  double factors = 0;
  int lags = 0;
  for (const double lag : {0.5, 0.25, 0.125}) {
    double surface = 0, octaves = 0;
    for (int k = 0; k < 4096; ++k) {
      // A Weyl sequence over the region (golden-ratio steps: evenly spread, no grid alignment).
      const double lat = south_deg + (north_deg - south_deg) * std::fmod(k * 0.6180339887498949, 1.0);
      const double lon = west_deg + (east_deg - west_deg) * std::fmod(k * 0.7548776662466927, 1.0);
      const double step = lag * raster.step_deg;
      const double b = relief_elevation(raster, smooth, lat + step, lon) - relief_elevation(raster, smooth, lat, lon);
      const double d = relief_elevation(raster, unit, lat + step, lon) - relief_elevation(raster, unit, lat, lon) - b;
      surface += b * b, octaves += d * d;
    }
    const double target = detail.cell_rms_m * std::pow(lag, detail.hurst);
    const double lacking = target * target - surface / 4096;
    if (octaves > 0 && lacking > 0) factors += std::sqrt(lacking / (octaves / 4096)), ++lags;
  }
  detail.scale = lags > 0 ? factors / lags : 0.0;
  return detail;
}

double relief_elevation(const ElevationRaster& raster, const TerrainDetail& detail, double latitude_deg,
                        double longitude_deg) {
  const double bilinear = std::max(raster.at(latitude_deg, longitude_deg).value_or(0.0), 0.0);
  if (detail.strength <= 0) return bilinear;
  const std::optional<ElevationRaster::Cell> cell = raster.cell(latitude_deg, longitude_deg);
  if (!cell) return bilinear;
  const int r = cell->row, c = cell->column;
  const double u = cell->u, v = cell->v;
  auto h = [&](int rr, int cc) { return std::max(double(raster.sample(rr, cc)), 0.0); };
  // A sample is a summit when it is higher than its eight neighbours (those inside the raster).
  auto summit = [&](int rr, int cc) {
    for (int dr = -1; dr <= 1; ++dr)
      for (int dc = -1; dc <= 1; ++dc) {
        const int a = rr + dr, b = cc + dc;
        if ((dr != 0 || dc != 0) && a >= 0 && a < raster.rows && b >= 0 && b < raster.columns && h(a, b) >= h(rr, cc))
          return false;
      }
    return true;
  };
  const double corners[4] = {h(r, c), h(r, c + 1), h(r + 1, c), h(r + 1, c + 1)};
  const bool summits[4] = {summit(r, c), summit(r, c + 1), summit(r + 1, c), summit(r + 1, c + 1)};
  // The raster's longitude origin added back, so that the lattice is the same for every cut.
  const double column0 = std::round((raster.west_deg + 360.0) / raster.step_deg);
  const double row0 = std::round((raster.south_deg + 90.0) / raster.step_deg);
  const double d = detail.at(u + column0, v + row0, u - c, v - r, corners, summits);
  const double highest = std::max({corners[0], corners[1], corners[2], corners[3]});
  return std::max(std::min(bilinear + d, std::max(highest, bilinear)), 0.0);
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
  std::vector<double> bump;  // per hill: summit minus the relief there
  const std::vector<Hill>& hills;
  const TerrainDetail& detail;

  Relief(const ElevationRaster& r, const std::vector<Hill>& h, const TerrainDetail& d)
      : raster(r), hills(h), detail(d) {
    for (const Hill& hill : hills)
      bump.push_back(hill.summit_m - relief_elevation(raster, {}, hill.latitude_deg, hill.longitude_deg));
  }
  // distance_m(k): the point's distance from hill k.
  template <class Distance>
  double at(double latitude_deg, double longitude_deg, const Distance& distance_m) const {
    const double smooth = relief_elevation(raster, {}, latitude_deg, longitude_deg);
    double h = smooth;
    // The detail fades out over the hills (a Gaussian hole twice as wide as each), which stand
    // for the relief there.
    double keep = 1;
    for (size_t k = 0; k < hills.size(); ++k) {
      const double d = distance_m(k) / hills[k].sigma_m;
      if (d < 6) h += bump[k] * std::exp(-0.5 * d * d);
      keep *= 1 - std::exp(-0.125 * d * d);
    }
    if (detail.strength > 0 && keep > 0)
      h += keep * (relief_elevation(raster, detail, latitude_deg, longitude_deg) - smooth);
    return h;
  }
};

}  // namespace

TerrainGrid terrain_grid(double latitude_deg, double longitude_deg, double height_m, double earth_radius_m,
                         const ElevationRaster& raster, const std::vector<Hill>& hills, int size, double extent_m,
                         const LandCoverGrid* land, const TerrainDetail& detail) {
  TerrainGrid grid;
  grid.size = size;
  grid.extent_m = extent_m;
  grid.source = raster.source;
  grid.raster_source = raster.source;
  if (detail.strength > 0) {
    char text[96];
    std::snprintf(text, sizeof text, " + fractal detail (H %.2f, S %.0f m a cell, mean range %.0f m)", detail.hurst,
                  detail.cell_rms_m, detail.mean_range_m);
    grid.source += text;
  }
  for (const Hill& h : hills) grid.source += " + substitute " + h.name;
  if (land != nullptr && !land->empty()) grid.source += " + lakes of " + land->source;
  grid.altitudes.resize(static_cast<size_t>(size) * size);
  const TangentPlane plane(latitude_deg, longitude_deg, height_m, earth_radius_m);
  const GeographicLib::LocalCartesian& frame = plane.frame();
  const double R = earth_radius_m;
  std::vector<std::pair<double, double>> hill_xy;
  for (const Hill& h : hills) hill_xy.push_back(plane.of(h.latitude_deg, h.longitude_deg));
  const Relief relief(raster, hills, detail);
  // Rows shared by the hardware threads: each texel depends only on its own point.
  core::parallel_rows(size, [&](int first_row, int end_row) {
    for (int j = first_row; j < end_row; ++j) {
      const double y = ((2.0 * j + 1) / size - 1) * extent_m;
      for (int i = 0; i < size; ++i) {
        const double x = ((2.0 * i + 1) / size - 1) * extent_m;
        // The sphere's point under (x, y), and its latitude, longitude and ellipsoidal height.
        const double z = std::sqrt(std::max(R * R - x * x - y * y, 0.0)) - R - height_m;
        double lat, lon, h_sphere;
        frame.Reverse(x, y, z, lat, lon, h_sphere);
        double h =
            relief.at(lat, lon, [&](size_t k) { return std::hypot(x - hill_xy[k].first, y - hill_xy[k].second); });
        if (land != nullptr && !land->empty()) {
          // The lake's surface inside it; outside, the relief lowered towards it within the band.
          const auto [distance, surface] = land->far_lake(x, y);
          if (!std::isnan(surface)) {
            const double t = std::clamp(distance / land->band_m(1), 0.0, 1.0);
            h = distance <= 0 ? surface : std::min(h, surface + std::max(h - surface, 0.0) * t * t * (3 - 2 * t));
          }
        }
        grid.altitudes[static_cast<size_t>(j) * size + i] = static_cast<float>(h - h_sphere);
      }
    }
  });
  const float top = std::max(0.0f, *std::max_element(grid.altitudes.begin(), grid.altitudes.end()));
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
  glsl::TerrainParams t = no_terrain_params();
  t.enabled = 1;
  t.extent = static_cast<float>(grid.extent_m);
  t.top = grid.top_m + 1.0f;
  t.texel = static_cast<float>(grid.texel_m());
  t.reach = static_cast<float>(grid.reach_m());
  if (grid.land && !grid.land->empty()) {
    t.land = 1;
    t.land_near = static_cast<float>(grid.land->extent_m[0]);
    t.land_far = static_cast<float>(grid.land->extent_m[1]);
    t.land_texels = static_cast<float>(grid.land->size);
  }
  return t;
}

glsl::TerrainParams no_terrain_params() {
  glsl::TerrainParams t;
  t.enabled = 0;
  t.extent = 1.0f;
  t.top = 0.0f;
  t.texel = 1.0f;
  t.reach = 0.0f;
  t.land = 0;
  t.land_near = 1.0f;
  t.land_far = 1.0f;
  t.land_texels = 1.0f;
  t.snow_line = static_cast<float>(seasonal_snow_line_m(172));  // the summer solstice's
  t.crop_stage = static_cast<float>(seasonal_crop_stage(172));
  return t;
}

glsl::TerrainSource terrain_source(const TerrainGrid& grid) {
  return {{grid.size, 1, grid.altitudes.data()}, {grid.size, 1, grid.ceilings.data()}};
}

glsl::LandCoverSource land_cover_source(const LandCoverGrid& land) {
  return {{land.size, land_cover_levels, land.water.data()}, {land.size, land_cover_levels, land.urban.data()}};
}

double horizon_elevation_deg(double latitude_deg, double longitude_deg, double height_m, double azimuth_deg,
                             const ElevationRaster& raster, const std::vector<Hill>& hills, double max_distance_m,
                             double step_m, double* distance_m, const TerrainDetail& detail) {
  const GeographicLib::Geodesic& g = GeographicLib::Geodesic::WGS84();
  const GeographicLib::GeodesicLine line = g.Line(latitude_deg, longitude_deg, azimuth_deg);
  const GeographicLib::LocalCartesian frame(latitude_deg, longitude_deg, height_m);
  const Relief relief(raster, hills, detail);
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
