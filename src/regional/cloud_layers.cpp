#include "regional/cloud_layers.hpp"

#include <algorithm>
#include <cmath>

#include "regional/convection.hpp"

namespace nephele::regional {
namespace {

double max_mid_cover(const std::vector<WeatherSample>& hours, double within_hours, double from) {
  double m = 0;
  for (const auto& h : hours)
    if (h.time <= from + within_hours * 3600) m = std::max(m, h.cloud_mid);
  return m;
}

bool is_foggy(const WeatherSample& now) {
  // Radiation fog: low cover nearly total, calm air, no rain.
  return now.may_be_fog && now.cloud_low >= 0.95 && (!now.has_wind || now.wind_speed < 3.0) && now.precipitation < 0.1;
}

}  // namespace

const char* cloud_type_name(CloudType type) {
  switch (type) {
    case CloudType::cirrus: return "cirrus";
    case CloudType::cirrostratus: return "cirrostratus";
    case CloudType::cirrocumulus: return "cirrocumulus";
    case CloudType::alto: return "alto";
    case CloudType::cumulus: return "cumulus";
    case CloudType::stratocumulus: return "stratocumulus";
    case CloudType::stratus: return "stratus";
    case CloudType::fog: return "fog";
  }
  return "?";
}

StationCoverage station_coverage(const WeatherSample& now, const std::vector<WeatherSample>& ahead) {
  StationCoverage c;
  c.channel[int(CoverageChannel::high)] = now.cloud_high;
  c.channel[int(CoverageChannel::mid)] = now.cloud_mid;
  c.channel[int(CoverageChannel::low)] = now.cloud_low;
  c.channel[int(CoverageChannel::fog)] = is_foggy(now) ? 1.0 : 0.0;
  // Convective towers (docs/convection.md): the strength of what the station's weather calls for.
  c.channel[int(CoverageChannel::convective)] = convective_strength(convection_from_weather(now, ahead).kind);
  return c;
}

std::vector<CloudLayer> choose_layers(const WeatherSample& now, const std::vector<WeatherSample>& ahead,
                                      const LayerRules& rules) {
  std::vector<CloudLayer> layers;
  const double rain_ahead = max_precipitation(ahead, 6, now.time);
  const bool nimbostratus = now.precipitation >= 0.5 && now.cloud_mid >= 0.8;

  // High layer, 8-12 km (Open-Meteo's split: above 8 km).
  if (now.cloud_high >= layer_threshold) {
    const double mid_rise = max_mid_cover(ahead, 12, now.time) - now.cloud_mid;
    if (now.cloud_high >= 0.7 || mid_rise >= 0.3)
      layers.push_back(
          {CloudType::cirrostratus, CoverageChannel::high, 8500, 9500, 5e-4f, 0, 0, 0,
           now.cloud_high >= 0.7 ? "high cover >= 70%: veil" : "mid cover rising within 12 h: warm front veil"});
    else if (now.cloud_high >= 0.2 && now.cloud_high < 0.5 && now.cloud_mid < 0.2 && now.cloud_low < 0.3)
      layers.push_back({CloudType::cirrocumulus, CoverageChannel::high, 8000, 8600, 3e-3f, 0, 0, 0,
                        "high cover 20-50% with little below: small cells"});
    else
      layers.push_back({CloudType::cirrus, CoverageChannel::high, 8500, 10500, 1e-3f, 0, 0, 0, "high cover: fibres"});
  }
  // Mid layer, 3-8 km: Webanck et al.'s altostratus-altocumulus morph.
  if (now.cloud_mid >= layer_threshold) {
    float k = static_cast<float>(std::clamp((0.9 - now.cloud_mid) / 0.6, 0.0, 1.0));
    std::string why = "mid cover: k from cover (broken -> altocumulus, overcast -> altostratus)";
    if (rain_ahead > 0.2) {
      k *= 0.5f;
      why += ", halved: rain within 6 h thickens altostratus";
    }
    if (nimbostratus)
      layers.push_back({CloudType::alto, CoverageChannel::mid, 2500, 5500, 2e-2f, 0.0f, 0.6f, 0,
                        "rain with mid cover >= 80%: nimbostratus substitute (dark thick altostratus)"});
    else
      layers.push_back({CloudType::alto, CoverageChannel::mid, 3500, 5000, 1e-2f, k, 0, 0, why});
  }
  // Low layer, up to 3 km.
  const double low = nimbostratus ? std::max(now.cloud_low, 0.8) : now.cloud_low;
  if (low >= layer_threshold && !is_foggy(now)) {
    const float ground = static_cast<float>(rules.ground_m);
    if (low >= 0.9 || nimbostratus || (now.precipitation > 0.1 && low > 0.7))
      layers.push_back(
          {CloudType::stratus, CoverageChannel::low, ground + 300, ground + 900, 2e-2f, 0, nimbostratus ? 0.4f : 0.0f,
           0, nimbostratus ? "nimbostratus substitute: stratus below" : "low cover >= 90% or drizzle: stratus"});
    else if (low >= 0.6)
      layers.push_back({CloudType::stratocumulus, CoverageChannel::low, ground + 700, ground + 1400, 3e-2f, 0, 0, 0,
                        "low cover 60-90%: stratocumulus"});
    else
      layers.push_back({CloudType::cumulus, CoverageChannel::low, ground + 1000, ground + 2500, 4e-2f, 0, 0, 0,
                        "low cover below 60%: cumulus"});
  }
  // Ground fog (and denser fog under nimbostratus).
  if (is_foggy(now) || nimbostratus)
    layers.push_back({CloudType::fog, CoverageChannel::fog, static_cast<float>(rules.ground_m) - 50,
                      static_cast<float>(std::max(rules.fog_top_m, rules.ground_m + 50)), nimbostratus ? 3e-2f : 2e-2f,
                      0, 0, 0, nimbostratus ? "rain: denser fog" : "low cover >= 95%, calm, dry: ground fog"});
  // Towering cumulus and cumulonimbus are no layer: implicit models placed where the convective
  // channel calls for them (regional/convection.hpp).
  return layers;
}

}  // namespace nephele::regional
