#include "cover/integrators.hpp"

#include <algorithm>

#include "shader_math/shader_math.hpp"

namespace nephele::cover {

static_assert(static_cast<int>(Integrator::euler) == glsl::INTEGRATOR_EULER);
static_assert(static_cast<int>(Integrator::heun) == glsl::INTEGRATOR_HEUN);
static_assert(static_cast<int>(Integrator::rk4) == glsl::INTEGRATOR_RK4);
static_assert(static_cast<int>(Integrator::geodesic) == glsl::INTEGRATOR_GEODESIC);
static_assert(static_cast<int>(Integrator::adaptive) == glsl::INTEGRATOR_ADAPTIVE);

const char* integrator_name(Integrator integrator) {
  switch (integrator) {
    case Integrator::euler: return "euler";
    case Integrator::heun: return "heun";
    case Integrator::rk4: return "rk4";
    case Integrator::geodesic: return "geodesic";
    case Integrator::adaptive: return "adaptive";
  }
  return "?";
}

const char* curl_mode_name(CurlMode mode) {
  switch (mode) {
    case CurlMode::sampled: return "sampled";
    case CurlMode::procedural: return "procedural";
    case CurlMode::spline: return "spline";
    case CurlMode::automatic: return "auto";
  }
  return "?";
}

const std::vector<CurlMode>& all_curl_modes() {
  static const std::vector<CurlMode> all{CurlMode::sampled, CurlMode::procedural, CurlMode::spline};
  return all;
}

const std::vector<Integrator>& all_integrators() {
  static const std::vector<Integrator> all{Integrator::euler, Integrator::heun, Integrator::rk4, Integrator::geodesic,
                                           Integrator::adaptive};
  return all;
}

std::optional<Integrator> parse_integrator(const std::string& name) {
  for (Integrator i : all_integrators())
    if (name == integrator_name(i)) return i;
  return std::nullopt;
}

std::optional<CurlMode> parse_curl_mode(const std::string& name) {
  for (CurlMode m : all_curl_modes())
    if (name == curl_mode_name(m)) return m;
  if (name == curl_mode_name(CurlMode::automatic)) return CurlMode::automatic;
  return std::nullopt;
}

int integrator_order(Integrator integrator) {
  switch (integrator) {
    case Integrator::heun: return 2;
    case Integrator::rk4: return 4;
    case Integrator::adaptive: return 3;
    default: return 1;
  }
}

int evaluations_per_step(Integrator integrator) {
  switch (integrator) {
    case Integrator::heun: return 2;
    case Integrator::rk4: return 4;
    case Integrator::adaptive: return 3;
    default: return 1;
  }
}

double stability_limit(Integrator integrator) {
  switch (integrator) {
    case Integrator::rk4: return 2.785;
    case Integrator::adaptive: return 1.732;
    default: return 2.0;
  }
}

int loop_iterations_per_step(Integrator integrator, CurlMode mode, int potential_octaves) {
  const int per_evaluation = mode == CurlMode::procedural ? 2 * 13 * std::max(0, potential_octaves) : 0;
  // RK4 runs its four stages in a loop of their own (warp_step.glsl's rk4_step).
  const int stages = integrator == Integrator::rk4 ? 4 : 0;
  return 1 + stages + evaluations_per_step(integrator) * per_evaluation;
}

int steps_per_dispatch(Integrator integrator, CurlMode mode, int potential_octaves) {
  return std::max(1, shader_loop_budget / loop_iterations_per_step(integrator, mode, potential_octaves));
}

std::vector<std::pair<std::string, std::string>> warp_defines(Integrator integrator, CurlMode mode) {
  return {{"WARP_INTEGRATOR", std::to_string(static_cast<int>(integrator))},
          {"WARP_PROCEDURAL", mode == CurlMode::procedural ? "1" : "0"},
          {"WARP_SPLINE", mode == CurlMode::spline ? "1" : "0"}};
}

}  // namespace nephele::cover
