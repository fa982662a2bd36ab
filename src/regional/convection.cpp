#include "regional/convection.hpp"

#include <algorithm>
#include <cmath>

#include "regional/cloud_layers.hpp"
#include "shader_math/shader_math.hpp"

namespace nephele::regional {
namespace {

// The field's channel at a ground point, bilinear between texel centres and clamped to the edge
// (as the renderer's sampler reads it).
double field_value(const WeatherField& field, int channel, double east, double north) {
  const double x = std::clamp((east / field.extent_m + 1.0) * 0.5 * field.size - 0.5, 0.0, field.size - 1.0);
  const double y = std::clamp((north / field.extent_m + 1.0) * 0.5 * field.size - 0.5, 0.0, field.size - 1.0);
  const int i = std::min(static_cast<int>(x), field.size - 2), j = std::min(static_cast<int>(y), field.size - 2);
  const double fx = x - i, fy = y - j;
  auto at = [&](int c, int r) { return double(field.at(channel, c, r)); };
  return (1 - fy) * ((1 - fx) * at(i, j) + fx * at(i + 1, j)) + fy * ((1 - fx) * at(i, j + 1) + fx * at(i + 1, j + 1));
}

}  // namespace

const char* convective_kind_name(ConvectiveKind kind) {
  switch (kind) {
    case ConvectiveKind::none: return "none";
    case ConvectiveKind::towering: return "towering";
    case ConvectiveKind::cumulonimbus: return "cumulonimbus";
  }
  return "?";
}

ConvectiveVerdict convection_from_weather(const WeatherSample& now, const std::vector<WeatherSample>& ahead) {
  using namespace convection;
  if (now.has_weather_code && now.weather_code >= thunderstorm_code_first && now.weather_code <= thunderstorm_code_last)
    return {ConvectiveKind::cumulonimbus,
            "weather_code " + std::to_string(now.weather_code) + " (95-99): thunderstorm"};
  if (now.has_cape && now.cape >= cumulonimbus_cape)
    return {ConvectiveKind::cumulonimbus, "cape >= 1000 J/kg: deep convection"};
  if (now.has_lifted_index && now.lifted_index <= cumulonimbus_lifted_index)
    return {ConvectiveKind::cumulonimbus, "lifted_index <= -2 K: deep convection"};
  if (now.has_cape && now.cape >= towering_cape)
    return {ConvectiveKind::towering, "cape 250-1000 J/kg: towering cumulus"};
  if (now.has_lifted_index && now.lifted_index <= towering_lifted_index)
    return {ConvectiveKind::towering, "lifted_index -2 to 0 K: towering cumulus"};
  if (now.has_cape || now.has_lifted_index || now.has_weather_code) return {};
  // Without instability indices, heavy showers are the sign of convection.
  if (std::max(now.precipitation, max_precipitation(ahead, shower_hours, now.time)) >= shower_rate)
    return {ConvectiveKind::cumulonimbus, "no cape, lifted_index or weather_code; showers >= 2 mm/h now or within 6 h"};
  return {};
}

ConvectiveVerdict convection_from_cover(double low_cover, double unix_seconds, double longitude_deg) {
  using namespace convection;
  // Local mean solar time in hours, in [0, 24).
  const double hours = std::fmod(std::fmod(unix_seconds / 3600.0 + longitude_deg / 15.0, 24.0) + 24.0, 24.0);
  if (hours < afternoon_first_hour || hours >= afternoon_last_hour) return {};
  if (low_cover >= cumulonimbus_low_cover)
    return {ConvectiveKind::cumulonimbus, "global cover: afternoon (12-19 h solar time), low cover >= 0.75"};
  if (low_cover >= towering_low_cover)
    return {ConvectiveKind::towering, "global cover: afternoon (12-19 h solar time), low cover 0.5-0.75"};
  return {};
}

double convective_strength(ConvectiveKind kind) {
  return kind == ConvectiveKind::cumulonimbus ? 1.0 : kind == ConvectiveKind::towering ? 0.5 : 0.0;
}

ConvectiveKind kind_of_strength(double strength) {
  if (strength >= convection::cumulonimbus_strength) return ConvectiveKind::cumulonimbus;
  if (strength >= convection::towering_strength) return ConvectiveKind::towering;
  return ConvectiveKind::none;
}

void add_cover_convection(WeatherField& field, double unix_seconds, double longitude_deg) {
  for (int row = 0; row < field.size; ++row)
    for (int column = 0; column < field.size; ++column) {
      const double low = field.at(int(CoverageChannel::low), column, row);
      const double strength = convective_strength(convection_from_cover(low, unix_seconds, longitude_deg).kind);
      field.values[(static_cast<size_t>(CoverageChannel::convective) * field.size + row) * field.size + column] =
          static_cast<float>(strength);
    }
}

void vertical_span(const model::CloudModel& model, double& lowest, double& highest) {
  lowest = 1e30;
  highest = -1e30;
  for (const auto& p : model.primitives) {
    lowest = std::min(lowest, double(std::min(p.from.z, p.to.z) - p.radius));
    highest = std::max(highest, double(std::max(p.from.z, p.to.z) + p.radius));
  }
  // The flat base and top cut the field (model_levels).
  lowest = std::max(lowest, double(model.base));
  highest = std::min(highest, double(model.top));
}

std::vector<ConvectiveCloud> place_convective_clouds(const WeatherField& field, double anchor_bearing_deg,
                                                     double wind_towards_deg, std::uint32_t seed, double ground_m) {
  using namespace convection;
  std::vector<ConvectiveCloud> clouds;
  if (field.size < 2 || field.max_of(int(CoverageChannel::convective)) < towering_strength) return clouds;
  for (int i = 0; i < candidates && static_cast<int>(clouds.size()) < max_clouds; ++i) {
    // Three independent uniforms per candidate: bearing, distance, size.
    const glsl::vec3 u = glsl::hash_to_unit3(glsl::pcg3d(glsl::uvec3(seed, std::uint32_t(i), 0xC0A7u)));
    const double bearing = (anchor_bearing_deg + (2.0 * u.x - 1.0) * spread_deg) * M_PI / 180;
    const double distance = nearest_m + u.y * (farthest_m - nearest_m);
    ConvectiveCloud c;
    c.east_m = distance * std::sin(bearing);
    c.north_m = distance * std::cos(bearing);
    c.kind = kind_of_strength(field_value(field, int(CoverageChannel::convective), c.east_m, c.north_m));
    if (c.kind == ConvectiveKind::none) continue;
    const bool cb = c.kind == ConvectiveKind::cumulonimbus;
    c.model = model::example(convective_kind_name(c.kind));
    // The example scaled so that its radius edges reach from the cloud base to the top, the
    // top varied by +-10 % so that clouds differ.
    double lowest = 0, highest = 0;
    vertical_span(c.model, lowest, highest);
    c.cloud_base_m = ground_m + (cb ? cumulonimbus_base_above_ground : towering_base_above_ground);
    const double top = (cb ? cumulonimbus_top : towering_top) * (0.9 + 0.2 * u.z);
    c.extent_m = (top - c.cloud_base_m) / (highest - lowest);
    c.bottom_m = c.cloud_base_m - lowest * c.extent_m;
    c.cloud_top_m = c.bottom_m + highest * c.extent_m;
    c.axis_deg = wind_towards_deg;
    c.model.extent_m = c.extent_m;
    // Each cloud its own turbulence: the primitives' seeds moved by the candidate's hash (kept
    // below the table's 2^24, exact in the shader's float).
    const std::uint32_t shift = glsl::pcg3d(glsl::uvec3(seed, std::uint32_t(i), 0x5EEDu)).x & 0xFFFFu;
    for (auto& p : c.model.primitives) p.noise.seed = (p.noise.seed + shift) & 0xFFFFFFu;
    // Boxes keep clear of each other: footprints (cubes turned alike) do not overlap.
    bool clear = true;
    for (const auto& other : clouds)
      if (std::hypot(other.east_m - c.east_m, other.north_m - c.north_m) <
          0.5 * (other.extent_m + c.extent_m) * std::sqrt(2.0))
        clear = false;
    if (!clear) continue;
    c.reason = std::string(cb ? "cumulonimbus" : "towering cumulus") + " where the convective channel is " +
               (cb ? ">= 0.75" : "0.25-0.75");
    clouds.push_back(std::move(c));
  }
  return clouds;
}

}  // namespace nephele::regional
