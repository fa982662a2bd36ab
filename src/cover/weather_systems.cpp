#include "cover/weather_systems.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "cover/latitude_profile.hpp"
#include "cover/moving_flow.hpp"
#include "params/table.hpp"

namespace nephele::cover {
namespace {

constexpr double degree = M_PI / 180.0;
// n + 1 cyclones alive per hemisphere at most (weather_systems.hpp), for the table's largest n.
static_assert(2 * (params::cover::cyclones.max + 1) <= MAX_CYCLONES);
constexpr double earth_radius_km = 6371.0;

// Three uniform numbers in [0, 1) for a slot of a hemisphere (slots may be negative: before the
// epoch).
glsl::vec3 slot_random(std::uint32_t seed, std::int64_t slot, int hemisphere, std::uint32_t salt) {
  const auto s = static_cast<std::uint64_t>(slot);
  return glsl::hash_to_unit3(glsl::pcg3d(
      glsl::uvec3(seed ^ salt, static_cast<std::uint32_t>(s), static_cast<std::uint32_t>(s >> 32) * 2u + hemisphere)));
}

glsl::Cyclone make_cyclone(double latitude_deg, double longitude_deg, double radius_km, double age_fraction) {
  const double lat = latitude_deg * degree, lon = longitude_deg * degree;
  const float sign = latitude_deg >= 0.0 ? 1.0f : -1.0f;
  glsl::Cyclone c;
  c.centre = glsl::vec3(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat));
  c.east = glsl::vec3(-std::sin(lon), std::cos(lon), 0.0);
  c.pole = sign * glsl::vec3(-std::sin(lat) * std::cos(lon), -std::sin(lat) * std::sin(lon), std::cos(lat));
  c.radius = static_cast<float>(radius_km / earth_radius_km);
  c.wrap = cyclone_wrap(age_fraction);
  c.strength = cyclone_strength(age_fraction);
  return c;
}

// A cyclone's centre `age` hours after its genesis at (latitude, longitude), degrees, in its own
// hemisphere's latitude (positive): east at its speed along the mean latitude of its way so far,
// poleward by its drift.
struct TrackPoint {
  double latitude, longitude;
};
TrackPoint track_point(double genesis_lat, double genesis_lon, double age) {
  const double a = age / cyclone_lifetime_hours;
  const double mean_cos = std::cos((genesis_lat + 0.5 * cyclone_poleward_deg * a) * degree);
  const double east_deg = cyclone_speed_m_s * 3.6 * age / (earth_radius_km * mean_cos) / degree;
  return {genesis_lat + cyclone_poleward_deg * a, genesis_lon + east_deg};
}

// The mask's land fraction in the cell holding (latitude, longitude), degrees.
double land_at(const SurfaceMask& mask, double latitude, double longitude) {
  const double turn = (longitude + 180.0) / 360.0;
  const int column = static_cast<int>(std::floor((turn - std::floor(turn)) * mask.columns)) % mask.columns;
  const int row = std::clamp(static_cast<int>(std::floor((90.0 - latitude) / 180.0 * mask.rows)), 0, mask.rows - 1);
  return mask.land[static_cast<size_t>(row) * mask.columns + column];
}

// A genesis longitude over a mask: candidate k (360 first for k = 0, 360 r_k.y after) is taken
// with probability s, the ocean's share of its mature track (r_k.x < s); after eight refusals,
// the candidate of the largest share. `random(k)` gives r_k, three uniform numbers of the slot.
template <typename Random>
double genesis_longitude(const SurfaceMask& mask, double genesis_lat, double first, Random random) {
  constexpr int tries = 8;
  double best = 360.0 * first, best_share = -1.0;
  for (int k = 0; k < tries; ++k) {
    const glsl::vec3 r = random(k);
    const double longitude = 360.0 * (k == 0 ? first : r.y);
    const double share = mature_ocean_share(mask, genesis_lat, longitude);
    if (r.x < share) return longitude;
    if (share > best_share) best = longitude, best_share = share;
  }
  return best;
}

}  // namespace

double mature_ocean_share(const SurfaceMask& mask, double genesis_lat, double genesis_lon) {
  // Eight moments of the mature life (strength 1: ages 0.2-0.67 of the lifetime), each the
  // centre and four points 5 degrees (about 550 km, half the smallest head radius) around it.
  constexpr int moments = 8;
  constexpr double core_deg = 5.0;
  const double sign = genesis_lat >= 0.0 ? 1.0 : -1.0;
  double ocean = 0.0;
  for (int k = 0; k < moments; ++k) {
    const double a = 0.2 + (k + 0.5) / moments * (0.67 - 0.2);
    const TrackPoint c = track_point(std::abs(genesis_lat), genesis_lon, a * cyclone_lifetime_hours);
    const double lat = sign * c.latitude, east = core_deg / std::cos(c.latitude * degree);
    ocean += 5.0 - land_at(mask, lat, c.longitude) - land_at(mask, lat + core_deg, c.longitude) -
             land_at(mask, lat - core_deg, c.longitude) - land_at(mask, lat, c.longitude + east) -
             land_at(mask, lat, c.longitude - east);
  }
  return ocean / (5.0 * moments);
}

float cyclone_strength(double a) {
  return static_cast<float>(glm::smoothstep(0.0, 0.2, a)) * (1.0f - static_cast<float>(glm::smoothstep(0.67, 1.0, a)));
}

float cyclone_wrap(double a) { return static_cast<float>(M_PI * (0.5 + 0.75 * std::clamp(a, 0.0, 1.0))); }

glsl::LineWaves moved_line_waves(glsl::LineWaves waves, double hours, double loop_hours) {
  // A wave |c| cos(m lon - arg c) moving east at angular speed w is c e^(i m w t) at time t: it
  // turns m w / (2 pi) times an hour, with a loop a whole number of times in it.
  for (int k = 0; k < glsl::LINE_WAVES; ++k) {
    const int m = glsl::LINE_FIRST_WAVENUMBER + k;
    const auto turn = [&](glsl::vec2 c, double speed_m_s) {
      double turns_per_hour = m * speed_m_s / (earth_radius_km * 1000.0) * 3600.0 / (2.0 * M_PI);
      if (loop_hours > 0.0) turns_per_hour = std::round(turns_per_hour * loop_hours) / loop_hours;
      const double angle = 2.0 * M_PI * std::fmod(turns_per_hour * hours, 1.0);
      const double cs = std::cos(angle), sn = std::sin(angle);
      return glsl::vec2(static_cast<float>(c.x * cs - c.y * sn), static_cast<float>(c.x * sn + c.y * cs));
    };
    waves.meander[k] = turn(waves.meander[k], itcz_meander_speed_m_s);
    waves.envelope[k] = turn(waves.envelope[k], supercluster_speed_m_s);
  }
  return waves;
}

float spcz_season(int month) { return static_cast<float>(0.75 - 0.25 * seasonal_phase(month)); }

double monsoon_target(const SurfaceMask& mask, int month, double line, double lon) {
  const double land_lat = monsoon_land_deg * seasonal_phase(month);
  double land = 0.0;
  int samples = 0;
  for (int i = -10; i <= 10; ++i)
    for (int j = -5; j <= 5; ++j, ++samples) land += land_at(mask, land_lat + i, lon / degree + 2.0 * j);
  return land / samples * (land_lat * degree - line);
}

glsl::LineWaves with_monsoons(glsl::LineWaves waves, const SurfaceMask& mask, int month, double line) {
  constexpr int n = 360;
  std::vector<double> target(n);
  for (int j = 0; j < n; ++j) target[j] = monsoon_target(mask, month, line, 2.0 * M_PI * j / n);
  // Fourier coefficients: a term dot(c, (cos m lon, sin m lon)) with c = (2 / n) sum f e^(i m lon)
  // (conjugated into the dot), times Lanczos' sigma sinc(m / (M + 1)).
  const double z = std::cos(line);
  double mean = 0.0;
  for (double f : target) mean += f / n;
  waves.monsoon_mean = static_cast<float>(z * mean);
  for (int m = 1; m <= glsl::MONSOON_WAVES; ++m) {
    double c = 0.0, s = 0.0;
    for (int j = 0; j < n; ++j) {
      c += 2.0 / n * target[j] * std::cos(2.0 * M_PI * m * j / n);
      s += 2.0 / n * target[j] * std::sin(2.0 * M_PI * m * j / n);
    }
    const double x = M_PI * m / (glsl::MONSOON_WAVES + 1), sigma = std::sin(x) / x;
    waves.monsoon[m - 1] = glsl::vec2(static_cast<float>(z * sigma * c), static_cast<float>(z * sigma * s));
  }
  // The reach: the sum's largest size over a fine circle, in radians, with a margin for the
  // float sums and the points between.
  double reach = 0.0;
  for (int j = 0; j < 4 * n; ++j) {
    const double lon = 2.0 * M_PI * j / (4 * n);
    const glsl::vec3 p(static_cast<float>(std::cos(lon)), static_cast<float>(std::sin(lon)), 0.0f);
    reach = std::max(reach, std::abs(static_cast<double>(glsl::line_waves(p, waves).z)) / z);
  }
  waves.monsoon_reach = static_cast<float>(reach + 0.01);
  return waves;
}

glsl::WeatherSystems weather_systems(const CoverParameters& p, double hours) {
  glsl::WeatherSystems w{};
  const std::uint32_t seed = layer_seed(p.seed, NoiseLayer::weather_systems);
  w.seed = seed;
  w.itcz = p.itcz;
  w.trade_cumulus = p.trade_cumulus;
  w.cirrus = p.cirrus;
  w.shallow_trades = p.shallow_trades;
  w.cells = p.stratocumulus_cells;
  w.streets = p.cloud_streets;
  // The ITCZ's annual-mean line near 5 N (Waliser and Gautier 1993), moved with the profile's
  // seasonal shift there.
  w.itcz_latitude = static_cast<float>((5.0 + seasonal_shift_deg(5.0, p.month)) * degree);
  w.itcz_waves = moved_line_waves(glsl::line_waves_of(seed, w.itcz_latitude), hours, p.loop_hours);
  if (p.surface) {
    w.itcz_waves = with_monsoons(w.itcz_waves, *p.surface, p.month, w.itcz_latitude);
    w.itcz_waves.spcz = p.spcz * spcz_season(p.month);
    w.itcz_waves.spcz_shift = static_cast<float>(seasonal_shift_deg(spcz_mid_latitude_deg, p.month) * degree);
  }
  if (p.cyclones <= 0) return w;
  const double lifetime = cyclone_lifetime_hours;
  double spacing = lifetime / p.cyclones;
  // With a loop, a whole number of slots fits it and slot k + n is slot k again, a loop later.
  std::int64_t slots_in_loop = 0;
  if (p.loop_hours > 0.0) {
    slots_in_loop = std::max<std::int64_t>(1, std::llround(p.loop_hours / spacing));
    spacing = p.loop_hours / static_cast<double>(slots_in_loop);
  }
  const double track_deg = 38.0 + seasonal_shift_deg(50.0, p.month);
  const auto first = static_cast<std::int64_t>(std::floor((hours - lifetime) / spacing)) - 1;
  const auto last = static_cast<std::int64_t>(std::floor(hours / spacing));
  for (int hemisphere = 0; hemisphere < 2; ++hemisphere) {
    for (std::int64_t slot = first; slot <= last && w.cyclone_count < MAX_CYCLONES; ++slot) {
      std::int64_t named = slot;
      if (slots_in_loop > 0) named = ((slot % slots_in_loop) + slots_in_loop) % slots_in_loop;
      const glsl::vec3 u = slot_random(seed, named, hemisphere, 0x68E31DA4u);
      const glsl::vec3 v = slot_random(seed, named, hemisphere, 0xB5297A4Du);
      const double genesis = (static_cast<double>(slot) + 0.8 * u.x) * spacing;
      const double age = hours - genesis;
      if (age < 0.0 || age >= lifetime) continue;
      const double a = age / lifetime;
      // In the south the tracks move with the season as the north's do (the profile's shift).
      const double genesis_lat = (hemisphere == 0 ? track_deg : 76.0 - track_deg) + 12.0 * (u.y - 0.5);
      const double genesis_lon =
          p.surface ? genesis_longitude(*p.surface, hemisphere == 0 ? genesis_lat : -genesis_lat, u.z,
                                        [&](int k) { return slot_random(seed, named, hemisphere, 0x2C1B3C6Du + k); })
                    : 360.0 * u.z;
      const TrackPoint c = track_point(genesis_lat, genesis_lon, age);
      const double radius_km = (900.0 + 600.0 * v.x) * (0.7 + 0.3 * cyclone_strength(a));
      w.cyclones[w.cyclone_count++] =
          make_cyclone(hemisphere == 0 ? c.latitude : -c.latitude, c.longitude, radius_km, a);
    }
  }
  return w;
}

std::uint32_t layer_systems_seed(const CoverParameters& p, std::int64_t layer, int layers_in_loop) {
  return glsl::pcg3d(glsl::uvec3(layer_density_params(p, layer, layers_in_loop).seed, 0x57A7E5u, 0u)).x;
}

CellPatterns cell_patterns_drawn(const CoverParameters& p) {
  // As the shader computes it: texels 2 / size radians across at a face's centre, in float.
  const float texel_arc = 2.0f / static_cast<float>(p.size);
  const bool cells = p.stratocumulus_cells > 0.0f;
  return {cells && glsl::cells_resolved(glsl::CLOSED_CELLS, texel_arc) > 0.0f,
          cells && glsl::cells_resolved(glsl::OPEN_CELLS, texel_arc) > 0.0f,
          p.cloud_streets > 0.0f && p.cyclones > 0 && glsl::cells_resolved(glsl::STREETS, texel_arc) > 0.0f};
}

}  // namespace nephele::cover
