// The GPU reductions of the cover (src/cover/gpu_reductions.hpp) against their CPU reference.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "steady_cover.hpp"
#include "cover/global_cover.hpp"
#include "cover/gpu_reductions.hpp"
#include "cover/solid_angle.hpp"
#include "gl_support.hpp"

using namespace nephele;

namespace {

std::vector<float> random_densities(int size, unsigned seed, int levels = 0) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-0.3f, 0.9f);
  std::vector<float> d(6 * static_cast<size_t>(size) * size);
  for (auto& x : d) x = levels ? std::floor(u(rng) * levels) / levels : u(rng);
  return d;
}

gpu::Texture upload(const std::vector<float>& densities, int size) {
  gpu::Texture t = gpu::Texture::cube(size, GL_R32F);
  t.write(densities);
  return t;
}

// The GPU calibration of `densities` at targets 0.1, 0.5 and 0.9 gives the CPU's threshold, and
// its fraction within the fixed-point sum's bound of the CPU's.
void check_calibration_matches_cpu(const std::vector<float>& densities, int size) {
  const gpu::Texture field = upload(densities, size);
  const cover::GpuCalibration gpu_calibration(size);
  for (double target : {0.1, 0.5, 0.9}) {
    const auto cpu = cover::calibrate_coverage(densities, size, target);
    const auto gpu = gpu_calibration.run(field, target);
    INFO("target " << target);
    CHECK(gpu.threshold == cpu.threshold);
    CHECK(std::abs(gpu.achieved_fraction - cpu.achieved_fraction) <=
          gpu_calibration.weights().units().sum_error_bound());
  }
}

}  // namespace

TEST_CASE("texel weight units sum to the sphere within half a unit per texel", "[fast][gpu-reduce]") {
  for (int size : {1, 2, 3, 16, 33, 256}) {
    const cover::TexelWeightUnits units = cover::texel_weight_units(size);
    const std::vector<double> exact = cover::face_texel_solid_angles(size);
    std::uint64_t sum = 0;
    double worst = 0.0;
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i) {
        const int a = std::min(i, size - 1 - i), b = std::min(j, size - 1 - j);
        const int lo = std::min(a, b), hi = std::max(a, b);
        const std::uint32_t u = units.octant[static_cast<size_t>(hi) * (hi + 1) / 2 + lo];
        sum += 6 * static_cast<std::uint64_t>(u);
        worst = std::max(worst, std::abs(units.fraction(u) - exact[static_cast<size_t>(j) * size + i] / (4 * M_PI)));
      }
    INFO("size " << size);
    // Rounding to units: half a unit; the mirrored texels' doubles differ from the octant's
    // only in their last bits (1e-16 relative), far below a unit (2^-31 of the largest).
    CHECK(worst <= std::ldexp(0.5, -units.scale_bits) * (1 + 1e-6));
    CHECK(std::abs(units.fraction(sum) - 1.0) <= units.sum_error_bound());
  }
}

TEST_CASE("the GPU calibration gives the CPU's threshold and its fraction within the unit rounding", "[gpu-reduce]") {
  test::test_context();
  for (int size : {1, 2, 3, 17, 64}) {
    const auto densities = random_densities(size, 7 + size);
    const gpu::Texture field = upload(densities, size);
    const cover::GpuCalibration gpu_calibration(size);
    for (double target : {0.0, 0.01, 0.25, 0.5, 0.67, 0.99, 1.0}) {
      const cover::CoverageCalibration cpu = cover::calibrate_coverage(densities, size, target);
      const cover::CoverageCalibration gpu = gpu_calibration.run(field, target);
      INFO("size " << size << " target " << target);
      const double bound = gpu_calibration.weights().units().sum_error_bound();
      // Two cuts equally near the target (size 1, target 0.25: 1/6 and 2/6) may go either way
      // with fixed-point sums; otherwise the cut is the same.
      const bool tie =
          std::abs(std::abs(gpu.achieved_fraction - target) - std::abs(cpu.achieved_fraction - target)) <= 2 * bound;
      if (gpu.threshold != cpu.threshold) {
        CHECK(tie);
        continue;
      }
      CHECK(gpu.density_min == cpu.density_min);
      CHECK(gpu.density_max == cpu.density_max);
      CHECK(gpu.max_texel_fraction == cpu.max_texel_fraction);
      CHECK(std::abs(gpu.achieved_fraction - cpu.achieved_fraction) <=
            gpu_calibration.weights().units().sum_error_bound());
    }
  }
}

TEST_CASE("the GPU calibration of a cover's density matches the CPU's on the same field", "[gpu-reduce]") {
  test::test_context();
  cover::CoverParameters p = test::steady_cover();
  p.size = 48;
  p.iterations = 10;
  p.profile = cover::flat_profile();
  cover::GlobalCover cover(p);
  cover.run();
  const cover::CoverageCalibration cpu = cover::calibrate_coverage(cover.density_field().read(), p.size, p.coverage);
  CHECK(cover.calibration().threshold == cpu.threshold);
  CHECK(std::abs(cover.calibration().achieved_fraction - cpu.achieved_fraction) <=
        cover::texel_weight_units(p.size).sum_error_bound());
}

TEST_CASE("the density and remap passes reduce the range and band fractions the calibration's own stages find",
          "[gpu-reduce][profile]") {
  // The passes reduce as they write (strips of 32 texels: size 45 leaves a partial strip and
  // partial workgroups); the same integer sums in any order, so equal to the bit.
  test::test_context();
  cover::CoverParameters p = test::steady_cover();
  p.size = 45;
  p.iterations = 10;
  cover::GlobalCover cover(p);
  cover.run();
  REQUIRE(cover.band_calibration());
  const cover::BandCalibration& fused = *cover.band_calibration();
  const cover::GpuCalibration separate(p.size);
  cover::BandCalibration own = separate.run_bands(cover.density_field(), fused.targets);
  separate.measure_bands(cover.density_field(), own);
  CHECK(fused.density_min == own.density_min);
  CHECK(fused.density_max == own.density_max);
  CHECK(fused.thresholds == own.thresholds);
  CHECK(fused.achieved == own.achieved);
  CHECK(fused.achieved_fraction == own.achieved_fraction);
  CHECK(cover.calibration().achieved_fraction == own.achieved_fraction);
  // And the cover is cloudy exactly where the measurement counted a texel.
  const std::vector<float> texels = cover.cover_field().read();
  const std::vector<float> densities = cover.density_field().read();
  cover::BandCalibration cpu = own;
  cover::measure_band_coverage(densities, p.size, cpu);
  CHECK(std::abs(cpu.achieved_fraction - fused.achieved_fraction) <= separate.weights().units().sum_error_bound());
  double cloudy = 0.0;
  const std::vector<double> solid = cover::face_texel_solid_angles(p.size);
  for (size_t k = 0; k < texels.size(); ++k)
    if (texels[k] > 0.0f) cloudy += solid[k % solid.size()];
  CHECK(std::abs(cloudy / (4.0 * M_PI) - fused.achieved_fraction) <=
        1e-9 + separate.weights().units().sum_error_bound());
}

TEST_CASE("fields with many equal densities are calibrated like the CPU", "[gpu-reduce]") {
  test::test_context();
  // Few distinct values: whole fine bins of equal densities, listed and sorted.
  const int size = 40;
  const auto densities = random_densities(size, 3, 5);
  check_calibration_matches_cpu(densities, size);
}

TEST_CASE("a flat field too large to list is all cloudy or all clear, whichever is nearer the target",
          "[gpu-reduce][extreme]") {
  test::test_context();
  // 6 * 105^2 > calibration_member_capacity texels of one density: only 0 or 1 is possible.
  const int size = 105;
  REQUIRE(6 * size * size > cover::calibration_member_capacity);
  const std::vector<float> flat(6 * size * size, 0.25f);
  const gpu::Texture field = upload(flat, size);
  const cover::GpuCalibration gpu_calibration(size);
  const double bound = gpu_calibration.weights().units().sum_error_bound();
  for (double target : {0.2, 0.8}) {
    const auto cpu = cover::calibrate_coverage(flat, size, target);
    const auto gpu = gpu_calibration.run(field, target);
    INFO("target " << target);
    // The nearer of all or nothing; never further from the target than the CPU's cut.
    CHECK(gpu.achieved_fraction == Approx(target < 0.5 ? 0.0 : 1.0).epsilon(0).margin(bound));
    CHECK(std::abs(gpu.achieved_fraction - target) <= std::abs(cpu.achieved_fraction - target) + bound);
    CHECK((gpu.threshold == 0.25f || gpu.threshold == std::nextafter(0.25f, -INFINITY)));
  }
}

namespace {

// GPU against CPU diagnosis. Both use float texel directions, rounded independently (a float
// normalize is within 2 ulp = 2^-22 per component); the differences of directions that the
// rates and Jacobians divide by span two texels, at least (2/N)/3 at a face corner, so their
// relative error is at most 2 * 2^-22 * 1.5 N, twice that for the ratio of two of them.
double direction_tolerance(int size) { return 2 * 2 * std::ldexp(1.0, -22) * 1.5 * size; }

void check_same_diagnosis(const cover::WarpDiagnostics& gpu, const cover::WarpDiagnostics& cpu, int size) {
  const double relative = direction_tolerance(size);
  const double fraction_bound = cover::texel_weight_units(size).sum_error_bound();
  CHECK(gpu.stiffness.max_rate == Approx(cpu.stiffness.max_rate).epsilon(relative));
  CHECK(gpu.stiffness.stiffness == Approx(cpu.stiffness.stiffness).epsilon(relative));
  CHECK(gpu.stiffness.limit == cpu.stiffness.limit);
  CHECK(gpu.folding.jacobian_min == Approx(cpu.folding.jacobian_min).epsilon(relative).margin(relative));
  CHECK(gpu.folding.jacobian_max == Approx(cpu.folding.jacobian_max).epsilon(relative));
  CHECK(gpu.folding.area_error_rms == Approx(cpu.folding.area_error_rms).epsilon(relative).margin(relative));
  // Fractions: a texel on the edge of a criterion could flip; none does in these fields, so
  // they differ by the unit rounding only.
  CHECK(std::abs(gpu.folding.folded_fraction - cpu.folding.folded_fraction) <= fraction_bound);
  CHECK(std::abs(gpu.stiffness.beyond_fraction - cpu.stiffness.beyond_fraction) <= fraction_bound);
  CHECK(gpu.substeps.mean_attempts == Approx(cpu.substeps.mean_attempts).epsilon(1e-12));
  CHECK(gpu.substeps.max_attempts == cpu.substeps.max_attempts);
  CHECK(gpu.substeps.capped_texels == cpu.substeps.capped_texels);
  CHECK(gpu.warnings.size() == cpu.warnings.size());
}

}  // namespace

TEST_CASE("the GPU diagnosis gives the CPU's stiffness, folding and sub-step figures", "[gpu-reduce]") {
  test::test_context();
  struct Case {
    int size, iterations;
    double step;
    cover::Integrator integrator;
  };
  for (const Case c : {Case{40, 50, 0.006, cover::Integrator::euler}, Case{33, 30, 0.05, cover::Integrator::euler},
                       Case{24, 10, 0.006, cover::Integrator::adaptive}, Case{2, 5, 0.006, cover::Integrator::heun},
                       Case{1, 5, 0.006, cover::Integrator::euler}}) {
    cover::CoverParameters p = test::steady_cover();
    p.size = c.size;
    p.iterations = c.iterations;
    p.step = c.step;
    p.integrator = c.integrator;
    cover::GlobalCover cover(p);
    cover.run_identity();
    cover.run_curl();
    cover.run_warp();
    const cover::WarpDiagnostics cpu =
        cover::diagnose_warp(cover.curl_field().read(), cover.warp_field().read(), p.size, p.integrator, p.step);
    const cover::WarpDiagnostics gpu = cover.diagnose();
    INFO("size " << c.size << " step " << c.step << " integrator " << cover::integrator_name(c.integrator)
                 << "; folded " << cpu.folding.folded_fraction << " beyond " << cpu.stiffness.beyond_fraction);
    check_same_diagnosis(gpu, cpu, c.size);
  }
}

TEST_CASE("the GPU diagnosis finds the folds of a mirror image", "[gpu-reduce]") {
  test::test_context();
  // A warp that mirrors x folds the whole sphere (J = -1); the CPU reference says the same.
  const int size = 20;
  cover::CoverParameters p = test::steady_cover();
  p.size = size;
  cover::GlobalCover cover(p);
  cover.run_identity();
  cover.run_curl();
  std::vector<float> mirrored = cover.identity_field().read();
  for (size_t k = 0; k < mirrored.size(); k += 4) mirrored[k] = -mirrored[k];
  cover.warp_field().write(mirrored);
  const auto cpu = cover::diagnose_warp(cover.curl_field().read(), mirrored, size, p.integrator, p.step);
  const auto gpu = cover.diagnose();
  CHECK(gpu.folding.folded_fraction ==
        Approx(1.0).epsilon(0).margin(cover::texel_weight_units(size).sum_error_bound()));
  check_same_diagnosis(gpu, cpu, size);
}

TEST_CASE("a crowded histogram bin is refined into fine bins and still gives the CPU's threshold", "[gpu-reduce]") {
  test::test_context();
  // All but one texel in the lowest of 4096 bins over [0, 1]: more than the listing holds,
  // so the fine level finds the crossing.
  const int size = 110;
  REQUIRE(6 * size * size > cover::calibration_member_capacity);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.0f, 1e-4f);
  std::vector<float> densities(6 * size * size);
  for (auto& d : densities) d = u(rng);
  densities[12345] = 1.0f;
  check_calibration_matches_cpu(densities, size);
}

TEST_CASE("the texel weights of a 16384 face read to the face centre: the table passes a storage block's 128 MiB",
          "[gpu-reduce]") {
  test::test_context();
  const int size = 16384;
  const cover::GpuTexelWeights weights(size);
  const cover::TexelWeightUnits& units = weights.units();
  REQUIRE(units.octant.size() * 4 > (size_t(1) << 27));  // past llvmpipe's storage block limit
  weights.bind();
  // Texels from the corner to the centre, the last of the table among them.
  const std::vector<glm::uvec4> texels = {{0, 0, 0, 0},       {5000, 3, 0, 0},    {8190, 8191, 0, 0},
                                          {8191, 8191, 0, 0}, {8192, 8192, 0, 0}, {16383, 8191, 0, 0}};
  const std::vector<glm::uvec4> gpu = test::probe<glm::uvec4>(
      "#include \"../cover/texel_weights.glsl\"",
      "uvec4(texel_weight(int(input_value.x), int(input_value.y), " + std::to_string(size) + "), 0u, 0u, 0u)", texels);
  for (size_t k = 0; k < texels.size(); ++k) {
    const glm::ivec2 texel(texels[k]);
    const int a = std::min(texel.x, size - 1 - texel.x), b = std::min(texel.y, size - 1 - texel.y);
    const int lo = std::min(a, b), hi = std::max(a, b);
    INFO("texel " << texel.x << ", " << texel.y);
    CHECK(gpu[k].x == units.octant[size_t(hi) * (hi + 1) / 2 + lo]);
    CHECK(gpu[k].x > 0u);
  }
}
