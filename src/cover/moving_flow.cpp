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

namespace {

// The flow's periods in flow units: the vortices' generation time L, the cloud layers' period
// T/2 and the time nodes' spacing h/2; with --loop each rounded to a whole fraction of the loop
// (at least 2 generations and layers), and the generations' count in the loop.
struct Periods {
  double generation, layer, node;
  int generations = 0, layers = 0;
};

Periods periods(const CoverParameters& p) {
  Periods out;
  out.generation = 0.5 * p.vortex_lifetime / flow_hours_per_unit;
  out.layer = 0.5 * static_cast<double>(p.iterations) * p.step;
  out.node = 0.5 * static_cast<double>(p.step);
  const double loop = p.loop_hours / flow_hours_per_unit;
  if (loop > 0) {
    out.generations = std::max(2, int(std::lround(loop / out.generation)));
    out.generation = loop / out.generations;
    out.layers = std::max(2, int(std::lround(loop / out.layer)));
    out.layer = loop / out.layers;
    out.node = loop / std::max(1.0, double(std::lround(loop / out.node)));
  }
  return out;
}

glsl::FlowMotion motion_at(const Periods& periods, double origin) {
  glsl::FlowMotion motion;
  motion.generation_time = static_cast<float>(periods.generation);
  motion.origin = static_cast<int>(origin);
  motion.drift = 1.0f;
  motion.generations = periods.generations;
  return motion;
}

}  // namespace

FrameClock frame_clock(const CoverParameters& p, double hours) {
  FrameClock clock;
  const Periods times = periods(p);
  const double t = hours / flow_hours_per_unit;
  // Generations are centred on multiples of L, half the vortices' lifetime.
  const double generation = times.generation;
  const double origin = std::floor(t / generation);
  clock.motion = motion_at(times, origin);
  clock.time = static_cast<float>(t - origin * generation);
  // Cloud layers: born every T/2, layer j at j T/2; the younger of the two alive is aged
  // [T/2, T), the older [T, 3T/2).
  const double period = times.layer;
  const double young = std::floor(t / period) - 1.0;
  const double young_age = t - young * period;
  clock.young_layer = static_cast<std::int64_t>(young);
  clock.young_age = static_cast<float>(young_age);
  clock.old_age = static_cast<float>(young_age + period);
  const double rise = std::sin(0.5 * M_PI * (young_age - period) / period);
  clock.young_share = static_cast<float>(rise * rise);
  const auto steps_for = [&](double span) { return std::max(1, int(std::ceil(span / p.step - 1e-9))); };
  clock.young_steps = steps_for(2.0 * period);
  clock.older_steps = steps_for(period);
  clock.layers_in_loop = times.layers;
  const double spacing = times.node;
  const double first = std::floor((t - young_age - period) / spacing), last = std::ceil(t / spacing);
  clock.node_spacing = static_cast<float>(spacing);
  clock.first_node_time = static_cast<float>(first * spacing - origin * generation);
  clock.nodes = static_cast<int>(last - first) + 1;
  clock.first_node = static_cast<std::int64_t>(first);
  return clock;
}

NodeTime node_time(const CoverParameters& p, std::int64_t node) {
  const Periods times = periods(p);
  const double t = static_cast<double>(node) * times.node;
  const double origin = std::floor(t / times.generation);
  NodeTime out;
  out.motion = motion_at(times, origin);
  out.time = static_cast<float>(t - origin * times.generation);
  return out;
}

glsl::FbmParams layer_density_params(const CoverParameters& p, std::int64_t layer, int layers_in_loop) {
  if (layers_in_loop > 0) layer = ((layer % layers_in_loop) + layers_in_loop) % layers_in_loop;
  // The index wraps to 32 bits in the hash, as generations do: 2^32 layers of hours apart.
  return glsl::generation_noise(density_params(p), static_cast<int>(static_cast<std::uint32_t>(layer)));
}

}  // namespace nephele::cover
