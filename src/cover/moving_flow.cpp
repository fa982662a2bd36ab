#include "cover/moving_flow.hpp"

#include <algorithm>
#include <cmath>

#include "core/time.hpp"

namespace nephele::cover {

const char* flow_name(Flow flow) { return flow == Flow::moving ? "moving" : "steady"; }

std::optional<Flow> parse_flow(const std::string& name) {
  if (name == "steady") return Flow::steady;
  if (name == "moving") return Flow::moving;
  return std::nullopt;
}

double hours_since_epoch(const std::string& iso_time) {
  static const double epoch = core::parse_utc_time(flow_epoch);
  return (core::parse_utc_time(iso_time) - epoch) / 3600.0;
}

FrameClock frame_clock(const CoverParameters& p, double hours) {
  FrameClock clock;
  const double t = hours / flow_hours_per_unit;
  // Generations are centred on multiples of L, half the vortices' lifetime.
  const double generation = 0.5 * p.vortex_lifetime / flow_hours_per_unit;
  const double origin = std::floor(t / generation);
  clock.motion.generation_time = static_cast<float>(generation);
  clock.motion.origin = static_cast<int>(origin);
  clock.motion.drift = 1.0f;
  clock.time = static_cast<float>(t - origin * generation);
  // Cloud layers: born every T/2, layer j at j T/2; the younger of the two alive is aged
  // [T/2, T), the older [T, 3T/2).
  const double flow_time = static_cast<double>(p.iterations) * p.step;
  const double period = 0.5 * flow_time;
  const double young = std::floor(t / period) - 1.0;
  const double young_age = t - young * period;
  clock.young_layer = static_cast<std::int64_t>(young);
  clock.young_age = static_cast<float>(young_age);
  clock.old_age = static_cast<float>(young_age + period);
  const double rise = std::sin(0.5 * M_PI * (young_age - period) / period);
  clock.young_share = static_cast<float>(rise * rise);
  clock.steps = std::max(1, static_cast<int>(std::ceil(3.0 * period / p.step - 1e-9)));
  const double spacing = 0.5 * static_cast<double>(p.step);
  const double first = std::floor((t - young_age - period) / spacing), last = std::ceil(t / spacing);
  clock.node_spacing = static_cast<float>(spacing);
  clock.first_node_time = static_cast<float>(first * spacing - origin * generation);
  clock.nodes = static_cast<int>(last - first) + 1;
  clock.first_node = static_cast<std::int64_t>(first);
  return clock;
}

NodeTime node_time(const CoverParameters& p, std::int64_t node) {
  const double generation = 0.5 * p.vortex_lifetime / flow_hours_per_unit;
  const double t = static_cast<double>(node) * 0.5 * static_cast<double>(p.step);
  const double origin = std::floor(t / generation);
  NodeTime out;
  out.motion.generation_time = static_cast<float>(generation);
  out.motion.origin = static_cast<int>(origin);
  out.motion.drift = 1.0f;
  out.time = static_cast<float>(t - origin * generation);
  return out;
}

glsl::FbmParams layer_density_params(const CoverParameters& p, std::int64_t layer) {
  // The index wraps to 32 bits in the hash, as generations do: 2^32 layers of hours apart.
  return glsl::generation_noise(density_params(p), static_cast<int>(static_cast<std::uint32_t>(layer)));
}

}  // namespace nephele::cover
