#pragma once
// Image error of the ray marcher against its run time, over the numbers of view and light steps.
#include <vector>

#include "regional/scene.hpp"

namespace nephele::render {

struct RenderErrorRow {
  int view_steps, light_steps;
  double time_ms;
  double rms_error;    // root mean square over pixels and RGB, relative to the reference's mean
  double max_error;    // largest absolute difference, relative to the reference's mean
};

// Renders `scene` with each pair of step counts and compares with a reference rendered with
// reference_view x reference_light steps. Needs a current OpenGL 4.5 context.
std::vector<RenderErrorRow> render_error_sweep(const regional::Scene& scene, const std::vector<int>& view_steps,
                                               const std::vector<int>& light_steps, int reference_view,
                                               int reference_light);

}  // namespace nephele::render
