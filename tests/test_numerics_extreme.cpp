// Extreme cases of the warp, each for every integrator and both curl modes, on the GPU (the
// warp pass, and special start points through the same shader) and the CPU twin: no NaN or
// Inf, warped points on the unit sphere to 1e-6, and the behaviour docs/numerics.md states.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "steady_cover.hpp"
#include "cover/global_cover.hpp"
#include "cube_fields.hpp"
#include "gl_support.hpp"
#include "cover/integrators.hpp"
#include "shader_math/shader_math.hpp"
#include "tolerances.hpp"

using namespace nephele;
using namespace nephele::glsl;
using cover::CurlMode;
using cover::Integrator;

using test::as_vec4;
using test::kUlp;
using test::kUnitLength;

namespace {

// At a pole the latitude term is multiplied by north = 0, so the velocity does not depend on
// the prevailing winds at all: exact (0 x finite = 0); 1e-6 only guards the check.
constexpr float kPoleIndependent = 1e-6f;
// On the feature point q (|q| < 3.5): n = q / |q| scaled back by the frequency |q| is q up to
// the length's, the division's and the product's roundings (3 ulp of 3.5 per component, 2^-24
// x 4 each): sqrt(3) x 3 x 4 x 2^-24 = 1.2e-6 from the feature point, F1 as much; 1e-5 leaves a
// factor 8.
constexpr float kOnFeaturePoint = 1e-5f;
static_assert(kOnFeaturePoint >= 1.7321f * 3 * 4 * kUlp);
// On a Voronoi border the velocity is one of the two one-sided limits (1e-3 cells either side):
// within 5% of their difference plus an absolute floor for the smooth change over those 1e-3
// cells, which scales with the potential's strength s: 1e-2 s (1e-3 at s = 0.1, where it was
// measured). Empirical (the share and the floor per unit strength are not derived).
constexpr float kOneSidedShare = 0.05f;
constexpr float kOneSidedFloorPerStrength = 1e-2f;
// Zero flow: each step renormalises a unit vector, moving it by at most about 1.5 ulp per
// component (the multiplier's rounding), sqrt(3) x 1.5 x 2 x 2^-24 = 3.1e-7 with fused
// differences; 4.8e-7 (8 x 2^-24 rounded up) per step.
constexpr float kRenormalisePerStep = 4.8e-7f;
static_assert(kRenormalisePerStep >= 8 * kUlp);
// The reduced noise offset (below the period, < 4 radii) against fmod in double rounded to float:
// at most one float rounding of values below 4 apart (an ulp, 2^-22 = 2.4e-7, if the double sum
// 1e6 + 7 period rounds the remainder across a float boundary); 1e-6 covers 2 ulp. The comment
// "to the last bit" below is what happens; the check allows 2 ulp.
constexpr float kReducedOffset = 1e-6f;
// The sampled velocity at a corner, a convex combination of texels, against the worst texel:
// the weights and the mixes round by a few ulp of speeds below 4 (4 x 2^-24 x 4 = 9.5e-7):
// 1e-6 (only just; partly empirical, the speeds near the corners are not checked).
constexpr float kConvexCombination = 1e-6f;
static_assert(kConvexCombination >= 4 * 4 * kUlp);
// 100000 tiny steps: the rounding of W + h v (half an ulp of 1 per component, 2^-24, in the
// same direction for many consecutive steps) and the normalisation add up linearly: at most
// about 1e-7 per step (the test's comment; strictly sqrt(3) x 2^-24 = 1.03e-7 if all three
// components round the same way, 3% above the value used; measured: 1e-3 over 1e5 steps, 1e-8
// per step, so the check has a factor 10 in practice).
constexpr float kDriftPerStep = 1e-7f;
static_assert(kDriftPerStep >= kUlp);
static_assert(kReducedOffset >= 2 * 4 * kUlp);

bool on_sphere(vec3 w) {
  return std::isfinite(w.x) && std::isfinite(w.y) && std::isfinite(w.z) && std::abs(length(w) - 1.0f) <= kUnitLength;
}

// Warps `points` with the GPU warp pass's shader of `cover` (the start texture holds them).
std::vector<vec3> gpu_warp(cover::GlobalCover& cover, const std::vector<vec3>& points) {
  int m = 1;
  while (6 * m * m < static_cast<int>(points.size())) ++m;
  std::vector<float> texels(static_cast<size_t>(4 * 6 * m * m), 0.0f);
  for (size_t k = 0; k < 6u * m * m; ++k)
    for (int c = 0; c < 3; ++c) texels[4 * k + c] = points[k % points.size()][c];
  const gpu::Texture starts = gpu::Texture::cube(m, GL_RGBA32F), ends = gpu::Texture::cube(m, GL_RGBA32F);
  starts.write(texels);
  cover.warp_points(starts, ends);
  const auto warped = as_vec4(ends.read());
  std::vector<vec3> result;
  for (size_t k = 0; k < points.size(); ++k) result.push_back(vec3(warped[k]));
  return result;
}

vec3 cpu_warp(const cover::CoverParameters& p, const std::vector<vec4>& curl, vec3 start) {
  const CubeSource source{p.size, curl.data()};
  const CurlParams c = cover::curl_params(p);
  const vec3 offset = cover::potential_offset(p);
  const auto procedural = [&](vec3 w) { return curl_velocity_shifted(w, c, offset); };
  const float flow_time = static_cast<float>(static_cast<double>(p.iterations) * p.step);
  if (p.integrator == Integrator::adaptive) {
    return p.curl_mode == CurlMode::sampled
               ? vec3(integrate_adaptive(start, flow_time, p.step, flow_time, p.tolerance, p.max_substeps, source))
               : vec3(integrate_adaptive(start, flow_time, p.step, flow_time, p.tolerance, p.max_substeps, procedural));
  }
  const int integrator = static_cast<int>(p.integrator);
  return p.curl_mode == CurlMode::sampled ? integrate_fixed(integrator, start, p.iterations, p.step, source)
                                          : integrate_fixed(integrator, start, p.iterations, p.step, procedural);
}

struct VariantResult {
  cover::CoverParameters parameters = test::steady_cover();
  std::vector<vec4> identity, warp;
  std::vector<float> cover;
  std::vector<vec3> points_gpu, points_cpu;
};

// Runs the whole cover for every integrator and curl mode, warps `points` on the GPU and the
// CPU, and checks what holds in every extreme case.
std::vector<VariantResult> check_every_variant(const cover::CoverParameters& base,
                                               const std::vector<vec3>& points = {}) {
  test::test_context();
  std::vector<VariantResult> results;
  for (Integrator integrator : cover::all_integrators())
    for (CurlMode mode : {CurlMode::sampled, CurlMode::procedural}) {
      cover::CoverParameters p = base;
      p.integrator = integrator;
      p.curl_mode = mode;
      INFO(cover::integrator_name(integrator) << " " << cover::curl_mode_name(mode) << " size " << p.size);
      cover::GlobalCover cover(p);
      cover.run();
      const auto& diagnostics = cover.diagnose();
      CHECK(std::isfinite(diagnostics.stiffness.stiffness));
      CHECK(std::isfinite(diagnostics.folding.folded_fraction));
      VariantResult r{
          p, as_vec4(cover.identity_field().read()), as_vec4(cover.warp_field().read()), cover.cover_field().read(), {},
          {}};
      for (const vec4& w : r.warp) REQUIRE(on_sphere(vec3(w)));
      for (float c : r.cover) {
        REQUIRE(c >= 0.0f);
        REQUIRE(c <= 1.0f);
      }
      if (!points.empty()) {
        const auto curl = as_vec4(cover.curl_field().read());
        r.points_gpu = gpu_warp(cover, points);
        for (size_t k = 0; k < points.size(); ++k) {
          INFO("start " << points[k].x << " " << points[k].y << " " << points[k].z);
          REQUIRE(on_sphere(r.points_gpu[k]));
          r.points_cpu.push_back(cpu_warp(p, curl, points[k]));
          REQUIRE(on_sphere(r.points_cpu.back()));
        }
      }
      results.push_back(std::move(r));
    }
  return results;
}

cover::CoverParameters small(int size = 8) {
  cover::CoverParameters p = test::steady_cover();
  p.size = size;
  p.iterations = 10;
  p.step = 0.03f;
  p.curl_mode = cover::CurlMode::sampled;  // the cheap mode; tests of every variant set their own
  return p;
}

// The feature point of cell `cell` of octave 0 of an fBm, in cell units.
vec3 feature_point(const FbmParams& f, ivec3 cell) {
  return vec3(cell) + feature_offset(cell, ivec3(0), noise_key(f.seed, 0u));
}

}  // namespace

TEST_CASE("extreme: warps starting at the poles stay finite and on the sphere", "[numerics][extreme]") {
  const std::vector<vec3> poles{vec3(0, 0, 1), vec3(0, 0, -1)};
  check_every_variant(small(), poles);
  // As documented: at a pole the direction north is undefined and the latitude term (the
  // zonal winds) is dropped, so the velocity there does not depend on the prevailing winds.
  cover::CoverParameters p = small();
  CurlParams c = cover::curl_params(p);
  const vec3 v = curl_velocity(poles[0], c);
  c.prevailing = 7.0f;
  CHECK(length(curl_velocity(poles[0], c) - v) < kPoleIndependent);
}

TEST_CASE("extreme: warps starting at cube corners and on face edges stay finite and on the sphere",
          "[numerics][extreme]") {
  std::vector<vec3> points;
  for (float x : {-1.0f, 1.0f})
    for (float y : {-1.0f, 1.0f})
      for (float z : {-1.0f, 1.0f}) points.push_back(normalize(vec3(x, y, z)));
  for (const vec3 e : {vec3(1, 1, 0), vec3(-1, 0, 1), vec3(0, -1, -1), vec3(1, 0.3f, 1), vec3(0.2f, -1, -1)})
    points.push_back(normalize(e));
  const auto results = check_every_variant(small(), points);
  // The sampled velocity at a corner is a convex combination of texels near it (the seamless
  // filter substitutes a neighbour face's texel for the missing fourth), so it differs from
  // the exact velocity by at most the largest such texel's difference.
  const auto& r = results.front();
  cover::GlobalCover cover(r.parameters);
  cover.run_identity();
  cover.run_curl();
  const auto curl = as_vec4(cover.curl_field().read());
  const CurlParams c = cover::curl_params(r.parameters);
  const int n = r.parameters.size;
  for (size_t k = 0; k < 8; ++k) {
    const vec3 corner = points[k];
    const vec3 exact = curl_velocity(corner, c);
    float worst_texel = 0.0f;
    for (int face = 0; face < 6; ++face)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
          if (std::acos(std::min(1.0f, dot(texel_direction(face, i, j, n), corner))) < 2.0f * 1.6f / n)
            worst_texel =
                std::max(worst_texel, length(vec3(curl[(static_cast<size_t>(face) * n + j) * n + i]) - exact));
    const vec3 sampled = flow_velocity(corner, CubeSource{n, curl.data()});
    INFO("corner " << k);
    CHECK(length(sampled - exact) <= worst_texel + kConvexCombination);
  }
}

TEST_CASE("extreme: warps starting exactly on Worley feature points and cell borders stay finite and on the sphere",
          "[numerics][extreme]") {
  // Lattice points on the sphere: the sphere has radius f in cell units, so with the
  // frequency f = |q| the direction q / |q| lands on the lattice point q (up to rounding).
  cover::CoverParameters base = small();
  base.potential.octaves = 1;
  const FbmParams north = cover::curl_params(base).potential_north;
  const ivec3 cell(2, 1, 1);
  const vec3 q1 = feature_point(north, cell), q2 = feature_point(north, cell + ivec3(1, 0, 0));
  const vec3 border = 0.5f * (q1 + q2);  // equidistant from q1 and q2
  for (const vec3 q : {q1, border}) {
    cover::CoverParameters p = base;
    p.potential.frequency = length(q);
    const vec3 n = q / length(q);
    const FbmParams f = cover::curl_params(p).potential_north;
    const vec4 f1 = worley_f1(n * f.frequency, ivec3(0), noise_key(f.seed, 0u));
    INFO("F1 at the start " << f1.w);
    check_every_variant(p, {n});
    if (q == q1) {
      CHECK(f1.w < kOnFeaturePoint);  // on the feature point: the gradient is singular (zero at F1 = 0)
    } else {
      // On the border the gradient jumps; the velocity is one of the two one-sided limits.
      const CurlParams c = cover::curl_params(p);
      const vec3 across = normalize(q2 - q1) * (1e-3f / f.frequency);
      const vec3 v = curl_velocity(n, c);
      const vec3 left = curl_velocity(normalize(n - across), c), right = curl_velocity(normalize(n + across), c);
      CHECK(std::min(length(v - left), length(v - right)) <
            kOneSidedShare * length(left - right) + kOneSidedFloorPerStrength * p.curl_strength);
    }
  }
}

TEST_CASE("extreme: zero flow leaves every point where it is", "[numerics][extreme]") {
  cover::CoverParameters p = small();
  p.curl_strength = 0.0f;
  const auto results = check_every_variant(p);
  for (const auto& r : results)
    for (size_t k = 0; k < r.warp.size(); ++k) {
      // Each step renormalises a unit vector: at most a few ulp per step.
      REQUIRE(length(vec3(r.warp[k]) - vec3(r.identity[k])) <= p.iterations * kRenormalisePerStep);
      if (r.parameters.integrator == Integrator::adaptive) REQUIRE(std::abs(r.warp[k].w) <= 4.0f);  // steps grow 5x
    }
}

TEST_CASE("extreme: zero steps are the identity and huge step counts converge", "[numerics][extreme]") {
  cover::CoverParameters zero = small();
  zero.iterations = 0;
  for (const auto& r : check_every_variant(zero))
    for (size_t k = 0; k < r.warp.size(); ++k) REQUIRE(vec3(r.warp[k]) == vec3(r.identity[k]));

  // 100000 steps of h = T / 100000 (sampled, the cheap mode): the truncation error is gone, and
  // rounding takes over. A step moves W by only ~50 ulp, so the rounding of W + h v, up to half
  // an ulp per component and the same for many consecutive steps, adds up linearly: with the
  // normalisation, at most about 1e-7 per step, K 1e-7 = 1e-2 in all (measured: 1e-3).
  // These runs also cross llvmpipe's limit of 65535 loop iterations per invocation, so they
  // test that the warp pass splits them over several dispatches.
  test::test_context();
  cover::CoverParameters huge = small(2);
  huge.iterations = 100000;
  huge.step = 0.3f / huge.iterations;
  cover::CoverParameters converged = small(2);
  converged.integrator = Integrator::rk4;
  converged.iterations = 1000;
  converged.step = 0.3f / converged.iterations;
  cover::GlobalCover reference(converged);
  reference.run();
  const auto expected = as_vec4(reference.warp_field().read());
  for (Integrator integrator : {Integrator::euler, Integrator::heun, Integrator::rk4, Integrator::geodesic}) {
    huge.integrator = integrator;
    cover::GlobalCover cover(huge);
    cover.run();
    const auto warp = as_vec4(cover.warp_field().read());
    for (size_t k = 0; k < warp.size(); ++k) {
      INFO(cover::integrator_name(integrator) << " texel " << k);
      REQUIRE(on_sphere(vec3(warp[k])));
      CHECK(length(vec3(warp[k]) - vec3(expected[k])) < huge.iterations * kDriftPerStep);
    }
  }
  // Huge steps: one step of h = 10 is finite and on the sphere, though not accurate.
  cover::CoverParameters leap = small(4);
  leap.iterations = 1;
  leap.step = 10.0f;
  leap.max_substeps = 200;
  check_every_variant(leap, {vec3(1, 0, 0)});
}

TEST_CASE("extreme: cube maps of sizes 1 to 3 run for every integrator", "[numerics][extreme]") {
  for (int size : {1, 2, 3}) check_every_variant(small(size));
}

TEST_CASE("extreme: zero and many octaves of the potential", "[numerics][extreme]") {
  cover::CoverParameters none = small();
  none.potential.octaves = 0;  // the zonal flow alone
  check_every_variant(none, {vec3(0, 0, 1)});
  cover::CoverParameters many = small();
  many.potential = {2.0f, 16, 1.5f, 0.7f};  // the option's limit; highest octave 2 1.5^15 = 876
  check_every_variant(many, {normalize(vec3(1, 1, 1))});
  cover::CoverParameters flat = small();
  flat.density.octaves = 0;  // constant density
  check_every_variant(flat);
}

TEST_CASE("extreme: seeds at the integer limits give finite and different covers", "[numerics][extreme]") {
  cover::CoverParameters low = small(), high = small();
  low.seed = 0;
  high.seed = std::numeric_limits<std::uint32_t>::max();
  const auto a = check_every_variant(low), b = check_every_variant(high);
  size_t differing = 0;
  for (size_t k = 0; k < a[0].warp.size(); ++k) differing += vec3(a[0].warp[k]) != vec3(b[0].warp[k]);
  CHECK(differing > a[0].warp.size() / 2);
}

TEST_CASE("extreme: far-away noise offsets keep float precision through the periodic lattice", "[numerics][extreme]") {
  cover::CoverParameters far = small();
  far.noise_offset = 1e6;
  check_every_variant(far, {vec3(0, 0, 1), normalize(vec3(1, 1, 1))});

  // As documented: the lattice is periodic with (floor(2 f) + 2) / f radii, and the offset is
  // reduced modulo that in double, so the reduced offset is small and exact.
  const double period =
      cover::offset_period_cells(far.potential, far.noise_offset) / static_cast<double>(far.potential.frequency);
  CHECK(period > 2.0);
  const vec3 reduced = cover::potential_offset(far);
  CHECK(reduced.x >= 0.0f);
  CHECK(reduced.x < period);
  CHECK(std::abs(reduced.x - static_cast<float>(std::fmod(1e6, period))) < kReducedOffset);
  // One period further is the same noise, to the last bit.
  cover::CoverParameters further = far;
  further.noise_offset = 1e6 + 7 * period;
  CHECK(std::abs(cover::potential_offset(further).x - reduced.x) < kReducedOffset);

  // The potential at the far offset is resolved as near the origin; the naive float
  // evaluation, (n + 1e6) in float, has a spacing of 0.0625 radii: a staircase in which
  // neighbouring texels (0.05 radii apart here) often sample the same point.
  const int n = 32;
  const FbmParams potential = cover::curl_params(far).potential_north;
  size_t naive_equal = 0, reduced_equal = 0, pairs = 0;
  for (int face = 0; face < 6; ++face)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i + 1 < n; ++i) {
        const vec3 a = texel_direction(face, i, j, n), b = texel_direction(face, i + 1, j, n);
        naive_equal += inverted_worley_fbm(a + vec3(1e6f), potential) == inverted_worley_fbm(b + vec3(1e6f), potential);
        reduced_equal += inverted_worley_fbm(a + reduced, potential) == inverted_worley_fbm(b + reduced, potential);
        ++pairs;
      }
  INFO("equal neighbours: naive " << naive_equal << ", reduced " << reduced_equal << " of " << pairs);
  CHECK(naive_equal > pairs / 10);
  CHECK(reduced_equal == 0);
}

TEST_CASE("extreme: coverage 0 and 1 with every integrator", "[numerics][extreme]") {
  cover::CoverParameters clear = small(), cloudy = small();
  clear.coverage = 0.0f;
  cloudy.coverage = 1.0f;
  for (const auto& r : check_every_variant(clear))
    for (float c : r.cover) REQUIRE(c == 0.0f);
  for (const auto& r : check_every_variant(cloudy)) {
    size_t cloudy_texels = 0;
    for (float c : r.cover) cloudy_texels += c > 0.0f;
    // All but the texels of the smallest density, which sets the threshold.
    CHECK(cloudy_texels >= r.cover.size() - 6);
  }
}
