#pragma once
// Error against run time of the moving cover's back-trajectories (--flow moving; docs/numerics.md,
// "The moving flow's error"): each run makes one frame's trajectories on the GPU (curl mode
// procedural, or spline at a grid of curl_size nodes per face edge and time nodes h/2 apart),
// timed, and compares the points of both cloud layers with a reference: the same trajectories
// on the CPU through the procedural flow (the C++ twin of shaders/lib/moving_flow.glsl) with
// `reference_factor` times as many RK4 steps. Two sweeps: the step h at a fixed window (the
// error RK4 and the splines make), and the window W = 3T/2 at a fixed step (how the error grows
// with the trajectories' length: the flow's stretching). A third, the warp grid (--warp-grid): the
// defaults' trajectories from coarser and coarser grids of nodes, interpolated to the texels.
#include <functional>
#include <string>
#include <vector>

#include "cover/cover_parameters.hpp"

namespace nephele::studies {

struct MovingPrecisionOptions {
  cover::CoverParameters base;                // flow moving; its time is the frame's
  int size = 64;                              // texels per face edge of the runs
  int samples = 96;                           // sample texels (spread evenly over the six faces)
  int reference_factor = 32;                  // reference steps per run step
  std::vector<int> steps{1, 2, 4, 8};         // RK4 steps per T at T = base's K h (the step sweep)
  std::vector<int> windows{1, 2, 4, 8};       // K at the base's h (the window sweep: T = K h)
  std::vector<int> curl_sizes{64, 128, 256};  // spline grids; procedural is always run
  std::vector<int> warp_grids{16, 32};        // warp grids (the grid sweep: the defaults' K and h, the finest spline)
  int repeat = 1;                             // timed runs per configuration (the median is kept)

  static MovingPrecisionOptions full(const cover::CoverParameters& base);
  static MovingPrecisionOptions quick(const cover::CoverParameters& base);
};

struct MovingPrecisionRow {
  std::string sweep;                    // "step", "window" or "grid"
  std::string curl_mode;                // "procedural" or "spline"
  int curl_size = 0;                    // spline only
  int warp_grid = 0;                    // the trajectories' grid, nodes per face edge (0: every texel)
  int iterations = 0;                   // K: T = K h
  double step = 0;                      // h, flow units
  double window_hours = 0;              // the older layer's age at this frame (at most 3T/2)
  double time_ms = 0;                   // the spline grids and the warp pass (wall clock between glFinish)
  double young_rms = 0, young_max = 0;  // younger layer: great-circle distance to the reference (rad)
  double old_rms = 0, old_max = 0;      // older layer
  bool finite = true;                   // every point finite and on the sphere
};

// Runs both sweeps (needs a current GL context); `on_row` sees each row as it is made.
std::vector<MovingPrecisionRow> moving_precision_sweep(
    const MovingPrecisionOptions& options, const std::function<void(const MovingPrecisionRow&)>& on_row = {});

std::string moving_precision_csv(const std::vector<MovingPrecisionRow>& rows);
// Two log-log panels: the older layer's largest error against run time (step sweep), and against
// the window in hours (window sweep).
std::string moving_precision_svg(const std::vector<MovingPrecisionRow>& rows, const std::string& title);
std::string moving_precision_markdown(const std::vector<MovingPrecisionRow>& rows,
                                      const MovingPrecisionOptions& options);
// One line of the table the report prints as rows come.
std::string moving_precision_line(const MovingPrecisionRow& row);

}  // namespace nephele::studies
