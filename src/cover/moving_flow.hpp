#pragma once
// The host's side of the moving flow (shaders/lib/moving_flow.glsl): the clock of a frame. A
// frame at time t blends two cloud layers, each its own noise carried along the flow for its
// age by back-trajectories; a layer is born every T/2 (T = iterations * step, the steady warp's
// flow time), shows from age T/2 to 3T/2 and peaks at T, so that a frame looks like the steady
// cover and depends on nothing but the seed and t (docs/algorithm.md, "The moving flow").
#include <cstdint>
#include <string>

#include "cover/cover_parameters.hpp"
#include "shader_math/shader_math.hpp"

namespace nephele::cover {

// Hours per flow unit: the stream function's trade wind at the equator, u = 3 s P flow units
// for the table's s = 0.2 and P = 0.5 (s P = 0.1), is 6 m/s (the surface trades blow at 5-7 m/s; Peixoto and
// Oort, Physics of Climate, 1992, fig. 7.20): 0.3 / (6 m/s * 3600 s / 6371 km) = 88.5 hours.
constexpr double flow_hours_per_unit = 0.3 / (6.0 * 3600.0 / 6371000.0);
// The time origin of --time: the flow's time 0.
constexpr const char* flow_epoch = "2000-01-01T00:00Z";

// Hours from the epoch to an ISO 8601 UTC time (core::parse_utc_time's form); throws
// std::invalid_argument as it does.
double hours_since_epoch(const std::string& iso_time);

// What the passes of one frame need, in float, all small: times count from the generation
// `motion.origin`, subtracted in double.
struct FrameClock {
  glsl::FlowMotion motion;
  float time = 0;                // the frame, flow units from motion.origin * L
  float old_age = 0;             // the older cloud layer's age, in [T, 3T/2)
  float young_age = 0;           // the younger's, in [T/2, T)
  float young_share = 0;         // the younger's weight, sin^2(pi/2 (age - T/2) / (T/2))
  std::int64_t young_layer = 0;  // the younger layer's index (its noise's generation)
  // RK4 steps of the younger layer's back-trajectory, ceil(T / h), and of its continuation to
  // the older layer's age, ceil(T/2 / h): the older layer's air is the younger's, followed T/2
  // further back (one trajectory, not two).
  int young_steps = 1;
  int older_steps = 1;
  // Curl mode spline: the flow's grids at time nodes k = 0 .. nodes - 1, at first_node_time +
  // k node_spacing, node_spacing = h / 2 on a grid of absolute time (so that a node is the same
  // flow in every frame that uses it), covering [t - 3T/2, t].
  float first_node_time = 0;
  float node_spacing = 0;
  int nodes = 0;
  std::int64_t first_node = 0;  // the absolute index of the first node (node k at k node_spacing)
  int layers_in_loop = 0;       // --loop: layer j's noise is layer (j mod this)'s; 0 without a loop
};

FrameClock frame_clock(const CoverParameters& p, double hours);

// The time of the grid of absolute node `node`, counted from the node's own generation origin:
// the same flow, to the bit, whichever frame's window contains it.
struct NodeTime {
  glsl::FlowMotion motion;
  float time = 0;
};
NodeTime node_time(const CoverParameters& p, std::int64_t node);

// The density noise of cloud layer `layer` (its own seed, as the vortices' generations; in a loop
// of `layers_in_loop` layers, that of layer mod layers_in_loop).
glsl::FbmParams layer_density_params(const CoverParameters& p, std::int64_t layer, int layers_in_loop);

}  // namespace nephele::cover
