// The moving flow (shaders/lib/moving_flow.glsl) through its C++ twin: its drift, its
// generations, its divergence and the back-trajectories that carry the cover along it.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "cover/cover_parameters.hpp"
#include "shader_math/shader_math.hpp"

using namespace nephele;
using namespace nephele::glsl;

namespace {

CurlParams test_curl() {
  cover::CoverParameters p;
  return cover::curl_params(p);  // the table's defaults: 3 zonal cells, P = 0.5, s = 0.2
}

FlowMotion test_motion(float generation_time = 0.5f, int origin = 7) {
  FlowMotion m;
  m.generation_time = generation_time;
  m.origin = origin;
  m.drift = 1.0f;
  m.generations = 0;
  return m;
}

vec3 random_direction(std::mt19937& rng) {
  std::normal_distribution<float> g;
  return normalize(vec3(g(rng), g(rng), g(rng)));
}

// The surface divergence of v at n by central differences over the tangent plane: for a
// tangent field continued constant along rays, div_S v = div v in R^3 at |x| = 1.
float surface_divergence(const CurlParams& c, const FlowMotion& m, vec3 n, float t, float e) {
  float sum = 0.0f;
  for (int axis = 0; axis < 3; ++axis) {
    vec3 d(0.0f);
    d[axis] = e;
    const vec3 plus = vec3(moving_curl_flow(normalize(n + d), c, vec3(0.0f), m, t));
    const vec3 minus = vec3(moving_curl_flow(normalize(n - d), c, vec3(0.0f), m, t));
    sum += (plus[axis] - minus[axis]) / (2.0f * e);
  }
  return sum;
}

}  // namespace

TEST_CASE("the vortices drift at the angular speed of the stream function's zonal wind", "[fast][moving]") {
  // omega = u / cos(lat) with u = -s P Z'(lat) (curl_flow.glsl): zonal_profile_derivative gives
  // Z' with its cos(lat) factor, so omega cos(lat) must equal -s P Z'.
  CurlParams c = test_curl();
  for (int cells = 0; cells <= 3; ++cells) {
    c.zonal_cells = cells;
    for (float z = -0.95f; z <= 0.95f; z += 0.05f) {
      INFO("cells " << cells << ", z " << z);
      const float cosine = std::sqrt(1.0f - z * z);
      const float latitude = std::asin(z);
      const float a = c.mix_frequency;
      const float expected =
          -c.strength * c.prevailing * zonal_profile_derivative(z, cosine, cells, a * std::cos(a * latitude));
      const vec2 drift = zonal_drift(z, c);
      // Products of a few values below 16 (a few ulps each).
      CHECK(drift.x * cosine == Approx(expected).margin(1e-6));
      // omega' against a central difference: error h^2/6 omega''' (below 2e3 here) + rounding.
      const float h = 1e-3f;
      const float slope = (zonal_drift(z + h, c).x - zonal_drift(z - h, c).x) / (2.0f * h);
      CHECK(drift.y == Approx(slope).margin(2e-3));
    }
  }
}

TEST_CASE("a drifted potential is the noise rotated east by omega times its age, with its exact gradient",
          "[fast][moving]") {
  const CurlParams c = test_curl();
  std::mt19937 rng(3);
  for (int k = 0; k < 20; ++k) {
    const vec3 n = random_direction(rng);
    const float age = 0.1f * float(k % 5) - 0.2f;
    const vec2 drift = zonal_drift(n.z, c);
    const vec4 w = drifted_potential(n, c.potential_north, c.smoothing, vec3(0.0f), drift, age);
    // The value: the noise at n turned by beta = -omega age about the axis.
    const float beta = -drift.x * age;
    const vec3 turned(std::cos(beta) * n.x - std::sin(beta) * n.y, std::sin(beta) * n.x + std::cos(beta) * n.y, n.z);
    CHECK(w.w == Approx(smooth_worley_fbm(turned, c.potential_north, c.smoothing).w).margin(1e-6));
    // The gradient: central differences of the value along two tangent directions; the
    // potential's second derivatives (below about f^2 40 = 160 for f = 2) times h^2/6.
    const vec3 east = normalize(cross(vec3(0, 0, 1), n) + vec3(1e-3f, 0, 0));
    const vec3 north = cross(n, east);
    for (const vec3& d : {east, north}) {
      const float h = 1e-3f;
      const float plus =
          drifted_potential(n + h * d, c.potential_north, c.smoothing, vec3(0.0f), zonal_drift((n + h * d).z, c), age)
              .w;
      const float minus =
          drifted_potential(n - h * d, c.potential_north, c.smoothing, vec3(0.0f), zonal_drift((n - h * d).z, c), age)
              .w;
      INFO("case " << k << " age " << age);
      // float differences of values near 1 over 2h: 2^-23 / 2e-3 = 6e-5, plus the h^2 term.
      CHECK(dot(vec3(w), d) == Approx((plus - minus) / (2.0f * h)).margin(5e-4));
    }
  }
}

TEST_CASE("the moving flow is one generation's steady flow at the generation's centre", "[fast][moving]") {
  // At t = 0 (phase 0) the older generation has age 0 and the whole share: the flow is
  // curl_flow_of_potentials of that generation's noise, undrifted, to the float.
  const CurlParams c = test_curl();
  const FlowMotion m = test_motion();
  std::mt19937 rng(5);
  for (int k = 0; k < 10; ++k) {
    const vec3 n = random_direction(rng);
    const vec4 moving = moving_curl_flow(n, c, vec3(0.0f), m, 0.0f);
    const vec4 w1 = smooth_worley_fbm(n, generation_noise(c.potential_north, m.origin), c.smoothing);
    const vec4 w2 = smooth_worley_fbm(n, generation_noise(c.potential_south, m.origin), c.smoothing);
    const vec4 steady = curl_flow_of_potentials(n, w1, w2, c);
    for (int i = 0; i < 4; ++i) CHECK(moving[i] == Approx(steady[i]).margin(1e-7));
  }
}

TEST_CASE("the moving flow is tangent, divergence-free and continuous across generations", "[fast][moving]") {
  const CurlParams c = test_curl();
  const FlowMotion m = test_motion();
  std::mt19937 rng(9);
  for (int k = 0; k < 12; ++k) {
    const vec3 n = random_direction(rng);
    const float t = 0.37f * float(k) - 1.1f;
    const vec3 v = vec3(moving_curl_flow(n, c, vec3(0.0f), m, t));
    INFO("case " << k << " t " << t);
    CHECK(std::abs(dot(v, n)) <= 1e-6f * (1.0f + length(v)));
    // Divergence by central differences: the velocity's second derivatives (s f^2 ... about 20)
    // times e^2 / 6 per axis, and rounding 2^-23 |v| / e.
    CHECK(std::abs(surface_divergence(c, m, n, t, 2e-3f)) <= 2e-3f);
  }
  // Across a generation boundary (t = L: the older one dies, a new one is born with share 0).
  for (int k = 0; k < 8; ++k) {
    const vec3 n = random_direction(rng);
    const float eps = 1e-4f;
    const vec4 before = moving_curl_flow(n, c, vec3(0.0f), m, m.generation_time - eps);
    const vec4 after = moving_curl_flow(n, c, vec3(0.0f), m, m.generation_time + eps);
    // The flow's time derivative is bounded by the drift and the shares' slope (pi/2 / L times
    // the velocity, about 1): the jump over 2 eps is of order 1e-4, far below the flow itself.
    for (int i = 0; i < 3; ++i) CHECK(std::abs(after[i] - before[i]) <= 2e-3f);
  }
}

TEST_CASE("back-trajectories converge at fourth order and retrace forward steps", "[fast][moving]") {
  const MovingCurl field{test_curl(), vec3(0.0f), test_motion()};
  std::mt19937 rng(13);
  for (int k = 0; k < 6; ++k) {
    const vec3 x = random_direction(rng);
    const float t = 0.3f * float(k);
    const float age = 0.45f;
    // Age 0: the point itself, up to the three steps' normalisations (an ulp each).
    CHECK(length(back_trajectory(x, t, 0.0f, 3, field) - x) <= 3 * 1.2e-7f);
    // Error against a fine reference shrinks about 16 times per halving of h (order 4); at least
    // 8 allows for the smooth potential's limited smoothness between its Voronoi cells. Below the
    // float rounding that the 96-step reference gathers (a random walk of about 2 ulp of a unit
    // vector a step: sqrt(96) x 2.4e-7 = 2.4e-6, twice that as the floor) no order shows.
    const vec3 reference = back_trajectory(x, t, age, 96, field);
    const float coarse = length(back_trajectory(x, t, age, 3, field) - reference);
    const float fine = length(back_trajectory(x, t, age, 6, field) - reference);
    INFO("case " << k << ": error " << coarse << " at 3 steps, " << fine << " at 6");
    CHECK((fine <= 5e-6f || coarse / fine >= 8.0f));
    // A step forward from where the back-trajectory ends returns to x: RK4's local error h^5
    // times the flow's fifth derivatives; below 1e-4 rad (a third of a texel at 1024 per face).
    const vec3 back = back_trajectory(x, t, 0.15f, 1, field);
    CHECK(length(moving_rk4_step(back, t - 0.15f, 0.15f, field) - x) <= 1e-4f);
  }
}

TEST_CASE("the flow's splines at two time nodes mix linearly between them and hold beyond them", "[fast][moving]") {
  // Node 0's grid holds (1, 2, 3, 4) at every node, node 1's (5, 6, 7, 8): a cubic B-spline of
  // constant coefficients is that constant (its weights sum to 1), so between the nodes the value
  // is the linear mix, before the first node node 0's and after the last node 1's.
  const int cells = 4, row = cells + 2 * SPLINE_MARGIN;
  std::vector<vec4> texels;
  for (int layer = 0; layer < 12; ++layer)
    for (int i = 0; i < row * row; ++i) texels.push_back(layer < 6 ? vec4(1, 2, 3, 4) : vec4(5, 6, 7, 8));
  SplineSource grids;
  grids.cells = cells;
  grids.texels = texels.data();
  grids.layers = 12;
  const vec3 w = normalize(vec3(0.3f, -0.5f, 0.8f));
  const float rounding = 16 * 8 * 1.2e-7f;  // 16 terms of values below 8
  for (const auto& [node, expected] : {std::pair<float, vec4>{0.25f, vec4(2, 3, 4, 5)},
                                       {-1.0f, vec4(1, 2, 3, 4)},
                                       {3.0f, vec4(5, 6, 7, 8)},
                                       {1.0f, vec4(5, 6, 7, 8)}}) {
    const vec4 value = sample_curl_spline_in_time(w, grids, node, 0.0f);
    INFO("node " << node);
    for (int i = 0; i < 4; ++i) CHECK(std::abs(value[i] - expected[i]) <= rounding);
    // The velocity: the mix's xyz projected onto the tangent plane at w.
    const vec3 v = spline_velocity_in_time(w, grids, node, 0.0f);
    const vec3 projected = vec3(expected) - dot(vec3(expected), w) * w;
    CHECK(length(v - projected) <= 4 * rounding);
  }
}

namespace nephele::glsl {
namespace {
#include "probes/moving_flow.glsl"
}  // namespace
}  // namespace nephele::glsl

#include "library_probes.hpp"

TEST_CASE("moving_flow.glsl on the GPU agrees with the CPU", "[probe][moving]") {
  using test::arguments;
  using test::kArithmetic;
  using test::kTranscendental;
  using test::kUlp;
  // The probe's flow: frequency 2, 2 octaves (f_max = 4), P = 1, s = 0.1, a = 3, L = 0.5.
  const float s = 0.1f, f_max = 4.0f, a = 3.0f, prevailing = 1.0f;
  // A smooth fBm's gradient errs by 4096 ulp per unit of f_max (test_library_probes.cpp,
  // kSmoothFbm); each potential sums two generations (weights below 1, computed with one sin:
  // kTranscendental relative), each turned by cos and sin of beta (kTranscendental each) and its
  // chain-rule term (omega' age below 16 x 0.5 = 8, times |grad w| <= f_max, products of few ulp).
  const float potential = 2 * (4096 * kUlp * f_max + 2 * kTranscendental * f_max + 8 * f_max * kArithmetic);
  // Then curl_flow_of_potentials: the latitude terms as curl_flow's (m, m' from one sin and cos
  // each) and the storm-track envelope (dA/dlat below 4.2, one exp).
  const float velocity =
      s * (potential + (f_max + a * (1.0f + prevailing)) * (1.0f + a) * kTranscendental + 4.2f * kTranscendental);
  // A stage's error moves the next stage's point by h times it; RK4's weights sum to 1, so a step
  // of h errs by h velocity (plus the normalisation's ulp) amplified by at most e^(Lip h), with
  // the flow's Lipschitz constant below s (f_max^2 12 + ...) ~ 2: e^(2 x 0.45) < 2.5 over a
  // whole back-trajectory of age 0.45.
  const float trajectory = 2.5f * (0.45f * velocity + 3 * 4 * kUlp);
  std::mt19937 rng(21);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  std::vector<mat4> inputs;
  std::vector<float> tolerances;
  const vec4 potential_octaves(2.0f, 2.0f, 11.0f, 12.0f), flow(prevailing, s, 0.5f, 1.0f);
  for (int k = 0; k < 24; ++k) {
    const vec3 n = normalize(vec3(u(rng), u(rng), u(rng)) + vec3(1e-3f));
    const float t = 0.9f * u(rng);
    const int function = k % 6 == 0   ? PROBE_MOVING_CURL_FLOW
                         : k % 6 == 1 ? PROBE_DRIFTED_POTENTIAL
                         : k % 6 == 2 ? PROBE_BACK_TRAJECTORY
                         : k % 6 == 3 ? PROBE_MOVING_RK4_STEP
                         : k % 6 == 4 ? PROBE_MOVING_VELOCITY
                                      : PROBE_ZONAL_DRIFT;
    // Origin 7 (odd: the probe loops 5 generations) or 8 (no loop), by turns.
    const float origin = float(7 + (k / 6) % 2);
    const vec4 a0 = function == PROBE_BACK_TRAJECTORY   ? vec4(0.45f, 3.0f, origin, 0.0f)
                    : function == PROBE_MOVING_RK4_STEP ? vec4(-0.15f, 0.0f, origin, 0.0f)
                    : function == PROBE_ZONAL_DRIFT     ? vec4(float(k % 4), 0.0f, origin, 0.0f)
                                                        : vec4(0.3f, 0.0f, origin, 0.0f);
    inputs.push_back(arguments(function, a0, vec4(n, t), potential_octaves, flow));
    // zonal_drift: a polynomial of z (or one asin, sin and cos for 0 cells) times s P: values
    // below 16 x 3 in a few products. drifted_potential: `potential` for one generation.
    tolerances.push_back(function == PROBE_ZONAL_DRIFT         ? s * prevailing * 48 * kTranscendental
                         : function == PROBE_DRIFTED_POTENTIAL ? potential / 2
                         : function == PROBE_BACK_TRAJECTORY   ? trajectory
                         : function == PROBE_MOVING_RK4_STEP   ? 0.15f * velocity + 4 * kUlp
                                                               : velocity);
  }
  // generation_share (one sin, squared) and generation_noise's seed (exact integer hashing).
  for (int k = 0; k < 4; ++k) {
    inputs.push_back(arguments(PROBE_GENERATION_SHARE, vec4(float(k * 1000 - 1500), 0, 7, 0),
                               vec4(0.25f * float(k), 0, 0, 0), potential_octaves, flow));
    tolerances.push_back(2 * kTranscendental);
  }
  // looped_generation: integers, exact; negative generations wrap too.
  for (int g : {-11, -5, -1, 0, 4, 5, 13}) {
    inputs.push_back(arguments(PROBE_LOOPED_GENERATION, vec4(float(g), float(g % 3 == 0 ? 0 : 5), 7, 0)));
    tolerances.push_back(0.0f);
  }
  const std::vector<vec4> gpu = test::run_library_probe("moving_flow", inputs);
  const auto names = test::probe_function_names(test::probe_text("moving_flow"));
  for (size_t k = 0; k < inputs.size(); ++k) {
    const vec4 cpu = probe_moving_flow(inputs[k]);
    for (int i = 0; i < 4; ++i) {
      INFO("case " << k << " " << names.at(int(inputs[k][0].x)) << " component " << i << ": GPU " << gpu[k][i]
                   << ", CPU " << cpu[i] << ", tolerance " << tolerances[k]);
      CHECK(std::abs(gpu[k][i] - cpu[i]) <= tolerances[k]);
    }
  }
}

TEST_CASE("a looped flow repeats after its generations and wraps negative generations", "[fast][moving]") {
  CHECK(looped_generation(7, 0) == 7);
  CHECK(looped_generation(-1, 0) == -1);
  CHECK(looped_generation(7, 5) == 2);
  CHECK(looped_generation(-1, 5) == 4);
  CHECK(looped_generation(-10, 5) == 0);
  const CurlParams c = test_curl();
  FlowMotion m = test_motion(0.5f, 3);
  m.generations = 4;
  std::mt19937 rng(31);
  for (int k = 0; k < 8; ++k) {
    const vec3 n = random_direction(rng);
    const float t = 0.23f * float(k) - 0.6f;
    // Four generations later (t + 4 L) the flow is the same: only the float time differs, by an
    // ulp of 2 (t + 2): the flow's time derivative (about 1) times 2.4e-7.
    const vec4 now = moving_curl_flow(n, c, vec3(0.0f), m, t);
    const vec4 later = moving_curl_flow(n, c, vec3(0.0f), m, t + 4 * m.generation_time);
    for (int i = 0; i < 4; ++i) CHECK(std::abs(now[i] - later[i]) <= 1e-5f);
  }
}
