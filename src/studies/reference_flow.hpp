#pragma once
// The reference solution of the warp: the procedural curl flow solved far more accurately
// than any GPU variant, in double precision on the CPU (docs/numerics.md, "Reference").
#include <chrono>
#include <cstdint>
#include <vector>

#include "shader_math/shader_math.hpp"

namespace nephele::studies {

struct ReferenceOptions {
  double tolerance = 1e-10;  // error estimate allowed per step, radians
  double max_step = 5e-3;    // flow time per step at most
  long max_steps = 200000;   // attempted steps per point before it is marked unconverged
  int threads = 2;
  // The budget: points not finished by then are left unconverged and marked `cut`.
  std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
};

struct ReferencePoint {
  glm::dvec3 end{0.0};
  long steps = 0;          // attempted steps
  bool converged = false;  // false: max_steps or the deadline ran out (end is where it got to)
  bool cut = false;        // the deadline ran out before this point was finished
  // The reference's own error: the sum of the accepted steps' local error estimates, radians
  // (a first-order bound of the global error that ignores the flow's stretching).
  double error_estimate = 0.0;
};

// Classical RK4 in double with step doubling (Richardson): a step of h and two of h/2 differ
// by 15/16 of the error of the halves, so (b - a)/15 estimates it and b + (b - a)/15 is kept.
// Velocities come from the shared (float) curl_velocity at the rounded point, so the solution
// is that of the float field; it differs from the exact one by about 1e-7 relative.
// `offset` is the reduced noise offset of the potentials (cover::potential_offset).
ReferencePoint reference_warp(glm::dvec3 start, const glsl::CurlParams& curl, glm::vec3 offset, double flow_time,
                              const ReferenceOptions& options = {});

// The same for many points, split over options.threads threads.
std::vector<ReferencePoint> reference_warps(const std::vector<glm::vec3>& starts, const glsl::CurlParams& curl,
                                            glm::vec3 offset, double flow_time, const ReferenceOptions& options = {});

// 6 m^2 directions uniform on the sphere (Archimedes: z and the longitude uniform), from the
// shared integer hash, so the same on every platform; rounded to float and renormalised.
std::vector<glm::vec3> sample_directions(int count, std::uint32_t seed);

// Great-circle distance between two directions, radians (atan2 form: accurate at 0 and pi).
double great_circle_distance(glm::dvec3 a, glm::dvec3 b);

}  // namespace nephele::studies
