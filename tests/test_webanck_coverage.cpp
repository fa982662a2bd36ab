// The coverage windows of Webanck's forms (shaders/lib/webanck_forms.glsl, docs/layers.md
// "Coverage windows"): the share of the columns through a layer that hold cloud (optical depth 1
// or more) equals the weather's coverage c, by Monte Carlo over the exact fields. The hidden case
// [.calibration] derives the tables that the library holds.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <vector>

#include "render/cloud_renderer.hpp"
#include "shader_math/shader_math.hpp"

using namespace nephele::glsl;

namespace {

// The rules' layers (regional/cloud_layers.cpp): cumulus 1500 m thick from 1000 m above the
// ground, extinction 0.04 per m at density 1; alto 1500 m from 3500 m, 0.01 per m.
constexpr float kCumulusBase = 1000, kAltoBase = 3500, kThickness = 1500;
constexpr float kCumulusExtinction = 4e-2f, kAltoExtinction = 1e-2f;
// A column holds cloud where its optical depth reaches this: the orbit view's thinnest drawn cloud
// (tau of cover 0.1 by the fallback, 0.86) and more, opaque to two thirds.
constexpr double kCloudyDepth = 1.0;
constexpr int kHeights = 32;  // midpoints through the layer

// The exact fields at kHeights points of n columns at random positions of p_n (units of 108 km),
// spread over 50 x 50 units (750 periods of the coarsest field, n2's), of one noise seed; and the
// turbulence of the marcher's detail erosion of the cumulus (cloud_march.glsl's detail_eroded):
// the noise volume's detail channel (noise_volume_detail_fbm, which the host rank-equalises) over
// DETAIL_PERIOD metres, here equalised over the samples.
struct Columns {
  int n = 0;
  std::vector<vec4> shape, detail;  // cumulus n2..n5, n6..n9
  std::vector<vec3> alto;           // alto n1..n3
  std::vector<float> turbulence;    // at the cumulus's points
  Columns(int count, unsigned position_seed, uint noise_seed) : n(count) {
    const FbmParams volume_detail = noise_volume_detail_fbm(noise_seed);
    std::mt19937 rng(position_seed);
    std::uniform_real_distribution<float> u(0.0f, 50.0f);
    for (int i = 0; i < n; ++i) {
      const float x = u(rng), y = u(rng);
      for (int j = 0; j < kHeights; ++j) {
        const float h = (j + 0.5f) / kHeights;
        vec4 a, b;
        const vec3 pn(x, y, (kCumulusBase + kThickness * h) / 108000.0f);
        cumulus_fields_exact(pn, 0.0f, noise_seed, a, b);
        turbulence.push_back(inverted_worley_fbm(pn * (108000.0f / DETAIL_PERIOD), volume_detail).w);
        shape.push_back(a);
        detail.push_back(b);
        alto.push_back(alto_fields_exact(vec3(x, y, (kAltoBase + kThickness * h) / 108000.0f), 0.0f, noise_seed));
      }
    }
    std::vector<float> sorted = turbulence;
    std::sort(sorted.begin(), sorted.end());
    for (float& t : turbulence)
      t = float(std::lower_bound(sorted.begin(), sorted.end(), t) - sorted.begin()) / float(sorted.size());
  }
};

// The share of columns whose optical depth, midpoint rule over the heights, reaches kCloudyDepth,
// the density at column i, height j, fraction h given by `density`.
double cloudy_share(const Columns& columns, double extinction, const std::function<float(int, float)>& density) {
  int cloudy = 0;
  for (int i = 0; i < columns.n; ++i) {
    double depth = 0;
    for (int j = 0; j < kHeights; ++j) depth += density(i * kHeights + j, (j + 0.5f) / kHeights);
    cloudy += depth * extinction * kThickness / kHeights >= kCloudyDepth;
  }
  return cloudy / double(columns.n);
}

// Cumulus of phi and delta's weight (phi_weight) at each point, as the marcher draws it close up.
double cumulus_share(const Columns& columns, const std::function<vec2(vec4, float)>& phi_weight) {
  return cloudy_share(columns, kCumulusExtinction, [&](int k, float h) {
    const vec4 d = columns.detail[k];
    const vec2 w = phi_weight(columns.shape[k], h);
    float density = std::max(w.x - w.y * cumulus_delta(d.x, d.y, d.z, d.w), 0.0f);
    // detail_eroded: a density in (0, 1) eroded by the turbulence, a core (1 or more) left alone.
    if (density > 0.0f && density < 1.0f)
      density = model_erode(density, columns.turbulence[k], nephele::render::detail_erosion_strength);
    return density * cumulus_gate(h);
  });
}

double alto_share(const Columns& columns, float k, const std::function<vec2(float)>& phi_weight) {
  return cloudy_share(columns, kAltoExtinction, [&](int i, float h) {
    const vec3 n = columns.alto[i];
    const vec2 w = phi_weight(n.x);
    return std::max(w.x - w.y * alto_delta(k, n.y, n.z), 0.0f) * alto_gate(h);
  });
}

// p in [lo, hi] where share(p), growing, meets c.
double invert(const std::function<double(double)>& share, double c, double lo, double hi) {
  for (int k = 0; k < 30; ++k) {
    const double mid = 0.5 * (lo + hi);
    (share(mid) < c ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

TEST_CASE("print the coverage windows' tables: p at c = i / 16 (regenerates webanck_forms.glsl's)", "[.calibration]") {
  const Columns columns(3000, 3, 7u);
  // The share leaves 0 and reaches 1 steeply (a window that covers few columns covers few points
  // of each; the last columns fill at the forms' edges): the end knots are the lines through the
  // two nearest knots, extended, so that the table is linear to the ends of (0, 1) and c = 0 is
  // left to the forms' "no coverage, no cloud".
  const auto print = [](const char* name, const std::function<double(double)>& p_of_c) {
    std::vector<double> p(17);
    for (int i = 1; i < 16; ++i) p[i] = p_of_c(i / 16.0);
    p[0] = 2 * p[1] - p[2];
    p[16] = 2 * p[15] - p[14];
    std::printf("%s:", name);
    for (double v : p) std::printf(" %.4ff", v);
    std::printf("\n");
  };
  print("CUMULUS_WINDOW_KNOTS", [&](double c) {
    return invert(
        [&](double p) {
          const vec3 w = cumulus_window(float(p));
          return cumulus_share(columns, [&](vec4 s, float h) {
            return vec2(cumulus_phi(s.x, s.y, s.z, s.w, w.x + 0.25f * h) + w.z, w.y);
          });
        },
        c, 0.0, 3.0);
  });
  print("ALTOCUMULUS_WINDOW_KNOTS", [&](double c) {
    return invert(
        [&](double p) {
          const vec2 w = altocumulus_window(float(p));
          return alto_share(columns, 0.0f,
                            [&](float n1) { return vec2(hermite_step(0.43f + w.x, 1.0f + w.x, n1), w.y); });
        },
        c, 0.0, 2.0);
  });
  print("ALTOSTRATUS_COVER_KNOTS", [&](double c) {
    return invert(
        [&](double p) {
          return alto_share(columns, 1.0f, [&](float n1) { return vec2(sheet_amount(float(p), n1), 0.0f); });
        },
        c, 0.0, 1.0);
  });
}

TEST_CASE("knots17 interpolates its seventeen values linearly at x = i / 16 and clamps x to 0..1", "[fast][webanck]") {
  mat4 a(0.0f);
  for (int i = 0; i < 16; ++i) a[i / 4][i % 4] = float(i * i);
  CHECK(knots17(a, 256.0f, 0.0f) == 0.0f);
  CHECK(knots17(a, 256.0f, 5.0f / 16.0f) == 25.0f);
  CHECK(knots17(a, 256.0f, 5.5f / 16.0f) == Approx(30.5).margin(1e-4));      // (25 + 36) / 2
  CHECK(knots17(a, 256.0f, 15.25f / 16.0f) == Approx(232.75).margin(1e-4));  // 225 + (256 - 225) / 4
  CHECK(knots17(a, 256.0f, 1.0f) == 256.0f);
  CHECK(knots17(a, 256.0f, -1.0f) == 0.0f);
  CHECK(knots17(a, 256.0f, 2.0f) == 256.0f);
}

TEST_CASE("the windows' paths: nothing at p = 0, the paper's forms on the way, delta's weight 0 at p = 2",
          "[fast][webanck]") {
  // Cumulus: the window [0.45 + s, 0.65 + s] starts above every n2 <= 1 and ends below every n2 >= 0.
  CHECK(cumulus_window(0.0f).x == Approx(0.55f));
  CHECK(cumulus_window(1.0f).x == Approx(-0.65f));
  CHECK(cumulus_window(0.55f / 1.2f).x == Approx(0.0f).margin(1e-6));  // the paper's
  CHECK(cumulus_window(1.0f).y == 1.0f);
  CHECK(cumulus_window(2.0f).y == 0.0f);
  CHECK(cumulus_window(2.0f).x == Approx(-0.65f));
  CHECK(cumulus_window(2.0f).z == 0.0f);
  CHECK(cumulus_window(3.0f).z == 1.0f);
  CHECK(cumulus_phi(1.0f, 1.0f, 0.0f, 0.0f, cumulus_window(0.0f).x) == 0.0f);
  CHECK(cumulus_phi(0.0f, 0.5f, 0.0f, 0.0f, cumulus_window(1.0f).x) == 1.0f);
  // Altocumulus: [0.43 + s, 1 + s] from [1, 1.57] through the paper's [0.43, 1] to [-0.57, 0].
  CHECK(altocumulus_window(0.0f).x == Approx(0.57f));
  CHECK(altocumulus_window(0.57f).x == Approx(0.0f).margin(1e-6));
  CHECK(altocumulus_window(2.0f).x == Approx(-1.0f));
  CHECK(altocumulus_window(2.0f).y == 0.0f);
  // At the path's end every point has phi 1 and no erosion: alto's cells and sheet alike.
  CHECK(hermite_step(0.43f + altocumulus_window(2.0f).x, 1.0f + altocumulus_window(2.0f).x, 0.0f) == 1.0f);
  CHECK(cumulus_phi(0.0f, 0.5f, 0.0f, 0.0f, cumulus_window(2.0f).x) == 1.0f);
  // and past it the cumulus's phi is lifted to 1 and more wherever n3 is 0.
  CHECK(cumulus_phi(0.7f, 0.0f, 0.0f, 0.0f, cumulus_window(3.0f).x) + cumulus_window(3.0f).z == 1.0f);
  // No coverage, no cloud, whatever the fields (the tables' first knots lie above p = 0).
  for (float k : {0.0f, 0.5f, 1.0f})
    for (float n1 : {0.0f, 0.5f, 1.0f}) CHECK(alto_phi_at(k, 0.0f, n1).x == 0.0f);
  CHECK(cumulus_phi_at(vec4(1.0f, 1.0f, 0.0f, 0.0f), 0.0f, 0.0f).x == 0.0f);
}

namespace {
// The tolerance of a share estimated from n columns at coverage c: 4 binomial standard errors,
// sqrt(c (1 - c) / n) (the columns lie hundreds of field periods apart, close to independent),
// plus the table's interpolation between knots 1/16 apart: within 0.01 inside (0.008 measured at
// the intervals' midpoints), 0.025 in the two end intervals, whose lines are extended from their
// neighbours (0.021 measured at c = 1/64, where the share still rises steeply from 0).
double share_tolerance(double c, int n) {
  const bool end_interval = c < 1.0 / 16 || c > 15.0 / 16;
  return 4 * std::sqrt(c * (1 - c) / n) + (end_interval ? 0.025 : 0.01);
}
}  // namespace

TEST_CASE("the cumulus and alto windows cover the share c of the columns, on fields of another seed", "[webanck]") {
  // Other columns and another noise seed than the calibration's: the tables hold for the fields,
  // not for one sample of them.
  const int n = 2000;
  const Columns columns(n, 11, 5u);
  for (double c : {0.015625, 0.03125, 0.15625, 0.25, 0.40625, 0.5, 0.65625, 0.78125, 0.90625, 0.96875, 1.0}) {
    INFO("coverage " << c);
    const double cumulus = cumulus_share(columns, [&](vec4 s, float h) { return cumulus_phi_at(s, float(c), h); });
    const double altocumulus = alto_share(columns, 0.0f, [&](float n1) { return alto_phi_at(0.0f, float(c), n1); });
    const double altostratus = alto_share(columns, 1.0f, [&](float n1) { return alto_phi_at(1.0f, float(c), n1); });
    CHECK(cumulus == Approx(c).margin(share_tolerance(c, n)));
    CHECK(altocumulus == Approx(c).margin(share_tolerance(c, n)));
    CHECK(altostratus == Approx(c).margin(share_tolerance(c, n)));
    // Between the two, both parts grow with n1 and so share their cloud: c again (measured: within
    // 0.02 of the pure forms' shares).
    const double mixed = alto_share(columns, 0.5f, [&](float n1) { return alto_phi_at(0.5f, float(c), n1); });
    CHECK(mixed == Approx(c).margin(share_tolerance(c, n)));
    std::printf("c %.4f cumulus %.4f altocumulus %.4f altostratus %.4f mixed %.4f\n", c, cumulus, altocumulus,
                altostratus, mixed);
  }
}
