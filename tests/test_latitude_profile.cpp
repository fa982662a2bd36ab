// The coverage profile by latitude (docs/climate.md): the Earth curve and its rescaling, the
// seasonal shift, the CSV profile, the per-band calibration on the CPU and the GPU, and the
// smooth threshold of the remap pass.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include "cli_support.hpp"
#include "core/error.hpp"
#include "cover/coverage_threshold.hpp"
#include "cover/global_cover.hpp"
#include "cover/gpu_reductions.hpp"
#include "cover/latitude_profile.hpp"
#include "cover/solid_angle.hpp"
#include "gl_support.hpp"
#include "io/profile_files.hpp"
#include "shader_math/shader_math.hpp"

using namespace nephele;

namespace {

// Sums of 90 doubles in [0, 1] weighted by band areas: a few ulp each.
constexpr double kMeanRounding = 1e-12;

double area_mean(const std::vector<double>& targets) {
  const std::vector<double> areas = cover::band_areas(static_cast<int>(targets.size()));
  double mean = 0.0;
  for (size_t b = 0; b < targets.size(); ++b) mean += targets[b] * areas[b];
  return mean;
}

// Latitude of the centre of band b of 90.
double centre_deg(int band) { return -89.0 + 2.0 * band; }

int argmax_in(const std::vector<double>& t, double from_deg, double to_deg, bool minimum = false) {
  int best = -1;
  for (int b = 0; b < static_cast<int>(t.size()); ++b) {
    if (centre_deg(b) < from_deg || centre_deg(b) > to_deg) continue;
    if (best < 0 || (minimum ? t[b] < t[best] : t[b] > t[best])) best = b;
  }
  return best;
}

std::vector<float> random_densities(int size, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-0.3f, 0.9f);
  std::vector<float> d(6 * static_cast<size_t>(size) * size);
  for (auto& x : d) x = u(rng);
  return d;
}

std::string message_of(const std::string& csv) {
  try {
    io::parse_profile_csv(csv, "p.csv");
  } catch (const core::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("the Earth profile has the climatology's mean and features", "[fast][profile]") {
  const std::vector<double> t = cover::band_targets(cover::earth_profile(), 0, 0.67);
  REQUIRE(t.size() == 90);
  CHECK(std::abs(area_mean(t) - 0.67) <= kMeanRounding);
  // ITCZ maximum in the tropics at 5-10 N, subtropical minima near 20-30 N and S, the southern
  // storm track the cloudiest band, near 55-65 S, the northern one near 50-65 N.
  const int itcz = argmax_in(t, -15, 15);
  CHECK(centre_deg(itcz) >= 4.0);
  CHECK(centre_deg(itcz) <= 10.0);
  CHECK(t[itcz] == Approx(0.72).margin(0.02));
  for (double sign : {-1.0, 1.0}) {
    const int minimum = argmax_in(t, sign > 0 ? 15 : -35, sign > 0 ? 35 : -15, true);
    CHECK(std::abs(centre_deg(minimum)) >= 19.0);
    CHECK(std::abs(centre_deg(minimum)) <= 30.0);
    CHECK(t[minimum] >= 0.5);
    CHECK(t[minimum] <= 0.56);
  }
  const int south = argmax_in(t, -90, 90);
  CHECK(centre_deg(south) >= -65.0);
  CHECK(centre_deg(south) <= -55.0);
  const int north = argmax_in(t, 40, 90);
  CHECK(centre_deg(north) >= 50.0);
  CHECK(centre_deg(north) <= 65.0);
  CHECK(t[0] == Approx(0.63).margin(0.03));
  CHECK(t[89] == Approx(0.64).margin(0.03));
}

TEST_CASE("the profile is rescaled to any coverage keeping its order and [0, 1]", "[fast][profile]") {
  const std::vector<double> base = cover::band_targets(cover::earth_profile(), 0, 0.67);
  for (double coverage : {0.0, 0.1, 0.5, 0.67, 0.9, 1.0}) {
    const std::vector<double> t = cover::band_targets(cover::earth_profile(), 0, coverage);
    INFO("coverage " << coverage);
    CHECK(std::abs(area_mean(t) - coverage) <= kMeanRounding);
    for (size_t b = 0; b < t.size(); ++b) {
      REQUIRE(t[b] >= 0.0);
      REQUIRE(t[b] <= 1.0);
      // An increasing map of the Earth curve: bands keep their order.
      if (b > 0 && coverage > 0.0 && coverage < 1.0) REQUIRE((t[b] > t[b - 1]) == (base[b] > base[b - 1]));
    }
  }
}

TEST_CASE("the month option moves the ITCZ north in August and south in February", "[fast][profile]") {
  const auto itcz = [](int month) {
    return centre_deg(argmax_in(cover::band_targets(cover::earth_profile(), month, 0.67), -20, 20));
  };
  const double annual = itcz(0), august = itcz(8), february = itcz(2);
  // The shift is 5 degrees at the ITCZ (docs/climate.md); bands are 2 degrees wide.
  CHECK(august - annual >= 3.0);
  CHECK(august - annual <= 7.0);
  CHECK(annual - february >= 3.0);
  CHECK(annual - february <= 7.0);
  for (int month = 1; month <= 12; ++month) {
    INFO("month " << month);
    CHECK(cover::seasonal_shift_deg(90.0, month) == 0.0);  // the poles stay
    // 3 degrees at the storm tracks, plus the tail of the ITCZ term (2 e^-9 at 60 degrees).
    CHECK(std::abs(cover::seasonal_shift_deg(60.0, month)) <= 3.0 + 2.0 * std::exp(-9.0) + 1e-12);
  }
}

TEST_CASE("the profile curve passes through its knots without overshoot", "[fast][profile]") {
  const cover::LatitudeProfile p = cover::earth_profile();
  for (size_t k = 0; k < p.latitude_deg.size(); ++k)
    CHECK(cover::profile_fraction(p, p.latitude_deg[k]) == Approx(p.fraction[k]).margin(1e-12));
  for (size_t k = 0; k + 1 < p.latitude_deg.size(); ++k)
    for (int s = 1; s < 20; ++s) {
      const double x = p.latitude_deg[k] + (p.latitude_deg[k + 1] - p.latitude_deg[k]) * s / 20.0;
      const double f = cover::profile_fraction(p, x);
      REQUIRE(f >= std::min(p.fraction[k], p.fraction[k + 1]) - 1e-12);
      REQUIRE(f <= std::max(p.fraction[k], p.fraction[k + 1]) + 1e-12);
    }
}

TEST_CASE("a profile CSV takes a header, comments and rows, constant beyond its ends", "[fast][profile][io]") {
  const cover::LatitudeProfile p =
      io::parse_profile_csv("# zonal cover\nlatitude_deg,fraction\n\n-60, 0.8\n0,0.5\n# north\n60,0.2\n", "p.csv");
  REQUIRE(p.latitude_deg == std::vector<double>{-60, 0, 60});
  CHECK(cover::profile_fraction(p, -90) == 0.8);
  CHECK(cover::profile_fraction(p, 75) == 0.2);
  CHECK(cover::profile_fraction(p, 0) == 0.5);
  CHECK(io::parse_profile_csv("10,0.3\n", "one.csv").fraction == std::vector<double>{0.3});
}

TEST_CASE("every bad profile row is refused naming the file, line, field and range", "[fast][profile][io]") {
  CHECK(message_of("latitude_deg,fraction\n0,0.5\n-10,0.5\n").find("p.csv: line 3: latitude_deg") != std::string::npos);
  CHECK(message_of("0,1.5\n").find("p.csv: line 1: fraction") != std::string::npos);
  CHECK(message_of("0,1.5\n").find("0 to 1") != std::string::npos);
  CHECK(message_of("# c\n95,0.5\n").find("p.csv: line 2: latitude_deg") != std::string::npos);
  CHECK(message_of("95,0.5\n").find("-90 to 90") != std::string::npos);
  CHECK(message_of("0,0x1\n").find("line 1: fraction") != std::string::npos);
  CHECK(message_of("0;0.5\n").find("line 1") != std::string::npos);
  CHECK(message_of("0,0.5,1\n").find("latitude_deg,fraction") != std::string::npos);
  CHECK(message_of("# only a comment\n").find("p.csv") != std::string::npos);
  CHECK(message_of("0,nan\n").find("line 1: fraction") != std::string::npos);
  CHECK_THROWS_AS(io::read_profile_csv("/nonexistent/profile.csv"), core::InputError);
}

TEST_CASE("a band's threshold reaches its target within the texels of its crossing fine bin", "[fast][profile]") {
  const int size = 48;
  const std::vector<float> d = random_densities(size, 5);
  const std::vector<double> targets = cover::band_targets(cover::earth_profile(), 0, 0.67);
  const cover::BandCalibration c = cover::calibrate_band_coverage(d, size, targets);
  const float width = 1.0f / (cover::band_bin_scale(c.density_min, c.density_max) * cover::band_bins);
  const std::vector<double> weights = cover::face_texel_solid_angles(size);
  std::vector<double> cloudy(90, 0.0), near(90, 0.0), total(90, 0.0);
  const size_t per_face = static_cast<size_t>(size) * size;
  for (int face = 0; face < 6; ++face)
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i) {
        const size_t k = face * per_face + static_cast<size_t>(j) * size + i;
        const int band = glsl::band_of(glsl::band_coordinate(glsl::texel_direction(face, i, j, size), 90), 90);
        const double w = weights[k % per_face];
        total[band] += w;
        if (d[k] > c.thresholds[band]) cloudy[band] += w;
        if (std::abs(d[k] - c.thresholds[band]) <= width) near[band] += w;
      }
  for (int b = 0; b < 90; ++b) {
    if (total[b] == 0.0) continue;
    INFO("band " << b);
    CHECK(std::abs(cloudy[b] / total[b] - targets[b]) <= near[b] / total[b] + 1e-12);
  }
  // And the smooth threshold's fractions (measured) differ from the targets only by the
  // blending between neighbouring bands: on this field without structure, a few texels.
  CHECK(std::abs(c.achieved_fraction - 0.67) <= 0.01);
}

TEST_CASE("the GPU's band thresholds are the CPU's within one fine bin", "[profile][gpu-reduce]") {
  test::test_context();
  const std::vector<double> targets = cover::band_targets(cover::earth_profile(), 8, 0.6);
  for (int size : {17, 64}) {
    const std::vector<float> d = random_densities(size, 100 + size);
    gpu::Texture field = gpu::Texture::cube(size, GL_R32F);
    field.write(d);
    const cover::GpuCalibration gpu_calibration(size);
    cover::BandCalibration gpu = gpu_calibration.run_bands(field, targets);
    gpu_calibration.measure_bands(field, gpu);
    const cover::BandCalibration cpu = cover::calibrate_band_coverage(d, size, targets);
    const double units = gpu_calibration.weights().units().sum_error_bound();
    // Both pick the crossing fine bin from the same histograms (up to the units' rounding) and
    // place the threshold inside it: within one fine bin's width of each other.
    const float width = 1.0f / (cover::band_bin_scale(cpu.density_min, cpu.density_max) * cover::band_bins);
    INFO("size " << size);
    CHECK(gpu.density_min == cpu.density_min);
    CHECK(gpu.density_max == cpu.density_max);
    for (int b = 0; b < 90; ++b) {
      INFO("band " << b);
      CHECK(std::abs(gpu.band_weight[b] - cpu.band_weight[b]) <= units);
      CHECK(std::abs(gpu.thresholds[b] - cpu.thresholds[b]) <= width);
    }
    // The achieved fractions at the GPU's thresholds, measured on both sides: the same up to
    // the units' rounding and texels within float rounding of the smooth threshold (none here).
    cover::BandCalibration again = gpu;
    cover::measure_band_coverage(d, size, again);
    CHECK(std::abs(gpu.achieved_fraction - again.achieved_fraction) <= units);
  }
}

TEST_CASE("the smooth threshold has no steps at band edges and a continuous slope", "[fast][profile]") {
  std::vector<float> thresholds(90);
  std::mt19937 rng(3);
  for (float& t : thresholds) t = std::uniform_real_distribution<float>(0.2f, 0.6f)(rng);
  const auto at = [&](double latitude_deg) {
    const double r = latitude_deg * M_PI / 180.0;
    return static_cast<double>(cover::smooth_band_threshold(thresholds, glsl::vec3(std::cos(r), 0.0, std::sin(r))));
  };
  // Neighbouring centres differ by at most 0.4, so the Catmull-Rom slope is below
  // 1.5 x 0.4 per band = 0.3 per degree; float evaluation adds about 1e-6.
  const double slope = 0.3, rounding = 2e-6;
  for (int edge = -88; edge <= 88; edge += 2) {
    const double e = 1e-3;
    INFO("band edge " << edge);
    CHECK(std::abs(at(edge + e) - at(edge - e)) <= slope * 2 * e + rounding);
  }
  // C1 at the centres, where the cubic pieces meet: one-sided slopes over h agree within the
  // second derivative's h (below 6 x 0.4 per band^2 = 0.6 per degree^2) plus rounding / h.
  for (int centre = -87; centre <= 87; centre += 2) {
    const double h = 0.05;
    const double left = (at(centre) - at(centre - h)) / h, right = (at(centre + h) - at(centre)) / h;
    INFO("band centre " << centre);
    CHECK(std::abs(left - right) <= 0.6 * 2 * h + 2 * rounding / h);
  }
  // At the poles the curve is even: the same a little to either side of 90 degrees.
  CHECK(std::abs(at(89.9) - at(89.99)) <= slope * 0.1 + rounding);
}

TEST_CASE("the profile's remap pass gives the CPU's cover at the smooth threshold", "[profile][pass]") {
  test::test_context();
  cover::CoverParameters p;
  p.size = 32;
  p.iterations = 2;
  cover::GlobalCover cover(p);
  cover.run();
  REQUIRE(cover.band_calibration());
  const cover::BandCalibration& c = *cover.band_calibration();
  const std::vector<float> density = cover.density_field().read(), covered = cover.cover_field().read();
  const std::vector<float> contrast = cover.cover_contrast_field().read();
  // The band coordinate errs by 32 kArithmetic-like units (latitude_bands probe: 2.2e-4 of a
  // band); times the largest Catmull-Rom slope, 1.5 x the largest step between neighbouring
  // thresholds, plus the blend's and the ramp's rounding (a few ulp of values below 1).
  double step = 0.0;
  for (int b = 0; b + 1 < 90; ++b) step = std::max(step, std::abs(double(c.thresholds[b + 1]) - c.thresholds[b]));
  const double threshold_error = 2.2e-4 * 1.5 * step + 1e-6;
  const size_t per_face = 32 * 32;
  for (size_t k = 0; k < density.size(); ++k) {
    const int face = static_cast<int>(k / per_face), j = static_cast<int>(k % per_face / 32),
              i = static_cast<int>(k % 32);
    const float t = cover::smooth_band_threshold(c.thresholds, glsl::texel_direction(face, i, j, 32));
    const float expected = glsl::contrasted_cover(density[k], t, c.density_max, p.cover_softness, contrast[k]);
    // The remap's slope is (1 - COVER_EDGE) / softness (times the contrast, at most 1); within the
    // threshold's error of the threshold a texel may fall on either side of the edge's step.
    if (std::abs(density[k] - t) <= threshold_error) continue;
    REQUIRE(std::abs(covered[k] - expected) <= threshold_error * (1.0 - glsl::COVER_EDGE) / p.cover_softness + 1e-6);
  }
  // The sphere's fraction measured by the GPU is that of the written cover.
  CHECK(std::abs(cover::cloudy_fraction(covered, 32) - c.achieved_fraction) <=
        cover::texel_weight_units(32).sum_error_bound() + 1e-3);
}

TEST_CASE("generate takes --profile and --month, records them, and refuses bad ones with code 2", "[profile][cli]") {
  test::TemporaryDirectory out, files(true);
  const std::filesystem::path csv = files.path / "zonal.csv";
  std::ofstream(csv) << "latitude_deg,fraction\n-90,0.2\n0,0.9\n90,0.2\n";
  const test::Run ok =
      test::run("generate --size 16 --files faces --profile " + csv.string() + " --month 7 --out " + out.path.string());
  INFO(ok.output);
  REQUIRE(ok.exit_code == 0);
  const std::string sidecar = test::read_file(out.path / "cover.json");
  CHECK(sidecar.find("\"profile\": \"" + csv.string() + "\"") != std::string::npos);
  CHECK(sidecar.find("\"month\": 7") != std::string::npos);
  CHECK(sidecar.find("\"achieved\"") != std::string::npos);
  std::ofstream(files.path / "bad.csv") << "latitude_deg,fraction\n-90,0.2\n0,1.2\n";
  const test::Run bad = test::run("generate --size 8 --profile " + (files.path / "bad.csv").string() + " --out " +
                                  (files.path / "o").string());
  CHECK(bad.exit_code == 2);
  CHECK(bad.output.find("bad.csv: line 3: fraction") != std::string::npos);
  CHECK(test::run("generate --size 8 --month 13 --out " + (files.path / "o").string()).exit_code == 2);
  const test::Run flat = test::run("generate --size 8 --profile flat --month 3 --out " + (files.path / "o").string());
  CHECK(flat.exit_code == 2);
  CHECK(flat.output.find("--month") != std::string::npos);
  CHECK(!std::filesystem::exists(files.path / "o" / "cover.json"));
}
