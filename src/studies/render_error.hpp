#pragma once
// Image error of the ray marcher against its run time, over the numbers of view and light steps.
#include <functional>
#include <vector>

#include "regional/scene.hpp"

namespace nephele::studies {

struct RenderErrorRow {
  int view_steps, light_steps;
  double time_ms;      // wall-clock time of the clouds pass
  double rms_error;    // root mean square over pixels and RGB, relative to the reference's mean
  double max_error;    // largest absolute difference, relative to the reference's mean
};

// The step counts a sweep tries, its reference and its frame size: the one place that defines
// the sweeps of `nephele bench render` and `nephele report` (docs/rendering.md).
struct RenderSweepOptions {
  std::vector<int> view_steps, light_steps;
  int reference_view = 384, reference_light = 24;
  int width = 160, height = 90;

  // View 8, 16, 32, 48, 96 x light 2, 4, 6, 12 against 384 x 24 steps, 160 x 90 pixels.
  static RenderSweepOptions full();
  // View 8, 16, 48 x light 2, 6 against 96 x 12 steps, 32 x 18 pixels (seconds, for CI).
  static RenderSweepOptions quick();
};

// Renders `scene` at the options' frame size with each pair of step counts (view-major order)
// and compares with a reference rendered with reference_view x reference_light steps; `progress`
// gets each row when it is done. Needs a current OpenGL 4.5 context.
std::vector<RenderErrorRow> render_error_sweep(const regional::Scene& scene, const RenderSweepOptions& options,
                                               const std::function<void(const RenderErrorRow&)>& progress = {});

}  // namespace nephele::studies
