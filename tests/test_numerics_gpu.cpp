// The warp pass's integrators and curl modes on the GPU against their CPU twins, equal flow
// times, and the detection of stiff steps.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "steady_cover.hpp"
#include "cover/global_cover.hpp"
#include "cube_fields.hpp"
#include "gl_support.hpp"
#include "cover/integrators.hpp"
#include "studies/reference_flow.hpp"
#include "shader_math/shader_math.hpp"
#include "tolerances.hpp"

using namespace nephele;
using namespace nephele::glsl;
using cover::CurlMode;
using cover::Integrator;

using test::as_vec4;
using test::index;
using test::kAdaptiveErrorFactor;
using test::kOperationRounding;
using test::kOperationsPerEvaluation;
using test::kUlp;
using test::kUnitLength;
using test::velocity_lipschitz;

namespace {

// A procedural warp texel "agrees to rounding" with its CPU twin within 1e-4: of the order of
// rounding_bound for 10 steps (RK4: 8 x 2.4e-7 x 4 x 10 = 7.7e-5 before growth). A threshold
// for counting, with the share that must agree, 99% (95% for equal adaptive step counts), both
// empirical: texels whose trajectories cross a Voronoi border differ by O(1), not by rounding.
constexpr float kAgreesToRounding = 1e-4f;
constexpr double kAgreeingShare = 0.99;
constexpr double kSameStepsShare = 0.95;
// Same flow time, Euler with 2000 steps (h = 2.5e-4) and RK4 with 20: Euler's error is C h with
// C from the first-order test, below 1e-3 for C < 4; RK4's truncation is far below 1e-4. Both
// bounds are empirical (C is not measured here).
constexpr double kEulerFineError = 1e-3;
constexpr double kRk4CoarseError = 1e-4;
// The triangle inequality between the three great-circle distances holds up to their double
// rounding (a few 1e-16); 1e-6 is far looser (kept as set).
constexpr double kTriangleSlack = 1e-6;
// The two covers' float rounding on top of the Lipschitz bound: each cover value rounds its
// density (a few ulp of values below 1) and divides by the span density_max - threshold, which
// amplifies that by 1 / span: 4 x 2^-24 / span = 2.4e-7 / span per cover, so 1e-6 covers two of
// them for spans above 0.5 (the default densities' span, not checked here).
constexpr double kCoverRounding = 1e-6;
static_assert(kCoverRounding >= 2 * 4 * kUlp / 0.5);
// Stiff flow: the adaptive scheme's rms error against Euler's (same h): below 0.2 of it. An
// empirical threshold, not derived.
constexpr double kAdaptiveVersusEuler = 0.2;

cover::CoverParameters parameters(int size, Integrator integrator, CurlMode mode, int steps, float flow_time) {
  cover::CoverParameters p = test::steady_cover();
  p.size = size;
  p.integrator = integrator;
  p.curl_mode = mode;
  p.iterations = steps;
  p.step = flow_time / steps;
  p.profile = cover::flat_profile();  // one threshold, which the cover bounds below use
  return p;
}

cover::CoverParameters zonal(cover::CoverParameters p) {
  p.potential.octaves = 0;
  p.prevailing = 1.0f;
  p.zonal_cells = 0;  // u = -s P a cos(a lat), the closed form the tests turn by
  return p;
}

struct Warped {
  std::vector<vec4> identity, curl, warp;
};

Warped run_warp(const cover::CoverParameters& p) {
  cover::GlobalCover cover(p);
  cover.run_identity();
  cover.run_curl();
  cover.run_warp();
  return {as_vec4(cover.identity_field().read()), as_vec4(cover.curl_field().read()),
          as_vec4(cover.warp_field().read())};
}

const Integrator fixed_steps[] = {Integrator::euler, Integrator::heun, Integrator::rk4, Integrator::geodesic};

// Rounding of one step: a few ulp per operation (eps = 2^-22 covers float's 2^-24 with room),
// a handful of operations per velocity evaluation. An earlier difference grows at most by
// e^(h L) per step, L a Lipschitz bound of the velocity (bilinear sampling: the rate between
// texel centres, doubled for the seams), so over K steps by e^(T L).
double rounding_bound(Integrator integrator, int steps, double flow_time, double lipschitz) {
  return kOperationsPerEvaluation * kOperationRounding * cover::evaluations_per_step(integrator) * steps *
         std::exp(flow_time * lipschitz);
}

}  // namespace

TEST_CASE("each fixed-step warp pass agrees with its CPU twin on the sampled curl", "[numerics][gpu]") {
  test::test_context();
  for (Integrator integrator : fixed_steps) {
    const auto p = parameters(16, integrator, CurlMode::sampled, 10, 0.3f);
    const Warped w = run_warp(p);
    const CubeSource source{p.size, w.curl.data()};
    const double L = 2.0 * velocity_lipschitz(w.curl, p.size);
    const double tolerance = rounding_bound(integrator, p.iterations, 0.3, L);
    double worst = 0;
    for (size_t k = 0; k < w.warp.size(); ++k) {
      const vec3 cpu = integrate_fixed(static_cast<int>(integrator), vec3(w.identity[k]), p.iterations, p.step, source);
      const vec3 gpu = vec3(w.warp[k]);
      worst = std::max(worst, static_cast<double>(length(gpu - cpu)));
      REQUIRE(std::abs(length(gpu) - 1.0f) < kUnitLength);
    }
    INFO(cover::integrator_name(integrator) << ": largest difference " << worst << ", bound " << tolerance);
    CHECK(worst <= tolerance);
  }
}

TEST_CASE("each fixed-step warp pass agrees with its CPU twin on the procedural zonal flow", "[numerics][gpu]") {
  // Smooth away from the poles, and zonal trajectories keep their latitude, so the Lipschitz
  // bound from the texel centres holds along every trajectory.
  test::test_context();
  for (Integrator integrator : fixed_steps) {
    const auto p = zonal(parameters(16, integrator, CurlMode::procedural, 10, 0.3f));
    const Warped w = run_warp(p);
    const CurlParams curl = cover::curl_params(p);
    const double L = velocity_lipschitz(w.curl, p.size);
    const double tolerance = rounding_bound(integrator, p.iterations, 0.3, L);
    double worst = 0;
    for (size_t k = 0; k < w.warp.size(); ++k) {
      const vec3 cpu = integrate_fixed(static_cast<int>(integrator), vec3(w.identity[k]), p.iterations, p.step, curl);
      worst = std::max(worst, static_cast<double>(length(vec3(w.warp[k]) - cpu)));
    }
    INFO(cover::integrator_name(integrator) << ": largest difference " << worst << ", bound " << tolerance);
    CHECK(worst <= tolerance);
  }
}

TEST_CASE("the procedural warp matches its CPU twin except where rounding crosses a Voronoi border",
          "[numerics][gpu]") {
  // The Worley gradient jumps across cell borders: the flow is not Lipschitz there, and two
  // trajectories a rounding error apart can end on different sides, with velocities that
  // differ by O(1) for part of a step. So no pointwise bound exists; almost all texels agree
  // to rounding, and every point stays on the sphere.
  test::test_context();
  for (Integrator integrator : {Integrator::euler, Integrator::rk4}) {
    const auto p = parameters(16, integrator, CurlMode::procedural, 10, 0.3f);
    const Warped w = run_warp(p);
    const CurlParams curl = cover::curl_params(p);
    size_t close = 0;
    for (size_t k = 0; k < w.warp.size(); ++k) {
      const vec3 cpu = integrate_fixed(static_cast<int>(integrator), vec3(w.identity[k]), p.iterations, p.step, curl);
      close += length(vec3(w.warp[k]) - cpu) < kAgreesToRounding;
      REQUIRE(std::abs(length(vec3(w.warp[k])) - 1.0f) < kUnitLength);
    }
    INFO(cover::integrator_name(integrator) << ": " << close << " of " << w.warp.size() << " within 1e-4");
    CHECK(close >= kAgreeingShare * w.warp.size());
  }
}

TEST_CASE("the adaptive warp pass and its CPU twin both meet the tolerance on the zonal flow", "[numerics][gpu]") {
  // Rounding can flip an accept/reject decision, after which the step sequences differ: the
  // two agree through the exact solution, each within its error control (about the tolerance
  // here, see the CPU test of tolerance proportionality), not to rounding.
  test::test_context();
  const float tolerance = 1e-5f;
  auto p = zonal(parameters(12, Integrator::adaptive, CurlMode::procedural, 10, 1.0f));
  p.tolerance = tolerance;
  const Warped w = run_warp(p);
  const CurlParams curl = cover::curl_params(p);
  const double a = curl.mix_frequency;
  size_t same_steps = 0, compared = 0;
  for (size_t k = 0; k < w.warp.size(); ++k) {
    const vec3 start = vec3(w.identity[k]);
    const double lat = std::asin(static_cast<double>(start.z));
    if (std::abs(lat) > 1.2) continue;  // the zonal flow's rate grows without bound at the poles
    const double lon = std::atan2(static_cast<double>(start.y), static_cast<double>(start.x));
    const double turned = lon - 1.0 * curl.strength * curl.prevailing * a * std::cos(a * lat) / std::cos(lat);
    const glm::dvec3 exact(std::cos(lat) * std::cos(turned), std::cos(lat) * std::sin(turned), std::sin(lat));
    const vec4 cpu = integrate_adaptive(start, 1.0f, p.step, 1.0f, tolerance, p.max_substeps, curl);
    REQUIRE(w.warp[k].w > 0.0f);
    CHECK(studies::great_circle_distance(glm::dvec3(vec3(w.warp[k])), exact) < kAdaptiveErrorFactor * tolerance);
    CHECK(studies::great_circle_distance(glm::dvec3(vec3(cpu)), exact) < kAdaptiveErrorFactor * tolerance);
    same_steps += cpu.w == w.warp[k].w;
    ++compared;
  }
  CHECK(same_steps >= kSameStepsShare * compared);
}

TEST_CASE("the adaptive warp pass on the sampled curl matches its CPU twin at almost every texel", "[numerics][gpu]") {
  test::test_context();
  auto p = parameters(16, Integrator::adaptive, CurlMode::sampled, 50, 0.3f);
  p.tolerance = 1e-4f;
  const Warped w = run_warp(p);
  const CubeSource source{p.size, w.curl.data()};
  size_t close = 0;
  for (size_t k = 0; k < w.warp.size(); ++k) {
    const vec4 cpu = integrate_adaptive(vec3(w.identity[k]), 0.3f, p.step, 0.3f, p.tolerance, p.max_substeps, source);
    close += length(vec3(w.warp[k]) - vec3(cpu)) < kAgreesToRounding && cpu.w == w.warp[k].w;
    REQUIRE(std::abs(length(vec3(w.warp[k])) - 1.0f) < kUnitLength);
    REQUIRE(w.warp[k].w > 0.0f);
  }
  CHECK(close >= kAgreeingShare * w.warp.size());
}

TEST_CASE("two runs with the same flow time and different integrators give the same warp and cover up to their errors",
          "[numerics][gpu]") {
  // T = K h is the physical quantity: Euler with 2000 steps and RK4 with 20 steps of the
  // zonal flow both approximate the same flow map, to their truncation errors (Euler:
  // about C h with C from the first-order test; RK4: far below).
  test::test_context();
  const float flow_time = 0.5f;
  const auto pe = zonal(parameters(12, Integrator::euler, CurlMode::procedural, 2000, flow_time));
  const auto pr = zonal(parameters(12, Integrator::rk4, CurlMode::procedural, 20, flow_time));
  cover::GlobalCover euler(pe), rk4(pr);
  euler.run();
  rk4.run();
  const auto we = as_vec4(euler.warp_field().read()), wr = as_vec4(rk4.warp_field().read());
  const auto identity = as_vec4(euler.identity_field().read());
  const CurlParams curl = cover::curl_params(pe);
  const double a = curl.mix_frequency;
  double worst_euler = 0, worst_rk4 = 0, worst_difference = 0;
  for (size_t k = 0; k < we.size(); ++k) {
    const vec3 start = vec3(identity[k]);
    const double lat = std::asin(static_cast<double>(start.z));
    if (std::abs(lat) > 1.2) continue;
    const double lon = std::atan2(static_cast<double>(start.y), static_cast<double>(start.x));
    const double turned = lon - flow_time * curl.strength * curl.prevailing * a * std::cos(a * lat) / std::cos(lat);
    const glm::dvec3 exact(std::cos(lat) * std::cos(turned), std::cos(lat) * std::sin(turned), std::sin(lat));
    worst_euler = std::max(worst_euler, studies::great_circle_distance(glm::dvec3(vec3(we[k])), exact));
    worst_rk4 = std::max(worst_rk4, studies::great_circle_distance(glm::dvec3(vec3(wr[k])), exact));
    worst_difference =
        std::max(worst_difference, studies::great_circle_distance(glm::dvec3(vec3(we[k])), glm::dvec3(vec3(wr[k]))));
  }
  INFO("euler error " << worst_euler << ", rk4 error " << worst_rk4 << ", difference " << worst_difference);
  CHECK(worst_euler < kEulerFineError);
  CHECK(worst_rk4 < kRk4CoarseError);
  CHECK(worst_difference <= worst_euler + worst_rk4 + kTriangleSlack);
  // The covers: with no potential noise only the density moves, and it is Lipschitz: the
  // inverted Worley fBm changes by at most sum_k a_k f_k / sum_k a_k per radian.
  const FbmParams density = cover::density_params(pe);
  double lipschitz = 0, norm = 0, amplitude = 1, frequency = density.frequency;
  for (int k = 0; k < density.octaves; ++k) {
    lipschitz += amplitude * frequency;
    norm += amplitude;
    amplitude *= density.gain;
    frequency *= density.lacunarity;
  }
  lipschitz /= norm;
  const auto& c = euler.calibration();
  const double cover_bound = lipschitz * worst_difference / (c.density_max - c.threshold) + kCoverRounding;
  double worst_cover = 0;
  for (size_t k = 0; k < we.size(); ++k) {
    if (std::abs(identity[k].z) > std::sin(1.2f)) continue;  // as above
    // The linear ramp (softness 0), whose slope is 1 / (d_max - t): the softened remap adds a step
    // of COVER_EDGE at the threshold, which no Lipschitz bound covers.
    const float ce = cover_from_density(cover_density(vec3(we[k]), density), c.threshold, c.density_max, 0.0f);
    const float cr = cover_from_density(cover_density(vec3(wr[k]), density), c.threshold, c.density_max, 0.0f);
    worst_cover = std::max(worst_cover, static_cast<double>(std::abs(ce - cr)));
  }
  INFO("cover difference " << worst_cover << ", bound " << cover_bound);
  CHECK(worst_cover <= cover_bound);
}

TEST_CASE("a stiff flow with large steps is reported for fixed-step schemes and the adaptive scheme sub-steps",
          "[numerics][gpu][stiff]") {
  // High curl frequency (64 cells per radius) and h = 0.05: vortex cores turn faster than a
  // step can follow. Each run is compared at sample points with RK4 at 100 times more steps.
  test::test_context();
  auto stiff = [](Integrator integrator, int steps) {
    auto p = parameters(32, integrator, CurlMode::sampled, steps, 0.3f);
    p.potential = {64.0f, 1, 2.0f, 0.5f};
    p.curl_strength = 0.1f;
    p.tolerance = 1e-4f;
    return p;
  };
  const std::vector<vec3> starts = studies::sample_directions(6 * 8 * 8, 7u);
  std::vector<float> texels(4 * starts.size(), 0.0f);
  for (size_t k = 0; k < starts.size(); ++k)
    for (int c = 0; c < 3; ++c) texels[4 * k + c] = starts[k][c];
  const gpu::Texture start_field = gpu::Texture::cube(8, GL_RGBA32F);
  start_field.write(texels);
  const gpu::Texture end_field = gpu::Texture::cube(8, GL_RGBA32F);
  auto sample_warp = [&](cover::GlobalCover& cover) {
    cover.warp_points(start_field, end_field);
    return as_vec4(end_field.read());
  };
  cover::GlobalCover fine(stiff(Integrator::rk4, 600));
  fine.run_identity();
  fine.run_curl();
  const auto reference = sample_warp(fine);
  auto rms_error = [&](const std::vector<vec4>& w) {
    double sum = 0;
    for (size_t k = 0; k < w.size(); ++k)
      sum += studies::great_circle_distance(glm::dvec3(vec3(w[k])), glm::dvec3(vec3(reference[k]))) *
             studies::great_circle_distance(glm::dvec3(vec3(w[k])), glm::dvec3(vec3(reference[k])));
    return std::sqrt(sum / w.size());
  };
  double euler_error = 0;
  for (Integrator integrator : {Integrator::euler, Integrator::rk4, Integrator::adaptive}) {
    cover::GlobalCover cover(stiff(integrator, 6));
    cover.run_identity();
    cover.run_curl();
    cover.run_warp();
    const auto& d = cover.diagnose();
    const double error = rms_error(sample_warp(cover));
    INFO(cover::integrator_name(integrator) << ": stiffness " << d.stiffness.stiffness << " limit " << d.stiffness.limit
                                            << " beyond on " << d.stiffness.beyond_fraction << ", rms error " << error);
    CHECK(d.stiffness.stiffness > d.stiffness.limit);
    for (float v : cover.warp_field().read()) REQUIRE(std::isfinite(v));
    if (integrator == Integrator::adaptive) {
      // No stiffness warning: it sub-stepped instead (the fold warning may stand: at size 32
      // the texels cannot resolve this flow's stretching).
      for (const auto& w : d.warnings) CHECK(w.find("stiffness") == std::string::npos);
      CHECK(d.substeps.mean_attempts > 6.0);
      CHECK(d.substeps.capped_texels == 0);
      CHECK(error < kAdaptiveVersusEuler * euler_error);
    } else {
      CHECK(d.stiffness.beyond_fraction > cover::warn_fraction);
      REQUIRE(!d.warnings.empty());
      CHECK(d.warnings[0].find("stiffness") != std::string::npos);
      if (integrator == Integrator::euler) euler_error = error;
    }
  }
}

TEST_CASE("the default cover is within the stable step and neither reported as stiff nor folded",
          "[numerics][gpu][stiff]") {
  test::test_context();
  cover::CoverParameters p = test::steady_cover();
  p.size = 256;
  cover::GlobalCover cover(p);
  cover.run();
  const auto& d = cover.diagnose();
  INFO("stiffness " << d.stiffness.stiffness << " beyond on " << d.stiffness.beyond_fraction);
  CHECK(d.warnings.empty());
  CHECK(d.stiffness.beyond_fraction <= cover::warn_fraction);
  // The exact flow keeps area (J = 1); the texels of size 256 resolve the default steady flow's
  // stretching (measured J_min 0.54; at 64 the finite differences see folds on 3e-5 of the sphere).
  CHECK(d.folding.folded_fraction == 0.0);
  CHECK(d.folding.jacobian_min > 0.0);
}
