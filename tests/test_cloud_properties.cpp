// The cloud's optical thickness and cloud-top height (shaders/lib/cloud_properties.glsl): the
// functions on the CPU, the calibration's tails, and the remap's fields on the GPU.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <vector>

#include <glm/glm.hpp>

#include "cover/coverage_threshold.hpp"
#include "cover/global_cover.hpp"
#include "cover/solid_angle.hpp"
#include "gl_support.hpp"
#include "shader_math/shader_math.hpp"
#include "steady_cover.hpp"
#include "studies/cover_statistics.hpp"

using namespace nephele;

namespace {

// Abramowitz and Stegun 26.2.23 bounds its error in z by 4.5e-4.
constexpr double kQuantile = 4.5e-4;

double normal_cdf(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }

}  // namespace

TEST_CASE("normal_quantile inverts the normal distribution within the approximation's bound", "[fast][properties]") {
  for (double z : {-3.0, -2.0, -1.0, -0.3, 0.0, 0.2, 1.0, 1.959964, 3.0}) {
    const float p = static_cast<float>(normal_cdf(z));
    INFO("z " << z);
    // The float p's rounding moves z by at most 2^-24 p / phi(z), under 1e-6 here.
    CHECK(glsl::normal_quantile(p) == Approx(z).margin(kQuantile + 1e-6));
  }
  CHECK(glsl::normal_quantile(0.5f) == 0.0f);
}

TEST_CASE("ranks spread evenly give the log-normal's shares of ISCCP's thin, medium and thick cloud",
          "[fast][properties]") {
  const float median = 4.0f, spread = 1.2f;
  const int n = 100000;
  double thin = 0, thick = 0, log_sum = 0;
  for (int k = 0; k < n; ++k) {
    const float tau = glsl::optical_thickness_from_rank((k + 0.5f) / n, median, spread);
    thin += tau < 3.6f;
    thick += tau >= 23.0f;
    log_sum += std::log(tau);
  }
  // A share is Phi((ln tau_c - ln median) / spread); the quantile's error in z moves it by at most
  // phi(z) 4.5e-4 < 1.8e-4, the ranks' grid by 1/n.
  const double tolerance = 0.4 * kQuantile + 1.0 / n;
  CHECK(thin / n == Approx(normal_cdf(std::log(3.6 / 4.0) / 1.2)).margin(tolerance));
  CHECK(thick / n == Approx(1.0 - normal_cdf(std::log(23.0 / 4.0) / 1.2)).margin(tolerance));
  CHECK(thin / n == Approx(0.465).margin(0.001));
  CHECK(thick / n == Approx(0.0725).margin(0.001));
  // The mean of ln tau is ln median (the ranks are symmetric about 1/2; the limits clip both tails alike).
  CHECK(log_sum / n == Approx(std::log(4.0)).margin(1e-3));
  // The limits bound tau: median exp(+-3.09 spread).
  CHECK(glsl::optical_thickness_from_rank(0.0f, median, spread) ==
        Approx(median * std::exp(-3.0902 * spread)).epsilon(2e-3));
  CHECK(glsl::optical_thickness_from_cover(0.0f, median, spread) == 0.0f);
  CHECK(glsl::optical_thickness_from_cover(0.5f, median, spread) == Approx(median).epsilon(1e-6));
}

TEST_CASE("cloud tops follow the cloud type: decks low, fronts middle, cirrus high, anvils at the tropopause",
          "[fast][properties]") {
  const auto top = [](float frontal, float deep, float cumulus, float cirrus, float latitude, float cyclonic,
                      float bias) {
    glsl::CloudTypes t{};
    t.frontal = frontal;
    t.deep_convection = deep;
    t.cumulus = cumulus;
    t.cirrus = cirrus;
    return glsl::cloud_top_km(t, latitude, cyclonic, bias);
  };
  const float deg = static_cast<float>(M_PI / 180.0);
  CHECK(glsl::tropopause_km(0.0f) == Approx(16.0f));
  CHECK(glsl::tropopause_km(90.0f * deg) == Approx(9.0f).margin(1e-5));
  CHECK(top(0, 0, 0, 0, 45 * deg, 0, 0) == Approx(2.0f));  // boundary-layer cloud
  CHECK(top(0, 0, 0, 0, 20 * deg, 0, 0) == Approx(2.0f));  // under the trade inversion
  CHECK(top(0, 0, 0, 0, 20 * deg, 0, 1) == Approx(1.5f));  // a stratocumulus deck
  // The cyclones' ascent deepens it: to the cirrus level at the deepest, ISCCP's middle class
  // (3.2-6.5 km) half way.
  CHECK(top(0, 0, 0, 0, 50 * deg, glsl::ASCENT_ONSET, 0) == Approx(2.0f));
  CHECK(top(0, 0, 0, 0, 50 * deg, 0.6f, 0) == Approx(glsl::tropopause_km(50 * deg) - 2.0f));
  const float half_way = top(0, 0, 0, 0, 50 * deg, 0.5f * (glsl::ASCENT_ONSET + glsl::ASCENT_FULL), 0);
  CHECK(half_way == Approx(0.5f * (2.0f + glsl::tropopause_km(50 * deg) - 2.0f)));
  CHECK(half_way > 3.2f);
  CHECK(half_way < 6.5f);
  CHECK(top(0, 0, 1, 0, 15 * deg, 0, 0) == Approx(2.0f));                                  // trade cumulus
  CHECK(top(1, 0, 0, 0, 50 * deg, 0, 0) == Approx(8.0f));                                  // the comma's shield
  CHECK(top(0, 1, 0, 0, 5 * deg, 0, 0) == Approx(glsl::tropopause_km(5 * deg) - 1.0f));    // anvils
  CHECK(top(0, 0, 0, 1, 50 * deg, 0, 0) == Approx(glsl::tropopause_km(50 * deg) - 2.0f));  // cirrus
  // A system over lower cloud shows its own top where it is whole, and the higher type wins.
  CHECK(top(1, 0, 0, 1, 50 * deg, 0, 0) == Approx(glsl::tropopause_km(50 * deg) - 2.0f));
  CHECK(top(0.5f, 0, 0, 0, 50 * deg, 0, 0) == Approx(5.0f));
  CHECK(glsl::cloud_top_from_cover(0.0f, 0.0f) == 0.0f);
  CHECK(glsl::cloud_top_from_cover(0.5f, 45 * deg) == Approx(2.0f));
  CHECK(glsl::cloud_top_from_cover(1.0f, 45 * deg) == Approx(8.0f));
}

TEST_CASE("clouds are as deep as their optical thickness makes them: decks shallow, cumulonimbus to the ground",
          "[fast][properties]") {
  CHECK(glsl::cloud_thickness_km(1.5f, 4.0f) == Approx(0.3f).margin(1e-3));   // a stratocumulus deck
  CHECK(glsl::cloud_thickness_km(2.0f, 3.0f) == Approx(0.45f).margin(1e-3));  // trade cumulus
  CHECK(glsl::cloud_thickness_km(15.0f, 80.0f) == Approx(14.5f));             // a cumulonimbus from 0.5 km
  const float shield = glsl::cloud_thickness_km(8.0f, 20.0f);
  CHECK(shield > 2.5f);
  CHECK(shield < 5.0f);
  // Deeper with tau at one top; never thinner than 300 m nor reaching below 200 m under the top's
  // floor.
  float previous = 0.0f;
  for (float tau = 0.5f; tau < 100.0f; tau *= 1.5f) {
    const float h = glsl::cloud_thickness_km(10.0f, tau);
    CHECK(h >= previous);
    previous = h;
  }
  CHECK(glsl::cloud_thickness_km(0.15f, 1.0f) == Approx(0.3f));
}

TEST_CASE("a partly cloudy texel is as transparent as its clear share and its cloud's transmittance",
          "[fast][properties]") {
  for (float c : {0.0f, 0.15f, 0.5f, 0.9f, 1.0f})
    for (float tau : {0.15f, 1.0f, 10.0f, 50.0f}) {
      INFO("cover " << c << " tau " << tau);
      const double expected = -std::log((1.0 - c) + c * std::exp(-double(tau)));
      CHECK(glsl::covered_optical_depth(c, tau) == Approx(expected).epsilon(1e-5).margin(1e-6));
    }
  // Whole thick cloud keeps its depth where exp(-tau) underflows in float.
  CHECK(glsl::covered_optical_depth(1.0f, 163.0f) == 163.0f);
  CHECK(glsl::covered_optical_depth(0.999f, 163.0f) == Approx(-std::log(0.001)).epsilon(1e-3));
}

TEST_CASE("band tails fall from 1 to 0 with each bin's weight", "[fast][properties]") {
  std::vector<double> histogram(2 * cover::band_bins, 0.0);
  histogram[10] = 0.25;
  histogram[20] = 0.75;  // band 0: two bins; band 1: empty
  const std::vector<float> tails = cover::band_tails(histogram, 2);
  REQUIRE(tails.size() == 2u * (cover::band_bins + 1));
  CHECK(tails[0] == 1.0f);
  CHECK(tails[10] == 1.0f);
  CHECK(tails[11] == 0.75f);
  CHECK(tails[20] == 0.75f);
  CHECK(tails[21] == 0.0f);
  CHECK(tails[cover::band_bins] == 0.0f);
  // A band without weight falls linearly, so that its ranks stay defined.
  const float* empty = tails.data() + cover::band_bins + 1;
  CHECK(empty[0] == 1.0f);
  CHECK(empty[cover::band_bins / 2] == 0.5f);
  CHECK(empty[cover::band_bins] == 0.0f);
  CHECK_THROWS(cover::band_tails(histogram, 3));
}

TEST_CASE("the remap's optical thickness follows each cloudy texel's rank in density, and clear texels have none",
          "[pass][properties]") {
  test::test_context();
  cover::CoverParameters p = test::steady_cover();
  p.size = 32;
  p.profile = cover::flat_profile();  // one band: the rank is over the sphere's cloudy texels
  cover::GlobalCover cover(p);
  cover.run();
  const std::vector<float> density = cover.density_field().read();
  const std::vector<float> covered = cover.cover_field().read();
  const std::vector<float> tau = cover.optical_thickness_field().read();
  const std::vector<float> top = cover.cloud_top_field().read();
  const std::vector<double> weights = cover::face_texel_solid_angles(p.size);
  const cover::CoverageCalibration& c = cover.calibration();

  // The exact ranks: the cloudy solid angle below each cloudy texel's density, over the whole.
  std::vector<size_t> cloudy;
  for (size_t k = 0; k < density.size(); ++k)
    if (density[k] > c.threshold) cloudy.push_back(k);
  REQUIRE(cloudy.size() > 100);
  std::sort(cloudy.begin(), cloudy.end(), [&](size_t a, size_t b) { return density[a] < density[b]; });
  double total = 0;
  for (size_t k : cloudy) total += weights[k % weights.size()];
  // The GPU interpolates the tails linearly inside the calibration's coarse bins; a rank is off
  // by at most the weight of the bins holding the density and the threshold, over the cloudy
  // weight: twice the heaviest bin's.
  const float scale = cover::band_bin_scale(c.density_min, c.density_max);
  std::vector<double> bins(cover::band_bins, 0.0);
  for (size_t k = 0; k < density.size(); ++k)
    bins[std::min(cover::band_bins - 1, static_cast<int>((density[k] - c.density_min) * scale))] +=
        weights[k % weights.size()];
  const double rank_error = 2.0 * *std::max_element(bins.begin(), bins.end()) / total;
  INFO("rank error bound " << rank_error);
  REQUIRE(rank_error < 0.2);
  double below = 0;
  for (size_t k : cloudy) {
    const double w = weights[k % weights.size()];
    const float rank = static_cast<float>((below + 0.5 * w) / total);
    below += w;
    // The bracket of the ranks within the bound, widened by the functions' float rounding.
    const float low =
        glsl::optical_thickness_from_rank(rank - static_cast<float>(rank_error), p.tau_median, p.tau_spread);
    const float high =
        glsl::optical_thickness_from_rank(rank + static_cast<float>(rank_error), p.tau_median, p.tau_spread);
    INFO("texel " << k << " rank " << rank << " tau " << tau[k] << " in [" << low << ", " << high << "]");
    REQUIRE(tau[k] >= low * (1.0f - 1e-5f));
    REQUIRE(tau[k] <= high * (1.0f + 1e-5f));
  }
  for (size_t k = 0; k < density.size(); ++k) {
    INFO("texel " << k);
    REQUIRE((covered[k] > 0.0f) == (tau[k] > 0.0f));
    // Every cloudy texel has a top between the decks' and the tropical tropopause's.
    if (covered[k] > 0.0f) {
      REQUIRE(top[k] >= 1.5f);
      REQUIRE(top[k] <= 16.0f);
    } else {
      REQUIRE(top[k] == 0.0f);
    }
  }
}

namespace {

// A point of the 6371 km sphere `east` and `north` metres from 0 N 0 E along the tangent plane.
glm::vec3 sphere_point(double east, double north) {
  const double R = 6371000.0;
  const glm::dvec3 d = glm::normalize(glm::dvec3(1.0, east / R, north / R));
  return glm::vec3(R * d);
}

// The areas and perimeters (pixels, pixel edges to clear pixels) of the 4-connected cloudy
// objects of an n x n image that do not touch its border (those are cut off by it).
void object_areas_and_perimeters(const std::vector<char>& cloudy, int n, std::vector<double>& areas,
                                 std::vector<double>& perimeters) {
  std::vector<char> seen(cloudy.size(), 0);
  for (int start = 0; start < n * n; ++start) {
    if (!cloudy[start] || seen[start]) continue;
    std::vector<int> stack{start};
    seen[start] = 1;
    long area = 0, perimeter = 0;
    bool cut = false;
    while (!stack.empty()) {
      const int q = stack.back();
      stack.pop_back();
      ++area;
      const int i = q % n, j = q / n;
      cut = cut || i == 0 || j == 0 || i == n - 1 || j == n - 1;
      for (const auto& [di, dj] : {std::pair{-1, 0}, std::pair{1, 0}, std::pair{0, -1}, std::pair{0, 1}}) {
        const int x = i + di, y = j + dj;
        if (x < 0 || y < 0 || x >= n || y >= n) continue;
        const int r = y * n + x;
        if (!cloudy[r]) {
          ++perimeter;
        } else if (!seen[r]) {
          seen[r] = 1;
          stack.push_back(r);
        }
      }
    }
    if (!cut) {
      areas.push_back(double(area));
      perimeters.push_back(double(perimeter));
    }
  }
}

}  // namespace

TEST_CASE("the sub-texel cloud is the cover itself wherever a sample spans half a texel", "[fast][properties]") {
  const float texel = 20000.0f;
  std::mt19937 random(5);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f), share(0.0f, 1.0f);
  for (int k = 0; k < 200; ++k) {
    const glm::vec3 p = 6371000.0f * glm::normalize(glm::vec3(u(random), u(random), u(random)));
    const float c = k < 3 ? 0.5f * k : share(random);
    // The first octave's wavelength is one texel; it fades out by a footprint of half of it.
    const auto far = glsl::subtexel_cloud(p, c, texel, 0.5f * texel);
    CHECK(far.cover == c);
    CHECK(far.relief == 0.0f);
    CHECK(far.field == 0.0f);
    // Clear stays clear and overcast overcast, at any footprint.
    CHECK(glsl::subtexel_cloud(p, 0.0f, texel, 10.0f).cover == 0.0f);
    CHECK(glsl::subtexel_cloud(p, 1.0f, texel, 10.0f).cover == 1.0f);
    // The relief's bound, which lets renderers skip columns above the highest possible top.
    CHECK(std::abs(glsl::subtexel_cloud(p, c, texel, 1.0f).relief) < glsl::SUBTEXEL_RELIEF_BOUND);
    // More cover never makes a point clearer.
    CHECK(glsl::subtexel_cloud(p, std::min(c + 0.1f, 1.0f), texel, 300.0f).cover >=
          glsl::subtexel_cloud(p, c, texel, 300.0f).cover);
  }
}

TEST_CASE("high cloud thinner than deep convection is a veil the sub-texel cloud leaves whole and all else is carved",
          "[fast][properties]") {
  // ISCCP's classes (Rossow and Schiffer 1999): cirrus and cirrostratus (tops above 440 hPa, about
  // 6.5 km; tau below 23) are veils; cumulus, stratocumulus, the middle classes and deep
  // convection (high, tau above 23) break into clouds and clear sky.
  CHECK(glsl::subtexel_carving(9.0f, 1.0f) == 0.0f);    // cirrus
  CHECK(glsl::subtexel_carving(11.0f, 10.0f) == 0.0f);  // cirrostratus
  CHECK(glsl::subtexel_carving(1.5f, 1.0f) == 1.0f);    // cumulus
  CHECK(glsl::subtexel_carving(1.5f, 10.0f) == 1.0f);   // stratocumulus
  CHECK(glsl::subtexel_carving(4.0f, 2.0f) == 1.0f);    // altocumulus
  CHECK(glsl::subtexel_carving(14.0f, 60.0f) == 1.0f);  // deep convection
  // Between the classes it changes smoothly and only one way: less carving higher up, more where
  // thicker.
  for (float top = 0.0f; top < 16.0f; top += 0.25f)
    for (float tau = 0.0f; tau < 40.0f; tau += 0.5f) {
      const float carving = glsl::subtexel_carving(top, tau);
      REQUIRE(carving >= 0.0f);
      REQUIRE(carving <= 1.0f);
      CHECK(glsl::subtexel_carving(top + 0.25f, tau) <= carving);
      CHECK(glsl::subtexel_carving(top, tau + 0.5f) >= carving);
      // A smoothstep's slope is at most 1.5 over its span: 1.5 per km of top, 1.5 / 16 per unit of tau.
      CHECK(std::abs(glsl::subtexel_carving(top + 0.25f, tau) - carving) <= 1.5f * 0.25f + 1e-6f);
      CHECK(std::abs(glsl::subtexel_carving(top, tau + 0.5f) - carving) <= 1.5f / 16.0f * 0.5f + 1e-6f);
    }
}

TEST_CASE("the sub-texel cloud keeps the cover's share of the sky in expectation", "[properties]") {
  // Cloudy where the field n lies below sigma Phi^-1(c): the share is c exactly for a normal n.
  // The octave sum of gradient noise is near normal but not exactly; for a monotone function g
  // into [0, 1], |E g(n) - E g(normal)| is at most the Kolmogorov distance between their
  // distributions, measured here over the same points. Points spread over the whole sphere are
  // some 100 first wavelengths (40 km) apart: independent, so the sampling error is the
  // standard error of the shares.
  const float texel = 20000.0f;
  const int points = 20000;
  std::mt19937 random(7);
  std::normal_distribution<float> g;
  std::vector<glm::vec3> where(points);
  for (auto& p : where) p = 6371000.0f * glm::normalize(glm::vec3(g(random), g(random), g(random)));
  // A footprint of 1 m resolves all 12 octaves: the whole field, standardised.
  std::vector<double> field(points);
  for (int k = 0; k < points; ++k) field[k] = glsl::subtexel_cloud(where[k], 0.5f, texel, 1.0f).field;
  std::sort(field.begin(), field.end());
  double kolmogorov = 0;
  for (int k = 0; k < points; ++k)
    kolmogorov = std::max({kolmogorov, std::abs(normal_cdf(field[k]) - double(k) / points),
                           std::abs(normal_cdf(field[k]) - double(k + 1) / points)});
  INFO("Kolmogorov distance of the standardised field from the normal " << kolmogorov);
  CHECK(kolmogorov < 0.05);
  for (float c : {0.05f, 0.3f, 0.5f, 0.8f, 0.97f})
    for (float footprint : {1.0f, 2000.0f}) {  // sharp edges; the octaves below 4-8 km faded out
      double sum = 0, squares = 0;
      for (const auto& p : where) {
        const double share = glsl::subtexel_cloud(p, c, texel, footprint).cover;
        sum += share;
        squares += share * share;
      }
      const double mean = sum / points, error = std::sqrt((squares / points - mean * mean) / points);
      INFO("cover " << c << ", footprint " << footprint << " m: mean share " << mean << " +- " << error);
      CHECK(std::abs(mean - c) <= kolmogorov + 4 * error + kQuantile);
    }
}

TEST_CASE("the sub-texel cloud's optical thickness is log-normal inside, keeping the texel's reflectance on average",
          "[properties]") {
  // ln tau = ln tau_texel + spread u - c, u the relief's octaves standardised (`undulation`): over
  // 20000 points of the sphere (the octaves of 8 km and less are independent between them) u has
  // mean 0 and, wholly resolved, deviation 1, so ln tau has the deviation `spread` and the mean
  // ln tau_texel - c, c = (2 T - 1) spread^2 / 2 (T the slab's diffuse transmittance at tau_texel):
  // within 4 standard errors and the octave deviation's own accuracy (PERLIN_OCTAVE_SIGMA, 3 %).
  // Its correlation with the field that decides the cloudy share is g^k0 for relief octaves from
  // the k0-th on (the field's amplitudes g^k, the relief's weights falling by the same g): under
  // 20 km texels they start at the 5 km octave, k0 = 2, so 2^(-4/3) = 0.397, negative (thick where
  // the field is low, in the cores), within 4 standard errors of a correlation, (1 - rho^2) /
  // sqrt(n), and the octave sum's small departure from the normal. Where none of its octaves is
  // resolved the thickness is the texel's. The spread fades in with the texel's tau (smoothstep(1,
  // 3.6, tau): 0.330 of it at tau 2, all of it from 3.6), so thin cloud (tau 1 and less) is uniform.
  const float texel = 20000.0f, full_spread = 0.84f;
  const int points = 20000;
  std::mt19937 random(13);
  std::normal_distribution<float> g;
  std::vector<glm::vec3> where(points);
  for (auto& p : where) p = 6371000.0f * glm::normalize(glm::vec3(g(random), g(random), g(random)));
  for (float tau : {2.0f, 8.0f, 50.0f}) {
    const float spread = full_spread * glm::smoothstep(1.0f, 3.6f, tau);
    double sum = 0, squares = 0, cross = 0, field_squares = 0, share = 0;
    for (int k = 0; k < points; ++k) {
      const auto detail = glsl::subtexel_cloud(where[k], 0.5f, texel, 1.0f);
      const double l = std::log(double(glsl::subtexel_optical_thickness(tau, detail, full_spread))) - std::log(tau);
      sum += l;
      squares += l * l;
      cross += l * detail.field;
      field_squares += double(detail.field) * detail.field;
      share += detail.undulation_share / points;
      const auto far = glsl::subtexel_cloud(where[k], 0.5f, texel, 9000.0f);  // every octave of 10 km and less faded
      if (k < 200) CHECK(glsl::subtexel_optical_thickness(tau, far, full_spread) == tau);
      // Thin cloud keeps the texel's tau wherever its octaves are resolved.
      if (k < 200) CHECK(glsl::subtexel_optical_thickness(1.0f, detail, full_spread) == 1.0f);
    }
    const double mean = sum / points, deviation = std::sqrt(squares / points - mean * mean);
    // The field's mean is 0 (gradient noise), so the covariance is the mean product.
    const double correlation = (cross / points) / (deviation * std::sqrt(field_squares / points));
    const double c = (2 * glsl::slab_diffuse_transmittance(tau) - 1) * 0.5 * double(spread) * spread * share;
    INFO("tau " << tau << ": ln tau about the texel's: mean " << mean << " (expected " << -c << "), deviation "
                << deviation << " (spread " << spread << "), correlation with the field " << correlation
                << ", resolved share " << share);
    CHECK(share == Approx(1.0).margin(1e-6));
    CHECK(std::abs(mean + c) < 4 * spread / std::sqrt(double(points)));
    CHECK(std::abs(deviation - spread) < spread * (4 / std::sqrt(2.0 * points) + 0.03));
    const double rho = std::pow(2.0, -4.0 / 3.0);
    CHECK(std::abs(correlation + rho) < 4 * (1 - rho * rho) / std::sqrt(double(points)) + 0.02);
  }
  glsl::SubtexelCloud flat;
  flat.cover = 1.0f;
  flat.field = flat.relief = flat.undulation = flat.undulation_share = 0.0f;
  CHECK(glsl::subtexel_optical_thickness(8.0f, flat, full_spread) == 8.0f);
  flat.undulation = 1.0f;
  CHECK(glsl::subtexel_optical_thickness(8.0f, flat, 0.0f) == 8.0f);  // no spread: uniform
  CHECK(glsl::subtexel_optical_thickness(8.0f, flat, full_spread) ==
        Approx(8.0f * std::exp(full_spread)).epsilon(1e-6));
}

TEST_CASE("the sub-texel cloud's edges have the perimeter dimension of cloud edges, about 4/3", "[properties]") {
  // Level sets of a fractional Brownian field of Hurst exponent H have dimension 2 - H (Mandelbrot
  // 1982): 4/3 for the field's H = 2/3, the dimension Lovejoy (1982) found for clouds from the
  // relation of their perimeters P to their areas A, P ~ A^(D/2), which is measured here as
  // `nephele stats` does (docs/climate.md): on a 1024 x 1024 grid of 100 m spacing (the footprint)
  // under 5 km cover texels at a cover of 0.3 (isolated clouds), over the objects of 10 pixels and
  // more that the grid does not cut. The field's octaves reach from 10 km down to 200-400 m (the
  // finer ones fade out at this footprint), so the smallest objects' perimeters are smoother than
  // the scaling's and pixels round them: a fit over about 2.5 decades of area is within 0.1 of
  // the scaling's dimension (Lovejoy's own fit: 1.35 +- 0.05).
  const int n = 1024;
  const float texel = 5000.0f, spacing = 100.0f;
  std::vector<char> cloudy(n * n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      cloudy[j * n + i] =
          glsl::subtexel_cloud(sphere_point(i * spacing, j * spacing), 0.3f, texel, spacing).cover > 0.5f;
  std::vector<double> areas, perimeters;
  object_areas_and_perimeters(cloudy, n, areas, perimeters);
  const auto fit = studies::fit_power_law(areas, perimeters, 10.0, 1e9);
  INFO(fit.points << " objects, D = " << 2 * fit.slope);
  REQUIRE(fit.points >= 100);
  CHECK(std::abs(2 * fit.slope - 4.0 / 3.0) < 0.1);
  // Without the detail (a footprint of two texels) the cover's smooth field draws no edges at all.
  bool any_edge = false;
  for (int i = 0; i < n && !any_edge; i += 8) {
    const float c = glsl::subtexel_cloud(sphere_point(i * spacing, 0.0), 0.3f, texel, 2 * texel).cover;
    any_edge = c != 0.3f;
  }
  CHECK(!any_edge);
}
