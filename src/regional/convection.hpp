#pragma once
// Convective clouds of the regional scene (docs/convection.md): whether the weather (or, without
// weather files, the global cover and the time of day) calls for towering cumulus or
// cumulonimbus, and where their implicit models (src/model's built-in examples, scaled) stand.
// The renderer turns each placed cloud into a density volume; a scene without convection places
// none, so it computes none.
#include <cstdint>
#include <string>
#include <vector>

#include "model/cloud_model.hpp"
#include "regional/weather.hpp"
#include "regional/weather_field.hpp"

namespace nephele::regional {

enum class ConvectiveKind : int { none = 0, towering = 1, cumulonimbus = 2 };
// "none", "towering" or "cumulonimbus" (the latter two are the names of model examples).
const char* convective_kind_name(ConvectiveKind kind);

// The thresholds (docs/convection.md gives their sources; those marked as assumptions are
// nephele's own).
namespace convection {
// Weather with instability indices (Open-Meteo): a cumulonimbus at CAPE >= 1000 J/kg (the
// usual lower bound of "moderate" instability), a lifted index <= -2 K, or a thunderstorm
// code 95 to 99 of WMO table 4677; towering cumulus at CAPE >= 250 J/kg (assumption) or a
// lifted index <= 0 K.
constexpr double cumulonimbus_cape = 1000, towering_cape = 250;              // J/kg
constexpr double cumulonimbus_lifted_index = -2, towering_lifted_index = 0;  // K, at or below
constexpr int thunderstorm_code_first = 95, thunderstorm_code_last = 99;
// Weather without any of the three fields (meteoblue, older Open-Meteo requests): showers of
// at least 2 mm/h now or within 6 h make a cumulonimbus (the rule of the former convective layer).
constexpr double shower_rate = 2.0;  // mm/h
constexpr double shower_hours = 6.0;
// Without weather (assumptions): convection only between 12 and 19 h local mean solar time, the
// diurnal maximum of convection over land, where the low cover is >= 0.5 (towering cumulus)
// or >= 0.75 (cumulonimbus).
constexpr double afternoon_first_hour = 12, afternoon_last_hour = 19;
constexpr double towering_low_cover = 0.5, cumulonimbus_low_cover = 0.75;
// The convective channel of the weather field holds a strength: 1 cumulonimbus, 0.5 towering
// cumulus, 0 none; blended between stations, >= 0.75 places a cumulonimbus and >= 0.25 a
// towering cumulus (a station with a cumulonimbus and one without give towering cumulus halfway).
constexpr double cumulonimbus_strength = 0.75, towering_strength = 0.25;
// At most this many clouds (MAX_CONVECTIVE of shaders/lib/render_types.glsl).
constexpr int max_clouds = 4;
// Where candidates stand: 15 to 60 km from the camera (the former cumulonimbus layer began at
// 15 km), within 30 degrees either side of the anchor bearing.
constexpr double nearest_m = 15000, farthest_m = 60000, spread_deg = 30;
constexpr int candidates = 16;
// Heights above the ground (the layer rules' ground, Bern's 540 m): the cumulus base of the
// layer rules (1.0 km) for towering cumulus with tops at 6.5 km above sea level; a cumulonimbus
// from 0.8 km above the ground to the tropopause, about 11 km over the Swiss Plateau in summer.
constexpr double towering_base_above_ground = 1000, towering_top = 6500;
constexpr double cumulonimbus_base_above_ground = 800, cumulonimbus_top = 11000;
}  // namespace convection

// What a station's weather calls for, and why.
struct ConvectiveVerdict {
  ConvectiveKind kind = ConvectiveKind::none;
  std::string reason;
};
ConvectiveVerdict convection_from_weather(const WeatherSample& now, const std::vector<WeatherSample>& ahead);
// Without weather: from the low cover at a point, the time (Unix seconds) and the longitude
// (local mean solar time = UTC + longitude / 15 degrees per hour).
ConvectiveVerdict convection_from_cover(double low_cover, double unix_seconds, double longitude_deg);

// The convective channel's value for a kind, and the kind a blended value places.
double convective_strength(ConvectiveKind kind);
ConvectiveKind kind_of_strength(double strength);

// Fills the convective channel of a field made from the global cover with convection_from_cover
// at every texel (its low channel; `longitude_deg` the camera's).
void add_cover_convection(WeatherField& field, double unix_seconds, double longitude_deg);

// One placed cloud: the model example of its kind scaled into a cube of edge extent_m, standing
// on the ground point (east_m, north_m) of the camera's frame, its bottom at bottom_m above the
// sphere, the model's +x (where the anvil spreads) towards axis_deg (clockwise from north).
struct ConvectiveCloud {
  ConvectiveKind kind = ConvectiveKind::none;
  double east_m = 0, north_m = 0;
  double bottom_m = 0, extent_m = 0;
  double cloud_base_m = 0, cloud_top_m = 0;  // the model's lowest and highest radius edge
  double axis_deg = 0;
  model::CloudModel model;
  std::string reason;
};

// The lowest and highest points of the model's primitives' radii (model units; the field is 1
// within a radius, so the visible cloud's base and top are about there), within the model's
// flat base and top.
void vertical_span(const model::CloudModel& model, double& lowest, double& highest);

// Deterministic from the seed: candidates at hashed bearings within spread_deg of
// anchor_bearing_deg and distances nearest_m to farthest_m; a candidate stands where the field's
// convective channel places a kind (kind_of_strength) and its box keeps clear of those placed
// before; at most max_clouds. The anvil points downwind (wind_towards_deg). Empty when the
// field has no convection.
std::vector<ConvectiveCloud> place_convective_clouds(const WeatherField& field, double anchor_bearing_deg,
                                                     double wind_towards_deg, std::uint32_t seed, double ground_m);

}  // namespace nephele::regional
