#include "studies/reference_flow.hpp"

#include <algorithm>
#include <cmath>
#include <thread>

namespace nephele::studies {
namespace {

using glm::dvec3;

// The flow's parameters as one source of velocities.
struct Flow {
  const glsl::CurlParams& curl;
  glm::vec3 offset;
};

dvec3 velocity(dvec3 x, const Flow& curl) {
  return dvec3(glsl::curl_velocity_shifted(glm::vec3(glm::normalize(x)), curl.curl, curl.offset));
}

dvec3 rk4(dvec3 y, double h, dvec3 k1, const Flow& curl) {
  const dvec3 k2 = velocity(y + 0.5 * h * k1, curl);
  const dvec3 k3 = velocity(y + 0.5 * h * k2, curl);
  const dvec3 k4 = velocity(y + h * k3, curl);
  return glm::normalize(y + (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4));
}

}  // namespace

ReferencePoint reference_warp(dvec3 start, const glsl::CurlParams& parameters, glm::vec3 offset, double flow_time,
                              const ReferenceOptions& options) {
  const Flow curl{parameters, offset};
  ReferencePoint point;
  dvec3 y = glm::normalize(start);
  double t = 0.0, h = options.max_step;
  bool done = !(flow_time > 0.0);
  while (!done && point.steps < options.max_steps) {
    // The clock is read every 64 steps: a step costs about 12 curl evaluations, far more.
    if (point.steps % 64 == 0 && std::chrono::steady_clock::now() > options.deadline) {
      point.cut = true;
      break;
    }
    const bool last = h >= flow_time - t;
    const double step = last ? flow_time - t : h;
    const dvec3 k1 = velocity(y, curl);
    const dvec3 whole = rk4(y, step, k1, curl);
    const dvec3 middle = rk4(y, 0.5 * step, k1, curl);
    const dvec3 halves = rk4(middle, 0.5 * step, velocity(middle, curl), curl);
    const double error = glm::length(halves - whole) / 15.0;
    ++point.steps;
    // Below 1e-14 the step no longer changes y in double: accept rather than stall.
    if (error <= options.tolerance || step < 1e-14) {
      y = glm::normalize(halves + (halves - whole) / 15.0);
      t += step;
      point.error_estimate += error;
      done = last;
    }
    // RK4's local error is O(h^5); at a jump of the velocity it is O(h), and the factor 0.2
    // bounds the shrinking per rejection.
    const double factor = 0.9 * std::pow(options.tolerance / std::max(error, 1e-300), 0.2);
    h = std::min(options.max_step, step * std::clamp(factor, 0.2, 4.0));
  }
  point.end = y;
  point.converged = done;
  return point;
}

std::vector<ReferencePoint> reference_warps(const std::vector<glm::vec3>& starts, const glsl::CurlParams& curl,
                                            glm::vec3 offset, double flow_time, const ReferenceOptions& options) {
  std::vector<ReferencePoint> points(starts.size());
  const int threads = std::max(1, options.threads);
  auto work = [&](int first) {
    for (size_t k = static_cast<size_t>(first); k < starts.size(); k += static_cast<size_t>(threads))
      points[k] = reference_warp(dvec3(starts[k]), curl, offset, flow_time, options);
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work, t);
  work(0);
  for (auto& thread : pool) thread.join();
  return points;
}

std::vector<glm::vec3> sample_directions(int count, std::uint32_t seed) {
  std::vector<glm::vec3> directions;
  directions.reserve(static_cast<size_t>(count));
  for (int k = 0; k < count; ++k) {
    const glsl::uvec3 h = glsl::pcg3d(glsl::uvec3(static_cast<std::uint32_t>(k), seed, 0x5EED5u));
    const double z = 1.0 - 2.0 * ((h.x >> 8) + 0.5) / 16777216.0;
    const double longitude = 2.0 * M_PI * (h.y >> 8) / 16777216.0;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    directions.push_back(glm::normalize(glm::vec3(dvec3(r * std::cos(longitude), r * std::sin(longitude), z))));
  }
  return directions;
}

double great_circle_distance(dvec3 a, dvec3 b) { return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)); }

}  // namespace nephele::studies
