// The global cover's GPU passes against their C++ twins, and the properties of the result.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <tuple>

#include "steady_cover.hpp"
#include "cover/global_cover.hpp"
#include "cover/moving_flow.hpp"
#include "cover/weather_systems.hpp"
#include "curl_bounds.hpp"
#include "cube_fields.hpp"
#include "gl_support.hpp"
#include "shader_math/shader_math.hpp"
#include "tolerances.hpp"

using namespace nephele;
using namespace nephele::glsl;

using test::as_vec4;
using test::index;
using test::kDirection;
using test::kFractionSum;
using test::kOperationRounding;
using test::kOperationsPerEvaluation;
using test::kTangentRelative;
using test::kUlp;
using test::kUnitLength;
using test::velocity_lipschitz;

namespace {

// Density on the GPU against cover_density on the CPU at the same warped point: normalize differs
// by about 4 x 2^-24 relative (inversesqrt's 2 ulp, the dot product's fused additions), which
// moves octave k's lattice point p f_k by 2.4e-7 f_k and F1 (1-Lipschitz) as much; with the
// density octaves of small() (frequency 3, 6 octaves, lacunarity 2, gain 0.5: a_k f_k = 3 each,
// sum a_k = 1.97) the weighted mean moves by 18 x 2.4e-7 / 1.97 = 2.2e-6, and each octave's F1
// differs by kF1 (1e-6, test_shader_probes.cpp): 3.2e-6; 1e-5 leaves a factor 3.
constexpr double kDensity = 1.0e-5;
static_assert(kDensity >= 18 * 4 * kUlp / 1.97 + 1.0e-6);
// cover_from_density at the same density on both sides: one subtraction and the division
// (GLSL: 2.5 ulp) of values in [0, 1], plus the span's subtraction: about 4 x 2^-24 = 2.4e-7;
// 1e-6 leaves a factor 4.
constexpr double kCoverRemap = 1.0e-6;

// The weather systems' own rounding on the two sides: atan, log and exp of the comma's frame
// (kTranscendental-like, 1e-6 relative) through a band edge's slope (1.5 / (0.4 x 0.12) = 31 per
// head radius at the narrowest): 3e-5; 1e-4 leaves a factor 3.
constexpr double kSystems = 1.0e-4;
static_assert(kCoverRemap >= 4 * kUlp);
// The achieved cloudy fraction is within one texel's share of the target (the calibration
// walks texel by texel); the slack on top of that is 1e-9, far looser than the double sums'
// rounding kFractionSum (1e-12) that it needs to absorb (kept as set).
constexpr double kFractionSlack = 1.0e-9;
static_assert(kFractionSlack >= kFractionSum);
// Seams: the mean |difference| of texels one texel apart across face edges against that inside
// faces; both are means over different sets of the same kind of neighbours, so they differ by
// sampling alone; 1.5 is empirical (a ratio, not a rounding bound; a real seam adds a jump of
// the order of the cover's range, far more).
constexpr double kSeamMeanRatio = 1.5;

cover::CoverParameters small(int size, int iterations = 50) {
  cover::CoverParameters p = test::steady_cover();
  p.size = size;
  p.iterations = iterations;
  // sfsim's scheme, which these passes are checked against (integrate_warp, warp_step).
  p.integrator = cover::Integrator::euler;
  p.curl_mode = cover::CurlMode::sampled;
  p.step = 0.006f;
  p.profile = cover::flat_profile();  // one threshold for the sphere (test_latitude_profile.cpp: the bands)
  p.density = {3.0f, 6, 2.0f, 0.5f};  // the octaves kDensity is derived for (the default before climate.md)
  return p;
}

}  // namespace

TEST_CASE("identity pass writes the unit direction of every texel centre", "[pass]") {
  test::test_context();
  cover::GlobalCover cover(small(16));
  cover.run_identity();
  const auto identity = as_vec4(cover.identity_field().read());
  for (int face = 0; face < 6; ++face)
    for (int j = 0; j < 16; ++j)
      for (int i = 0; i < 16; ++i) {
        const vec3 w = vec3(identity[index(16, face, i, j)]);
        REQUIRE(length(w - texel_direction(face, i, j, 16)) < kDirection);
        REQUIRE(std::abs(length(w) - 1.0f) < kUnitLength);
      }
}

TEST_CASE("curl pass agrees with the CPU twin and its vectors are tangent", "[pass]") {
  test::test_context();
  const auto p = small(16);
  cover::GlobalCover cover(p);
  cover.run_identity();
  cover.run_curl();
  const auto identity = as_vec4(cover.identity_field().read());
  const auto curl = as_vec4(cover.curl_field().read());
  const CurlParams c = cover::curl_params(p);
  for (size_t k = 0; k < curl.size(); ++k) {
    const vec3 n = vec3(identity[k]);
    const vec3 cpu = curl_velocity(n, c);
    const vec3 gpu = vec3(curl[k]);
    REQUIRE(length(gpu - cpu) < test::curl_rounding_bound(n, c));
    REQUIRE(std::abs(dot(gpu, n)) < kTangentRelative * (1.0f + length(gpu)));
    // The cyclonic depth: fBm values (below 1) mixed by weights below 1; its rounding is that
    // of the fBm values, kFbmValueRounding, plus m's (portable_asin, kPortableAsin x a = 3).
    REQUIRE(std::abs(curl[k].w - curl_flow_shifted(n, c, vec3(0.0f)).w) <
            test::kFbmValueRounding + 3 * test::kPortableAsin);
  }
}

TEST_CASE("warp pass agrees with the CPU twin within the growth of rounding errors", "[pass]") {
  test::test_context();
  for (int iterations : {1, 10, 50}) {
    const auto p = small(16, iterations);
    cover::GlobalCover cover(p);
    cover.run_identity();
    cover.run_curl();
    cover.run_warp();
    const auto identity = as_vec4(cover.identity_field().read());
    const auto curl = as_vec4(cover.curl_field().read());
    const auto warp = as_vec4(cover.warp_field().read());
    const CubeSource source{p.size, curl.data()};
    // Each step adds a few ulp (eps ~ 2.4e-7 per operation, a handful of operations); an
    // earlier error grows at most by (1 + h L) per step, L the sampled field's Lipschitz bound
    // (bilinear within a texel: rate of change between texel centres, doubled for the seams).
    const double L = 2.0 * velocity_lipschitz(curl, p.size);
    const double tolerance =
        kOperationsPerEvaluation * kOperationRounding * iterations * std::pow(1 + p.step * L, iterations);
    INFO("K = " << iterations << ", L = " << L << ", tolerance " << tolerance);
    double worst = 0;
    for (size_t k = 0; k < warp.size(); ++k) {
      const vec3 cpu = integrate_warp(vec3(identity[k]), p.iterations, p.step, source);
      const vec3 gpu = vec3(warp[k]);
      worst = std::max(worst, static_cast<double>(length(gpu - cpu)));
      REQUIRE(std::abs(length(gpu) - 1.0f) < kUnitLength);  // warped points stay on the unit sphere
    }
    INFO("largest difference " << worst);
    CHECK(worst <= tolerance);
  }
}

TEST_CASE("density and coverage passes agree with the CPU twin", "[pass]") {
  test::test_context();
  const auto p = small(16);
  cover::GlobalCover cover(p);
  cover.run();
  const auto identity = as_vec4(cover.identity_field().read());
  const auto warp = as_vec4(cover.warp_field().read());
  const auto curl = as_vec4(cover.curl_field().read());
  const auto density = cover.density_field().read();
  const auto covered = cover.cover_field().read();
  const auto contrast = cover.cover_contrast_field().read();
  const FbmParams params = cover::density_params(p);
  const WeatherSystems systems = cover::weather_systems(p, cover::hours_since_epoch(p.time));
  const auto& c = cover.calibration();
  int open_texels = 0;
  for (size_t k = 0; k < density.size(); ++k) {
    // The cyclonic factor 1 + k c (c from the GPU's curl field on both sides) scales the
    // density's error and adds two roundings of the product.
    const float factor = 1.0f + p.cyclone_cloudiness * curl[k].w;
    const float noise = cover_density(vec3(warp[k]), params);
    // The cyclones and the belts at the air's origin (cover_density.comp; the steady flow).
    const vec3 origin = normalize(vec3(warp[k]));
    const float latitude = portable_asin(clamp(origin.z, -1.0f, 1.0f));
    const float cyclones = cyclone_systems(origin, systems, cyclones_near(origin, systems), system_edge(noise));
    const vec4 regimes = belt_regimes(origin, latitude, systems, systems.seed);
    const float band = itcz_band(vec3(identity[k]), systems, system_edge(noise));
    // The density pass's texels, 2 / size radians across at a face's centre.
    const vec4 belts =
        belt_fields(origin, band, latitude, systems, systems.seed, system_edge(noise), regimes, 2.0f / float(p.size));
    const float systems_value = std::max(cyclones, belt_cloud(belts));
    const float shaped = shaped_density(noise, curl[k].w, p.cyclone_cloudiness, 0.0f, 0.0f);
    // The convective cells (none resolved by 16 texels a face: the modulation is 0 here).
    const float deck = frayed_deck(deck_strength(origin, latitude, systems.seed, 0.0f, 0.0f), system_edge(noise));
    // The cold air: the cyclones' cold sectors and the storm tracks' at the texel's own direction,
    // with the GPU's wind and cyclonic depth (no land/ocean mask here: all sea).
    const vec3 direction = vec3(identity[k]);
    const float storm_track =
        storm_track_cold_air(direction, portable_asin(clamp(direction.z, -1.0f, 1.0f)), vec3(curl[k]), curl[k].w, 1.0f);
    const vec2 weights = cell_weights(deck, std::max(cold_sectors(origin, systems), storm_track));
    const float cells = systems.cells * cell_modulation(origin, weights, systems.seed, 2.0f / float(p.size));
    REQUIRE(cells == 0.0f);
    // The open cells' weight dims their cloud at any size (no pockets without the open pattern).
    const float open = systems.cells * weights.y;
    open_texels += open > 0.0f ? 1 : 0;
    // The trades' shallow regime at the texel's own latitude, and the organised patterns' moats.
    const CloudTypes types = cloud_types(cyclones, belts);
    const float here = portable_asin(clamp(direction.z, -1.0f, 1.0f));
    const float shallow = shallow_trades_weight(types, here, deck_organisation(deck), systems.shallow_trades);
    const float organised = organised_trades(regimes, latitude, systems.trade_cumulus);
    const float expected =
        with_moats(with_cells(with_systems(shaped, systems_value), cells * (1.0f - cells_hidden(types))),
                   trade_moat(shallow, organised, types.cumulus));
    // The systems' field in [0, 1] takes the noise's error through system_edge (1 / 0.148) and a
    // band's edge (offset 0.6 half widths per unit of edge, smoothstep slope 1.5 / 0.4 half widths)
    // at most 15 kDensity, taken as 20, plus its transcendental functions' rounding (atan, log, exp: kSystems); the
    // factor 1 + 0.5 w scales the shaped density's error.
    const double systems_error = 20 * kDensity + kSystems;
    // The trades' shallow regime's weight takes the systems' error (the comma's and the clusters';
    // the cumulus's divided by its weight 0.6 and through its organisation's square, slope 2 at
    // most), the deck's organisation (its Perlin noise's rounding, about 1e-6, through the
    // smoothstep's slope 1.5 / DECK_ORGANISED: within kSystems; and the fray's, a strength below 1
    // times DECK_FRAY times the edge's error kDensity / 0.148, through the same slope) and the
    // latitude's (kPortableAsin through the belt's slope 1.5 / 0.13). The moat's weight takes it and
    // the cumulus's error through a smoothstep of slope 1.5 / 0.15 = 10, and the organised
    // patterns' share (two Perlin values through smoothsteps: kSystems); the factor 1 - 0.12 m
    // scales it by 0.12 of the density (at most 1.5 shaped).
    const double cumulus_error = systems_error / 0.6;
    const double fray_error = 1.5 / DECK_ORGANISED * DECK_FRAY * kDensity / 0.148;
    const double shallow_error = systems_error + 2 * cumulus_error + fray_error + kSystems + 12 * test::kPortableAsin;
    const double moat_error = shallow_error + 10 * cumulus_error + kSystems;
    REQUIRE(density[k] == Approx(expected).epsilon(0).margin((kDensity * factor + 4 * kUlp * shaped) * 1.5 +
                                                             0.5 * shaped * systems_error +
                                                             MOAT_CLEARING * 1.5 * shaped * moat_error));
    // The cover contrast of the trades' shallow cumulus at the texel's own latitude: 0.86 of the
    // shallow weight's error at most, and the organised patterns' share's (kSystems) times 0.14 x 0.7;
    // times the open cells' factor, whose weight takes the deck's error (its fray's, DECK_FRAY times the
    // edge's kDensity / 0.148, through the presence's and the closed weight's smoothsteps, slopes 1.5 /
    // 0.2 and 1.5 / 0.4), the cold sectors' and the storm tracks' (kSystems) and the hidden share's (the
    // systems' error), each times 0.75.
    const float expected_contrast = cover_contrast(shallow, organised, open * (1.0f - cells_hidden(types)));
    const double deck_error = DECK_FRAY * kDensity / 0.148;
    const double open_error = 0.75 * ((7.5 + 3.75) * deck_error + kSystems + systems_error);
    REQUIRE(contrast[k] == Approx(expected_contrast).epsilon(0).margin(shallow_error + kSystems + open_error));
    // The remap's exp: its argument's error over the softness (kCoverRemap of the subtraction and
    // the contrast's product, divided by s) and the exp's own rounding, at the GPU's contrast.
    REQUIRE(covered[k] ==
            Approx(contrasted_cover(density[k], c.threshold, c.density_max, p.cover_softness, contrast[k]))
                .epsilon(0)
                .margin(2 * kCoverRemap / p.cover_softness + 4 * kUlp));
  }
  // The cover has open cells' cloud (the cyclones' cold sectors, the storm tracks' cold air), so the
  // twin checks its dimming.
  INFO("texels with open cells " << open_texels);
  CHECK(open_texels > 0);
}

TEST_CASE("cover lies between 0 and 1 with the calibrated cloudy fraction", "[pass]") {
  test::test_context();
  for (float coverage : {0.0f, 0.3f, 0.67f, 1.0f}) {
    auto p = small(32);
    p.coverage = coverage;
    cover::GlobalCover cover(p);
    cover.run();
    const auto covered = cover.cover_field().read();
    for (float v : covered) {
      REQUIRE(v >= 0.0f);
      REQUIRE(v <= 1.0f);
    }
    const double fraction = cover::cloudy_fraction(covered, p.size);
    INFO("coverage " << coverage << " achieved " << fraction);
    CHECK(std::abs(fraction - coverage) <= cover.calibration().max_texel_fraction + kFractionSlack);
    // The GPU sums fixed-point solid angles: half a unit of error per texel, plus the CPU sum's
    // own rounding (kFractionSum).
    CHECK(std::abs(fraction - cover.calibration().achieved_fraction) <=
          cover::texel_weight_units(p.size).sum_error_bound() + kFractionSum);
  }
}

TEST_CASE("the cover has no seams: differences across face edges are like those inside faces", "[pass]") {
  test::test_context();
  const int n = 64;
  cover::GlobalCover cover(small(n));
  cover.run();
  const auto covered = cover.cover_field().read();
  double interior_sum = 0, seam_sum = 0, interior_max = 0, seam_max = 0;
  long interior_count = 0, seam_count = 0;
  for (int face = 0; face < 6; ++face)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i + 1 < n; ++i) {
        const double d = std::abs(covered[index(n, face, i, j)] - covered[index(n, face, i + 1, j)]);
        interior_sum += d;
        interior_max = std::max(interior_max, d);
        ++interior_count;
      }
  // Across the edge: the texel one texel-width beyond the edge, found geometrically.
  for (int face = 0; face < 6; ++face)
    for (int j = 0; j < n; ++j)
      for (int side : {0, 1}) {
        const int i = side ? n - 1 : 0;
        const float sc = side ? 1.0f + 1.0f / n : -1.0f - 1.0f / n;
        const float tc = 2.0f * (j + 0.5f) / n - 1.0f;
        const vec3 r = cube_face_point(face, sc, tc);
        const int other = cube_face_of(r);
        const vec2 st = 0.5f * cube_face_coords(other, r) + 0.5f;
        const int oi = std::clamp(int(st.x * n), 0, n - 1), oj = std::clamp(int(st.y * n), 0, n - 1);
        const double d = std::abs(covered[index(n, face, i, j)] - covered[index(n, other, oi, oj)]);
        seam_sum += d;
        seam_max = std::max(seam_max, d);
        ++seam_count;
      }
  const double interior_mean = interior_sum / interior_count, seam_mean = seam_sum / seam_count;
  INFO("mean difference inside " << interior_mean << ", across edges " << seam_mean);
  // Both are means of |difference| of texels one texel apart; a seam would add a jump.
  CHECK(seam_mean <= kSeamMeanRatio * interior_mean);
  CHECK(seam_max <= interior_max);
}

TEST_CASE("the same seed gives identical output and another seed a different one", "[pass]") {
  test::test_context();
  auto p = small(16);
  cover::GlobalCover first(p), second(p);
  first.run();
  second.run();
  const auto a = first.cover_field().read(), b = second.cover_field().read();
  CHECK(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0);
  p.seed = 2;
  cover::GlobalCover other(p);
  other.run();
  const auto c = other.cover_field().read();
  size_t differing = 0;
  for (size_t k = 0; k < a.size(); ++k) differing += a[k] != c[k];
  CHECK(differing > a.size() / 2);
}

TEST_CASE("tiny cube maps of sizes 1 to 3 run and stay finite", "[pass][extreme]") {
  test::test_context();
  for (int size : {1, 2, 3}) {
    cover::GlobalCover cover(small(size));
    cover.run();
    for (float v : cover.cover_field().read()) {
      REQUIRE(std::isfinite(v));
      REQUIRE(v >= 0.0f);
      REQUIRE(v <= 1.0f);
    }
    for (float v : cover.warp_field().read()) REQUIRE(std::isfinite(v));
  }
}

TEST_CASE("the trades' unorganised cloud keeps its place and turns dim and the mid-latitudes' stays as it was",
          "[pass][systems]") {
  test::test_context();
  // No systems at all: within 6 degrees of the equator every texel has the regime's full weight,
  // its contrast SHALLOW_CONTRAST, but for those whose air comes from a deck's reach (the decks'
  // belt, about 22 degrees, fades out towards 4; a deck's fringe reaches as far as the noise
  // frays it: frayed_deck at the largest edge). The regime leaves the
  // densities, and so the calibration and which texels are cloudy, as they are, and scales each
  // cloudy texel's excess over the threshold by the contrast: with the remap's cover
  // c = 1 - (1 - e) exp(-x / s), the excess x = -s ln((1 - c) / (1 - e)) shrinks by that factor
  // (and the edge e, COVER_EDGE, with it: contrasted_cover).
  // Beyond 33.2 degrees the weight is 0: the same covers, to the bit. (Without the trade cumulus
  // nothing organises the shallow cloud into clumps and moats: trade_moat and the moats' dimming
  // are 0.)
  auto run = [](float shallow) {
    cover::CoverParameters p = test::steady_cover();
    p.size = 64;
    p.curl_size = 64;
    p.cyclones = 0;
    p.itcz = p.trade_cumulus = p.cirrus = 0.0f;
    p.shallow_trades = shallow;
    cover::GlobalCover cover(p);
    cover.run();
    return std::tuple{as_vec4(cover.identity_field().read()), as_vec4(cover.warp_field().read()),
                      cover.cover_field().read(), cover::weather_systems(p, cover::hours_since_epoch(p.time)).seed};
  };
  const auto [identity, warp, without, seed] = run(0.0f);
  const auto with = std::get<2>(run(1.0f));
  const float softness = cover::CoverParameters{}.cover_softness;
  const auto excess = [&](float c, float edge) { return -softness * std::log((1.0f - c) / (1.0f - edge)); };
  int equatorial = 0, far = 0, near_deck = 0;
  double worst = 0, grey = 0, bright = 0;
  for (size_t k = 0; k < with.size(); ++k) {
    const double latitude = std::asin(identity[k].z) * 180 / M_PI;
    REQUIRE((with[k] > 0) == (without[k] > 0));
    if (std::abs(latitude) > 33.5) {
      ++far;
      REQUIRE(with[k] == without[k]);
    }
    if (std::abs(latitude) >= 6 || with[k] == 0) continue;
    const vec3 origin = normalize(vec3(warp[k]));
    const float reach = frayed_deck(deck_strength(origin, std::asin(origin.z), seed, 0.0f, 0.0f), 1.0f);
    if (deck_organisation(reach) > 0.0f) {
      ++near_deck;
      continue;
    }
    ++equatorial;
    // The excesses recovered from the covers: each cover is the exp's to a few ulp (4 kUlp, taken
    // as 8), which the log turns into s 8 kUlp / (1 - c) of excess; the contrast scales the one
    // without; and the contrasted density rounds once (an ulp of the threshold, below 1, over s).
    const double tolerance =
        softness * 8 * kUlp * (SHALLOW_CONTRAST / (1.0 - without[k]) + 1.0 / (1.0 - with[k])) + 2 * kUlp;
    worst = std::max(worst, std::abs(excess(with[k], SHALLOW_CONTRAST * COVER_EDGE) -
                                     SHALLOW_CONTRAST * excess(without[k], COVER_EDGE)) /
                                tolerance);
    grey += with[k], bright += without[k];
  }
  INFO(equatorial << " cloudy equatorial texels (" << near_deck << " more whose air comes from a deck's reach); worst "
                  << "excess mismatch " << worst << " tolerances; mean cover " << bright / equatorial << " -> "
                  << grey / equatorial);
  REQUIRE(far > 0);
  REQUIRE(equatorial > 2 * near_deck);  // most of them
  CHECK(worst <= 1.0);
  // Dim: without the regime the noise's cloud a spread above the threshold has cover 0.7, with it
  // 0.2; the means fall in proportion.
  CHECK(grey < 0.4 * bright);
}
