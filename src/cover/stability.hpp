#pragma once
// Stiffness and folding of the warp, measured on cube maps read back from the GPU
// (docs/numerics.md, "Stiffness" and "Folding").
#include <string>
#include <vector>

#include "cover/integrators.hpp"

namespace nephele::cover {

// Rates of change of the flow: per texel, the spectral radius rho of the tangential velocity
// gradient (largest |eigenvalue|, per unit flow time), by differences of the curl cube map
// between neighbouring texels of a face (central inside, one-sided at the edges). For the
// divergence-free flow the eigenvalues are +-i omega in vortices and +-mu in strain; shear
// across Voronoi borders, large as it is, has eigenvalues near 0 and does not count.
struct FlowRates {
  int size = 0;
  std::vector<float> spectral_radius;  // 6 size^2 texels in GL order; 0 where size < 2
  double max_rate = 0.0;
};
FlowRates flow_rates(const std::vector<float>& curl_rgba, int size);

// The stiffness number h rho of a step size against an integrator's stable limit.
struct StiffnessReport {
  double step = 0.0;             // h
  double max_rate = 0.0;         // largest rho over the sphere
  double stiffness = 0.0;        // h * max_rate
  double limit = 0.0;            // stability_limit(integrator)
  double beyond_fraction = 0.0;  // solid-angle fraction of the sphere where h rho > limit
  bool beyond() const { return stiffness > limit; }
};
StiffnessReport stiffness_report(const FlowRates& rates, double step, Integrator integrator);

// Folding of the warp W: the area Jacobian J = (area spanned by W at neighbouring texels) /
// (area spanned by the texel directions), by the same differences. The exact flow preserves
// area (J = 1); J <= 0 means W folds the sphere over itself there.
struct FoldingReport {
  double folded_fraction = 0.0;  // solid-angle fraction where J <= 0
  double jacobian_min = 1.0;
  double jacobian_max = 1.0;
  double area_error_rms = 0.0;  // solid-angle weighted rms of J - 1
};
FoldingReport folding_report(const std::vector<float>& warp_rgba, int size);

// Adaptive runs store the attempted steps in the warp field's w, negated where the texel ran
// out of sub-steps.
struct SubstepReport {
  double mean_attempts = 0.0;
  double max_attempts = 0.0;
  long capped_texels = 0;
};
SubstepReport substep_report(const std::vector<float>& warp_rgba);

// Everything above for one cover, with the warnings a user must see: a fixed-step scheme
// beyond its stable step on more than warn_fraction of the sphere, adaptive texels that ran
// out of sub-steps, warped points off the unit sphere.
struct WarpDiagnostics {
  StiffnessReport stiffness;
  FoldingReport folding;
  SubstepReport substeps;
  bool adaptive = false;
  std::vector<std::string> warnings;
};
constexpr double warn_fraction = 1e-4;
// The warnings above for reports already made; `off_sphere`: warped points that are not finite
// unit vectors. diagnose_warp and the GPU diagnosis (gpu_reductions.hpp) share it.
// `moving`: the moving flow's warp, which integrates with RK4 only (its advice is the step).
void add_warp_warnings(WarpDiagnostics& d, Integrator integrator, double step, long off_sphere, bool moving = false);
WarpDiagnostics diagnose_warp(const std::vector<float>& curl_rgba, const std::vector<float>& warp_rgba, int size,
                              Integrator integrator, double step);

}  // namespace nephele::cover
