#include "regional/land_cover.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "regional/terrain.hpp"

namespace nephele::regional {

const std::vector<Town>& towns() {
  // Centres: Bern's Zytglogge, Solothurn and Fribourg as in sites.cpp (docs/layers.md); the
  // others are their town centres to about 0.005 degrees (docs/terrain.md). The radii are the
  // built-up areas' rough extents around the centre: chosen, not measured.
  static const std::vector<Town> list = {
      {"Bern", {46.94806, 7.44778}, 4500},        {"Koeniz", {46.9245, 7.4145}, 2000},
      {"Ostermundigen", {46.9560, 7.4870}, 1500}, {"Muri bei Bern", {46.9310, 7.4860}, 1500},
      {"Ittigen", {46.9740, 7.4830}, 1500},       {"Zollikofen", {47.0000, 7.4580}, 1500},
      {"Belp", {46.8910, 7.4990}, 1200},          {"Muensingen", {46.8730, 7.5610}, 1200},
      {"Thun", {46.7580, 7.6280}, 2500},          {"Burgdorf", {47.0590, 7.6280}, 1500},
      {"Biel/Bienne", {47.1368, 7.2468}, 3000},   {"Solothurn", {47.20833, 7.53722}, 1800},
      {"Fribourg", {46.8065, 7.1620}, 2500},
  };
  return list;
}

bool contains(const GeoPolygon& polygon, GeoPoint point) {
  bool inside = false;
  for (const auto& ring : polygon.rings)
    for (size_t k = 0, n = ring.size(); k < n; ++k) {
      const GeoPoint& a = ring[k];
      const GeoPoint& b = ring[(k + 1) % n];
      if ((a.latitude_deg > point.latitude_deg) != (b.latitude_deg > point.latitude_deg)) {
        const double x = a.longitude_deg + (point.latitude_deg - a.latitude_deg) * (b.longitude_deg - a.longitude_deg) /
                                               (b.latitude_deg - a.latitude_deg);
        if (x > point.longitude_deg) inside = !inside;
      }
    }
  return inside;
}

namespace {

struct Point {
  double x, y;
};
using Ring = std::vector<Point>;

// One level's texel centres: coordinate of index k, and the index range a span covers.
struct Lattice {
  int size;
  double extent, texel;
  double centre(int k) const { return ((2.0 * k + 1) / size - 1) * extent; }
  // Indices whose centres lie within [lo, hi].
  std::pair<int, int> span(double lo, double hi) const {
    const int a = std::max(0, static_cast<int>(std::ceil((lo + extent) / texel - 0.5)));
    const int b = std::min(size - 1, static_cast<int>(std::floor((hi + extent) / texel - 0.5)));
    return {a, b};
  }
};

std::vector<Ring> project(const std::vector<std::vector<GeoPoint>>& rings, const TangentPlane& plane) {
  std::vector<Ring> out;
  for (const auto& ring : rings) {
    Ring r;
    r.reserve(ring.size());
    for (const GeoPoint& p : ring) {
      const auto [x, y] = plane.of(p.latitude_deg, p.longitude_deg);
      r.push_back({x, y});
    }
    out.push_back(std::move(r));
  }
  return out;
}

// Even-odd fill of closed rings: calls fill(i, j) for every texel centre inside.
template <class Fill>
void fill_rings(const std::vector<Ring>& rings, const Lattice& lattice, Fill&& fill) {
  std::vector<std::vector<double>> crossings(lattice.size);
  for (const Ring& ring : rings)
    for (size_t k = 0, n = ring.size(); k < n; ++k) {
      const Point a = ring[k], b = ring[(k + 1) % n];
      if (a.y == b.y) continue;
      const auto [j0, j1] = lattice.span(std::min(a.y, b.y), std::max(a.y, b.y));
      for (int j = j0; j <= j1; ++j) {
        const double y = lattice.centre(j);
        // Half-open in y, so that a vertex on the row is counted once.
        if ((a.y > y) == (b.y > y)) continue;
        crossings[j].push_back(a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y));
      }
    }
  for (int j = 0; j < lattice.size; ++j) {
    auto& xs = crossings[j];
    std::sort(xs.begin(), xs.end());
    for (size_t k = 0; k + 1 < xs.size(); k += 2) {
      const auto [i0, i1] = lattice.span(xs[k], xs[k + 1]);
      for (int i = i0; i <= i1; ++i) fill(i, j);
    }
  }
}

// Calls near(i, j, distance) for every texel centre within `band` of the segment a-b.
template <class Near>
void segment_band(Point a, Point b, double band, const Lattice& lattice, Near&& near) {
  const auto [i0, i1] = lattice.span(std::min(a.x, b.x) - band, std::max(a.x, b.x) + band);
  const auto [j0, j1] = lattice.span(std::min(a.y, b.y) - band, std::max(a.y, b.y) + band);
  const double dx = b.x - a.x, dy = b.y - a.y, length2 = dx * dx + dy * dy;
  for (int j = j0; j <= j1; ++j)
    for (int i = i0; i <= i1; ++i) {
      const double px = lattice.centre(i) - a.x, py = lattice.centre(j) - a.y;
      const double t = length2 > 0 ? std::clamp((px * dx + py * dy) / length2, 0.0, 1.0) : 0.0;
      const double d = std::hypot(px - t * dx, py - t * dy);
      if (d < band) near(i, j, d);
    }
}

}  // namespace

LandCoverGrid land_cover_grid(double latitude_deg, double longitude_deg, double height_m, double earth_radius_m,
                              const LandFeatures& features, int size, double near_extent_m, double far_extent_m) {
  LandCoverGrid grid;
  grid.size = size;
  grid.extent_m[0] = near_extent_m;
  grid.extent_m[1] = far_extent_m;
  grid.source = features.source;
  const size_t n = static_cast<size_t>(size) * size;
  grid.water.resize(land_cover_levels * n);
  grid.urban.resize(land_cover_levels * n);
  grid.lake_surface.assign(n, std::numeric_limits<float>::quiet_NaN());
  const TangentPlane plane(latitude_deg, longitude_deg, height_m, earth_radius_m);

  std::vector<std::vector<Ring>> lakes;
  for (const GeoPolygon& lake : features.lakes) lakes.push_back(project(lake.rings, plane));
  std::vector<Ring> rivers;
  for (const GeoLine& river : features.rivers) rivers.push_back(project({river.points}, plane)[0]);
  std::vector<std::vector<Ring>> municipalities;
  for (const Settlement& s : features.settlements) municipalities.push_back(project(s.municipality.rings, plane));

  for (int level = 0; level < land_cover_levels; ++level) {
    const Lattice lattice{size, grid.extent_m[level], grid.texel_m(level)};
    const double band = grid.band_m(level);
    float* water = grid.water.data() + level * n;
    float* urban = grid.urban.data() + level * n;
    // Distance to the nearest shore and the lake it belongs to; the lake a texel lies in (even-odd
    // per lake, so that lakes that touch do not cancel), -1 for none.
    std::vector<float> shore(n, static_cast<float>(band));
    std::vector<int> nearest(n, -1), inside(n, -1);
    for (size_t l = 0; l < lakes.size(); ++l) {
      std::vector<unsigned char> wet(n, 0);
      fill_rings(lakes[l], lattice, [&](int i, int j) { wet[static_cast<size_t>(j) * size + i] ^= 1; });
      for (size_t k = 0; k < n; ++k)
        if (wet[k]) inside[k] = static_cast<int>(l);
      for (const Ring& ring : lakes[l])
        for (size_t k = 0; k < ring.size(); ++k)
          segment_band(ring[k], ring[(k + 1) % ring.size()], band, lattice, [&](int i, int j, double d) {
            const size_t t = static_cast<size_t>(j) * size + i;
            if (d < shore[t]) {
              shore[t] = static_cast<float>(d);
              nearest[t] = static_cast<int>(l);
            }
          });
    }
    for (size_t k = 0; k < n; ++k) {
      water[k] = inside[k] >= 0 ? -shore[k] : shore[k];
      const int lake = inside[k] >= 0 ? inside[k] : nearest[k];
      if (level == 1 && lake >= 0) grid.lake_surface[k] = static_cast<float>(features.lakes[lake].surface_m);
    }
    // Rivers: the distance to the centre line less the half width, where the level resolves them.
    for (size_t r = 0; r < rivers.size(); ++r) {
      const double half_width = features.rivers[r].half_width_m;
      if (2 * half_width < lattice.texel) continue;
      const Ring& line = rivers[r];
      for (size_t k = 0; k + 1 < line.size(); ++k)
        segment_band(line[k], line[k + 1], band + half_width, lattice, [&](int i, int j, double d) {
          float& w = water[static_cast<size_t>(j) * size + i];
          w = std::min(w, static_cast<float>(d - half_width));
        });
    }
    // Built-up: inside the town's municipality, full within 60 % of its radius, none beyond it.
    std::fill(urban, urban + n, 0.0f);
    for (size_t t = 0; t < features.settlements.size(); ++t) {
      const Town& town = features.settlements[t].town;
      const auto [cx, cy] = plane.of(town.centre.latitude_deg, town.centre.longitude_deg);
      const double radius = town.radius_m;
      fill_rings(municipalities[t], lattice, [&](int i, int j) {
        const double d = std::hypot(lattice.centre(i) - cx, lattice.centre(j) - cy);
        const float f = static_cast<float>(std::clamp((radius - d) / (0.4 * radius), 0.0, 1.0));
        float& u = urban[static_cast<size_t>(j) * size + i];
        u = std::max(u, f);
      });
    }
  }
  return grid;
}

std::pair<double, double> LandCoverGrid::far_lake(double x, double y) const {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (empty()) return {0.0, nan};
  const double texel = texel_m(1);
  const double u = (x + extent_m[1]) / texel - 0.5, v = (y + extent_m[1]) / texel - 0.5;
  if (u < 0 || v < 0 || u > size - 1 || v > size - 1) return {band_m(1), nan};
  const int i = std::min(static_cast<int>(u), size - 2), j = std::min(static_cast<int>(v), size - 2);
  const double fu = u - i, fv = v - j;
  const auto w = [&](int a, int b) { return double(water[index(1, a, b)]); };
  const double distance =
      (1 - fv) * ((1 - fu) * w(i, j) + fu * w(i + 1, j)) + fv * ((1 - fu) * w(i, j + 1) + fu * w(i + 1, j + 1));
  const int ni = static_cast<int>(std::lround(u)), nj = static_cast<int>(std::lround(v));
  return {distance, lake_surface[static_cast<size_t>(nj) * size + ni]};
}

double seasonal_crop_stage(int day_of_year) {
  // (day, stage) at the turns of the year's course.
  static const double course[][2] = {{0, 0}, {80, 0}, {130, 1}, {175, 1}, {200, 2}, {235, 2}, {265, 0}, {367, 0}};
  const double day = std::clamp(double(day_of_year), 0.0, 366.0);
  for (int k = 0; k + 1 < 8; ++k)
    if (day <= course[k + 1][0])
      return course[k][1] +
             (course[k + 1][1] - course[k][1]) * (day - course[k][0]) / (course[k + 1][0] - course[k][0]);
  return 0.0;
}

double seasonal_snow_line_m(int day_of_year) {
  // Lowest on day 45 (14 February), highest half a year later.
  return 2000.0 - 1000.0 * std::cos(2.0 * M_PI * (day_of_year - 45) / 365.25);
}

}  // namespace nephele::regional
