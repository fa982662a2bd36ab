// The stiffness and folding measures on fields with known answers, the diagnostics' warnings,
// the loop budget of the warp pass, and the reduction of far noise offsets.
#include <catch2/catch.hpp>

#include <cmath>

#include "cover/cover_parameters.hpp"
#include "cover/integrators.hpp"
#include "cover/stability.hpp"
#include "shader_math/shader_math.hpp"
#include "tolerances.hpp"

using namespace nephele;
using namespace nephele::glsl;
using test::kUlp;

namespace {

// Flow rates from differences between texels of a size-32 map (texels about 0.05 rad apart):
// the solid-body rotation's rate omega |n_z| within 5% of omega everywhere, and the largest
// rate within 5% of omega. Empirical: the discretisation error of the differences over one or
// two texels (and across the seams) is not derived here.
constexpr double kRateRelative = 0.05;
// The share of the sphere beyond the stable step, 1 - 1.732 / 3: texels are counted whole, so
// the texels straddling the two circles |lat| = 35.3 deg decide it: half a texel (0.025 rad) on
// either side of 2 circles of length 2 pi cos(35.3 deg) = 5.13, over 4 pi: 2 x 5.13 x 0.025 /
// 12.57 = 0.020.
constexpr double kBeyondFraction = 0.02;
static_assert(kBeyondFraction >= 2 * 5.13 * 0.0245 / 12.57);
// The texel at a side face's centre of a size-64 map is half a texel (0.012 rad) from the
// equator; 0.05 is a loose check of that geometry.
constexpr float kNearEquator = 0.05f;
// A steep jet's pure shear at the equator: a rate below 10% of c k counts as zero. Empirical
// (the differences over a texel of a tanh of slope 40 per radian are not derived).
constexpr double kShearRateShare = 0.1;
// Folding measures of the identity, from differences of texel directions (float, within a few
// ulp, 2e-7) over texels 0.065 rad apart: Jacobians within about 2e-7 / 0.065 = 3e-6 of 1, so
// 1e-4 is 30x looser (kept as set); the same margin for the mirror's J = -1.
constexpr double kJacobian = 1e-4;
static_assert(kJacobian >= 4 * kUlp / 0.065);
constexpr double kIdentityAreaRms = 1e-4;
// The rotation by 0.7 rad in float (cos, sin and the products: a few ulp more per texel):
// 1e-3, empirical (10x the identity's; not derived).
constexpr double kRotatedAreaRms = 1e-3;
// The mirror's folded fraction is a ratio of texel counts (or solid angles) in double, all of
// them folded: 1 up to the sum's rounding; 1e-9 is far looser than that (kept as set).
constexpr double kMirrorFolded = 1e-9;
// Folding the south onto the north: the texel rows next to the equator have differences that
// straddle the fold and may count either way; on a size-24 map those are 2 rows of the 4 side
// faces, 192 of 3456 texels (5.6%), so 0.5 +- 0.05 is about half that band either way; partly
// derived (the band's solid angle is not computed).
constexpr double kFoldedHalf = 0.05;
// The reduced offset (below the period 3) in float against the exact reduction in double: one
// rounding, half an ulp of values below 4 (2^-23 = 1.2e-7); 1e-6 leaves a factor 8.
constexpr double kReducedOffset = 1e-6;
static_assert(kReducedOffset >= 2 * kUlp * 4);

// A cube map (RGBA, GL face order) of a vector field given as a function of the direction.
template <class Field>
std::vector<float> cube_of(int size, Field field) {
  std::vector<float> texels(static_cast<size_t>(4 * 6 * size * size), 0.0f);
  for (int face = 0; face < 6; ++face)
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i) {
        const vec3 v = field(texel_direction(face, i, j, size));
        const size_t k = (static_cast<size_t>(face) * size + j) * size + i;
        for (int c = 0; c < 3; ++c) texels[4 * k + c] = v[c];
      }
  return texels;
}

}  // namespace

TEST_CASE("the flow rate of a solid-body rotation is omega times the sine of the latitude", "[fast][stability]") {
  // v = omega k x n is a Killing field: its covariant derivative on the tangent plane is
  // omega n_z times a quarter turn, with eigenvalues +-i omega n_z.
  const float omega = 3.0f;
  const int size = 32;
  const auto rates = cover::flow_rates(cube_of(size, [&](vec3 n) { return omega * cross(vec3(0, 0, 1), n); }), size);
  double worst = 0;
  for (int face = 0; face < 6; ++face)
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i) {
        const vec3 n = texel_direction(face, i, j, size);
        const double rho = rates.spectral_radius[(static_cast<size_t>(face) * size + j) * size + i];
        worst = std::max(worst, std::abs(rho - omega * std::abs(n.z)));
      }
  INFO("largest deviation " << worst);
  CHECK(worst < kRateRelative * omega);  // differences over one or two texels
  CHECK(rates.max_rate == Approx(omega).epsilon(kRateRelative));
  const auto report = cover::stiffness_report(rates, 0.5, cover::Integrator::euler);
  CHECK(report.stiffness == Approx(0.5 * rates.max_rate));
  CHECK(!report.beyond());
  CHECK(report.beyond_fraction == 0.0);
  const auto stiff = cover::stiffness_report(rates, 1.0, cover::Integrator::adaptive);  // h rho up to 3 > 1.73
  CHECK(stiff.beyond());
  // Where h omega |n_z| > 1.732: |lat| > asin(0.577) = 35.3 deg, 1 - 0.577 = 42% of the sphere.
  CHECK(stiff.beyond_fraction == Approx(1.0 - 1.732 / 3.0).epsilon(0).margin(kBeyondFraction));
}

TEST_CASE("shear does not count as a rate of change: a jet across the equator has rate zero there",
          "[fast][stability]") {
  // u = c tanh(k lat) e_east: at the equator a pure shear du/dlat = c k, whose velocity
  // gradient is nilpotent (eigenvalues 0), however large c k is.
  const float c = 1.0f, k = 40.0f;
  const int size = 64;
  const auto rates = cover::flow_rates(cube_of(size,
                                               [&](vec3 n) {
                                                 const float lat = std::asin(n.z);
                                                 return c * std::tanh(k * lat) * normalize(cross(vec3(0, 0, 1), n));
                                               }),
                                       size);
  // The texel at each side face's centre lies half a texel from the equator.
  for (int face : {0, 1, 2, 3}) {
    const int i = size / 2, j = size / 2;
    const vec3 n = texel_direction(face, i, j, size);
    REQUIRE(std::abs(n.z) < kNearEquator);
    const double rho = rates.spectral_radius[(static_cast<size_t>(face) * size + j) * size + i];
    INFO("face " << face << " rho " << rho);
    CHECK(rho < kShearRateShare * c * k);
  }
}

TEST_CASE("folding is zero for rotations and total for a mirror image", "[fast][stability]") {
  const int size = 24;
  const auto identity = cube_of(size, [](vec3 n) { return n; });
  const auto id = cover::folding_report(identity, size);
  CHECK(id.folded_fraction == 0.0);
  CHECK(id.jacobian_min == Approx(1.0).epsilon(0).margin(kJacobian));
  CHECK(id.jacobian_max == Approx(1.0).epsilon(0).margin(kJacobian));
  CHECK(id.area_error_rms < kIdentityAreaRms);
  // A rotation preserves area and orientation: J = 1 (the exact flow map has J = 1 too).
  const auto rotated = cover::folding_report(cube_of(size,
                                                     [](vec3 n) {
                                                       const float a = 0.7f;
                                                       return vec3(std::cos(a) * n.x - std::sin(a) * n.y,
                                                                   std::sin(a) * n.x + std::cos(a) * n.y, n.z);
                                                     }),
                                             size);
  CHECK(rotated.folded_fraction == 0.0);
  CHECK(rotated.area_error_rms < kRotatedAreaRms);
  // A mirror image reverses orientation everywhere: J = -1.
  const auto mirror = cover::folding_report(cube_of(size, [](vec3 n) { return vec3(n.x, n.y, -n.z); }), size);
  CHECK(mirror.folded_fraction == Approx(1.0).epsilon(0).margin(kMirrorFolded));
  CHECK(mirror.jacobian_max == Approx(-1.0).epsilon(0).margin(kJacobian));
  // Folding the south onto the north reverses the southern half.
  const auto folded = cover::folding_report(cube_of(size, [](vec3 n) { return vec3(n.x, n.y, std::abs(n.z)); }), size);
  CHECK(folded.folded_fraction == Approx(0.5).epsilon(0).margin(kFoldedHalf));
}

TEST_CASE("the sub-step report counts attempts and the texels that ran out", "[fast][stability]") {
  const std::vector<float> warp{1, 0, 0, 10, 0, 1, 0, 20, 0, 0, 1, -30, 1, 0, 0, 0};
  const auto r = cover::substep_report(warp);
  CHECK(r.mean_attempts == Approx(15.0));
  CHECK(r.max_attempts == 30.0);
  CHECK(r.capped_texels == 1);
}

TEST_CASE("the diagnostics warn beyond the stable step and about capped texels but not for adaptive steps",
          "[fast][stability]") {
  const int size = 16;
  const float omega = 10.0f;
  const auto curl = cube_of(size, [&](vec3 n) { return omega * cross(vec3(0, 0, 1), n); });
  const auto identity = cube_of(size, [](vec3 n) { return n; });
  const auto calm = cover::diagnose_warp(curl, identity, size, cover::Integrator::rk4, 0.1);  // h rho <= 1
  CHECK(calm.warnings.empty());
  const auto stiff = cover::diagnose_warp(curl, identity, size, cover::Integrator::euler, 0.5);  // h rho <= 5
  REQUIRE(stiff.warnings.size() == 1);
  CHECK(stiff.warnings[0].find("--step") != std::string::npos);
  const auto adaptive = cover::diagnose_warp(curl, identity, size, cover::Integrator::adaptive, 0.5);
  CHECK(adaptive.warnings.empty());  // it sub-steps by itself
  auto capped = identity;
  capped[3] = -4096.0f;
  const auto ran_out = cover::diagnose_warp(curl, capped, size, cover::Integrator::adaptive, 0.5);
  REQUIRE(ran_out.warnings.size() == 1);
  CHECK(ran_out.warnings[0].find("--max-substeps") != std::string::npos);
  auto broken = identity;
  broken[0] = std::nanf("");
  // A NaN point also leaves its neighbours' area Jacobian undefined, reported as a fold.
  const auto nan_warnings = cover::diagnose_warp(curl, broken, size, cover::Integrator::rk4, 0.1).warnings;
  REQUIRE(nan_warnings.size() == 2);
  CHECK(nan_warnings[0].find("folds") != std::string::npos);
  CHECK(nan_warnings[1].find("not finite") != std::string::npos);
}

TEST_CASE("long warps are split so that no dispatch exceeds the shader loop budget", "[fast][stability]") {
  using cover::CurlMode;
  using cover::Integrator;
  for (Integrator integrator : cover::all_integrators())
    for (CurlMode mode : {CurlMode::sampled, CurlMode::procedural})
      for (int octaves : {0, 3, 16}) {
        const int steps = cover::steps_per_dispatch(integrator, mode, octaves);
        CHECK(steps >= 1);
        CHECK(steps * cover::loop_iterations_per_step(integrator, mode, octaves) <= cover::shader_loop_budget);
        CHECK(cover::shader_loop_budget < 65535);
      }
  // Sampled Euler has one loop iteration per step; RK4 adds its stage loop's 4: sampled 5,
  // procedural with 3 octaves 4 * 78 + 4 + 1.
  CHECK(cover::loop_iterations_per_step(Integrator::euler, CurlMode::sampled, 3) == 1);
  CHECK(cover::loop_iterations_per_step(Integrator::rk4, CurlMode::sampled, 3) == 5);
  CHECK(cover::loop_iterations_per_step(Integrator::rk4, CurlMode::procedural, 3) == 317);
}

TEST_CASE("noise offsets are reduced modulo a lattice period larger than the sphere", "[fast][stability]") {
  cover::NoiseOctaves o{2.0f, 3, 2.0f, 0.3f};
  CHECK(cover::offset_period_cells(o, 0.0) == 0);  // the default: not periodic, as before
  CHECK(cover::reduced_noise_offset(o, 0.0) == vec3(0.0f));
  const int cells = cover::offset_period_cells(o, 1e6);
  CHECK(cells == 6);
  const double period = cells / 2.0;
  CHECK(period > 2.0);
  for (double offset : {1e6, -1e6, 0.25, -0.25, 123456789.125}) {
    const vec3 r = cover::reduced_noise_offset(o, offset);
    INFO("offset " << offset);
    CHECK(r.x >= 0.0f);
    CHECK(r.x < period);
    CHECK(r.x == r.y);
    CHECK(r.y == r.z);
    const double expected = offset - period * std::floor(offset / period);
    CHECK(r.x == Approx(expected).epsilon(0).margin(kReducedOffset));
  }
  cover::CoverParameters p;
  p.noise_offset = 1e6;
  CHECK(cover::curl_params(p).potential_north.period == ivec3(6));
  CHECK(cover::density_params(p).period == ivec3(cover::offset_period_cells(p.density, 1e6)));
  p.noise_offset = 0.0;
  CHECK(cover::curl_params(p).potential_north.period == ivec3(0));
}
