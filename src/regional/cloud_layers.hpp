#pragma once
// Cloud layers and the rules that choose them from the weather.
#include <string>
#include <vector>

#include "params/table.hpp"

#include "regional/weather.hpp"

namespace nephele::regional {

// Must match the CLOUD_* constants in shaders/lib/cloud_density.glsl.
enum class CloudType : int {
  cirrus = 0,
  cirrostratus = 1,
  cirrocumulus = 2,
  alto = 3,  // altostratus (morph 0) to altocumulus (morph 1), Webanck et al.'s k
  cumulus = 4,
  stratocumulus = 5,
  stratus = 6,
  fog = 7,
  // (8 was the cumulonimbus layer: convective clouds are implicit models now, convection.hpp)
};
const char* cloud_type_name(CloudType type);

// Which coverage channel of the weather field drives a layer.
enum class CoverageChannel : int { high = 0, mid = 1, low = 2, fog = 3, convective = 4 };
inline constexpr int coverage_channels = 5;

struct CloudLayer {
  CloudType type;
  CoverageChannel channel;
  float base_m, top_m;       // altitude above the ellipsoid
  float extinction;          // 1/m at density 1
  float morph = 0;           // alto: 0 altostratus .. 1 altocumulus
  float darkness = 0;        // 0 normal .. 1 black (nimbostratus substitute darkens)
  float min_distance_m = 0;  // the layer starts this far from the camera (no rule uses it today)
  std::string reason;        // the rule that chose it
};

struct LayerRules {
  double ground_m = 540;                                     // terrain height for fog and the low layer (Bern)
  double fog_top_m = params::scene::fog_top.default_number;  // top of the ground fog (sea of fog)
};

// Coverage of each channel at one station, in [0, 1].
struct StationCoverage {
  double channel[coverage_channels] = {0, 0, 0, 0, 0};
};

// The least cover of a channel that makes a layer (docs/layers.md).
inline constexpr double layer_threshold = 0.05;

// Layer types from the current hour and the hours ahead (up to 7 days), with the reason for
// each choice. Thresholds are documented in docs/layers.md.
std::vector<CloudLayer> choose_layers(const WeatherSample& now, const std::vector<WeatherSample>& ahead,
                                      const LayerRules& rules = {});
// Coverage channels of one station's weather at one time.
StationCoverage station_coverage(const WeatherSample& now, const std::vector<WeatherSample>& ahead);

}  // namespace nephele::regional
