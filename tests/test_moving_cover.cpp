// The moving cover (--flow moving) on the GPU: frames that depend on their time alone, that move
// a little from hour to hour and renew within a day, and the spline grids of the flow at time
// nodes against the flow itself.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <tuple>
#include <vector>

#include "core/time.hpp"
#include "cover/global_cover.hpp"
#include "cover/moving_flow.hpp"
#include "cover/weather_systems.hpp"
#include "gl_support.hpp"
#include "shader_math/shader_math.hpp"

using namespace nephele;

namespace {

cover::CoverParameters moving(int size, const std::string& time) {
  cover::CoverParameters p;
  p.size = size;
  p.flow = cover::Flow::moving;
  p.time = time;
  p.curl_size = 32;  // the flow's grids: coarse, as the cover
  return p;
}

std::vector<float> cover_at(const cover::CoverParameters& p) {
  test::test_context();
  cover::GlobalCover cover(p);
  cover.run();
  return cover.cover_field().read();
}

double rms_difference(const std::vector<float>& a, const std::vector<float>& b) {
  double sum = 0;
  for (size_t i = 0; i < a.size(); ++i) sum += (double(a[i]) - b[i]) * (double(a[i]) - b[i]);
  return std::sqrt(sum / double(a.size()));
}

// The largest angle between the points of two warp fields (radians).
double largest_angle(const std::vector<float>& a, const std::vector<float>& b) {
  double worst = 0;
  for (size_t i = 0; i + 3 < a.size(); i += 4) {
    const glm::dvec3 p(a[i], a[i + 1], a[i + 2]), q(b[i], b[i + 1], b[i + 2]);
    worst = std::max(worst, std::atan2(glm::length(glm::cross(p, q)), glm::dot(p, q)));
  }
  return worst;
}

// The root mean square angle between the points of two warp fields (radians).
double rms_angle(const std::vector<float>& a, const std::vector<float>& b) {
  double sum = 0;
  size_t count = 0;
  for (size_t i = 0; i + 3 < a.size(); i += 4, ++count) {
    const glm::dvec3 p(a[i], a[i + 1], a[i + 2]), q(b[i], b[i + 1], b[i + 2]);
    const double angle = std::atan2(glm::length(glm::cross(p, q)), glm::dot(p, q));
    sum += angle * angle;
  }
  return std::sqrt(sum / double(count));
}

}  // namespace

TEST_CASE("a frame of the moving cover depends on its time alone, not on the frames made before it", "[moving]") {
  // A sequence reuses the flow's grids of time nodes that consecutive frames share; a frame made
  // alone makes them all. Both must give the same bits.
  test::test_context();
  cover::GlobalCover sequence(moving(32, "2026-06-21T00:00Z"));
  sequence.run();
  sequence.set_time("2026-06-21T09:00Z");
  sequence.run();
  const std::vector<float> alone = cover_at(moving(32, "2026-06-21T09:00Z"));
  const std::vector<float> in_sequence = sequence.cover_field().read();
  REQUIRE(alone.size() == in_sequence.size());
  CHECK(alone == in_sequence);
}

TEST_CASE("the moving cover changes little from hour to hour and renews itself within a day", "[moving]") {
  // Two covers of different seeds differ by D (RMS), their pattern independent. An hour apart,
  // the cloud layers' shares move by at most (pi/2) (1 h / 13.3 h) = 0.12 and the air by
  // |v| 1 h, under a texel here: the difference must stay far below D (a frame that popped to
  // a new pattern would reach D at once); a third of D leaves room for the advection of edges.
  // A day apart, the older layer of the first frame (age T to 3T/2, T = 26.5 h) has faded out
  // and the younger has aged past its peak: more than half of D.
  const std::string start = "2026-06-21T00:00Z";
  const std::vector<float> first = cover_at(moving(48, start));
  const std::vector<float> hour = cover_at(moving(48, "2026-06-21T01:00Z"));
  const std::vector<float> day = cover_at(moving(48, "2026-06-22T00:00Z"));
  cover::CoverParameters other = moving(48, start);
  other.seed = 2;
  const double independent = rms_difference(first, cover_at(other));
  INFO("RMS differences: an hour " << rms_difference(first, hour) << ", a day " << rms_difference(first, day)
                                   << ", another seed " << independent);
  CHECK(rms_difference(first, hour) < independent / 3);
  CHECK(rms_difference(first, day) > independent / 2);
}

TEST_CASE("the moving warp of the flow's splines follows the procedural flow within a tenth of a texel", "[moving]") {
  // The splines of the flow at time nodes (curl mode spline) against the flow evaluated at every
  // stage (procedural): the spline's own error (O(h^4): a few 1e-5 rad at 256 nodes per face,
  // 16 times that at the 128 here, docs/numerics.md) plus linear interpolation in time between
  // nodes h/2 apart, (h/2)^2 / 8 |v_tt| (|v_tt| below 1 for the drift's omega^2 |v| and the
  // shares' (pi/L)^2 |v|): 3e-4 |v| per unit time. Over a trajectory of 3T/2 = 0.45 both stay
  // below a tenth of a texel of a cover of 64 per face (pi/2 / 64 / 10 = 2.5e-3 rad; this one has
  // 32). A node taken one off would move the points by the flow over h/2, |v| 0.075 ~ 0.02 rad.
  // (Measured: 8.0e-5 rad for the older layer, 7.1e-5 for the younger, about the same at 256
  // nodes: the time interpolation dominates.)
  cover::CoverParameters spline = moving(32, "2026-06-21T05:00Z");
  spline.curl_size = 128;
  spline.curl_mode = cover::CurlMode::spline;  // auto would take procedural for this small cover
  REQUIRE(cover::resolved_curl_mode(spline) == cover::CurlMode::spline);
  cover::CoverParameters procedural = spline;
  procedural.curl_mode = cover::CurlMode::procedural;
  test::test_context();
  cover::GlobalCover a(spline), b(procedural);
  a.run();
  b.run();
  const double old_layer = largest_angle(a.warp_field().read(), b.warp_field().read());
  const double young_layer = largest_angle(a.young_warp_field().read(), b.young_warp_field().read());
  INFO("largest angle between the warps: older layer " << old_layer << " rad, younger " << young_layer << " rad");
  CHECK(old_layer < 2.5e-3);
  CHECK(young_layer < 2.5e-3);
}

TEST_CASE("the warp grid's spline approaches the trajectories from every texel at third to fourth order in its spacing",
          "[moving]") {
  // The grid's spline is the curl spline's quasi-interpolant, which reproduces cubics: its error
  // falls as h^4 where the trajectories' ends are smooth on the grid's scale, and no faster. The
  // ends are at least C2 (the flow's spline is C2, its third derivatives jump at its nodes), which
  // keeps at least h^3. Halving the spacing divides the error by 8 to 16; up to 32 allows for
  // the rms's sampling. (Measured: 11.3 for the older layer, 13.0 for the younger.)
  test::test_context();
  auto layers = [](int grid) {
    cover::CoverParameters p = moving(512, "2026-06-21T05:00Z");
    p.curl_size = 128;  // the default flow's grid at this size
    p.warp_grid = grid;
    cover::GlobalCover cover(p);
    cover.run_identity();
    cover.run_moving_warp();
    return std::make_pair(cover.warp_field().read(), cover.young_warp_field().read());
  };
  const auto exact = layers(0), coarse = layers(128), fine = layers(256);
  const double coarse_error = rms_angle(coarse.first, exact.first), fine_error = rms_angle(fine.first, exact.first);
  const double coarse_young = rms_angle(coarse.second, exact.second), fine_young = rms_angle(fine.second, exact.second);
  INFO("older layer rms " << coarse_error << " rad (128 nodes), " << fine_error << " (256); younger " << coarse_young
                          << ", " << fine_young);
  CHECK(fine_error > 0);
  CHECK(coarse_error / fine_error > 8);
  CHECK(coarse_error / fine_error < 32);
  CHECK(coarse_young / fine_young > 8);
  CHECK(coarse_young / fine_young < 32);
  // Every end stays on the sphere (the spline's value is renormalised).
  double off_sphere = 0;
  for (size_t i = 0; i + 3 < fine.first.size(); i += 4)
    off_sphere = std::max(off_sphere, std::abs(std::hypot(fine.first[i], fine.first[i + 1], fine.first[i + 2]) - 1.0));
  CHECK(off_sphere < 1e-6);
  // The grid is used only where it is coarser than the cover, and only by the moving flow.
  cover::CoverParameters p = moving(128, "2026-06-21T05:00Z");
  p.warp_grid = 128;
  CHECK(cover::warp_grid_cells(p) == 0);
  p.warp_grid = 64;
  CHECK(cover::warp_grid_cells(p) == 64);
  p.flow = cover::Flow::steady;
  CHECK(cover::warp_grid_cells(p) == 0);
}

TEST_CASE("the noise grid's density approaches every octave at every texel as its node spacing to the power 1.5",
          "[moving]") {
  // 1 - F1 is Lipschitz with creases on the Worley cells' faces: the spline's quasi-interpolant
  // errs by O(h) in a band of width O(h) along them and by O(h^4) elsewhere, so the rms error over
  // the texels falls as h^1.5. Halving the spacing divides it by 2.8: at least 2, at most the 16
  // of a smooth field. The density without weather systems is the noise times smooth factors.
  // (Measured: 3.1.)
  test::test_context();
  auto density = [](int grid, float nodes) {
    cover::CoverParameters p = moving(128, "2026-06-21T05:00Z");
    p.density.octaves = 2;
    p.cyclones = 0;
    p.itcz = p.trade_cumulus = p.cirrus = p.stratocumulus_cells = p.cloud_streets = 0.0f;
    p.warp_grid = grid;
    p.noise_grid_nodes = nodes;
    REQUIRE(cover::noise_grid_octaves(p) == (nodes > 0 ? 2 : 0));
    cover::GlobalCover cover(p);
    cover.run();
    return cover.density_field().read();
  };
  auto rms = [](const std::vector<float>& a, const std::vector<float>& b) {
    double sum = 0;
    for (size_t k = 0; k < a.size(); ++k) sum += (double(a[k]) - b[k]) * (double(a[k]) - b[k]);
    return std::sqrt(sum / double(a.size()));
  };
  // 0.25 nodes per cell: both octaves on both grids (32 nodes: 5.3 and 2.7 nodes per cell).
  const double coarse = rms(density(32, 0.25f), density(32, 0.0f)), fine = rms(density(64, 0.25f), density(64, 0.0f));
  INFO("density rms against every texel: " << coarse << " (32 nodes), " << fine << " (64)");
  CHECK(fine > 0);
  CHECK(coarse / fine > 2);
  CHECK(coarse / fine < 16);
  // The octaves a threshold selects: cells of 1 / (3 x 2^k) radians against the grid's 2 / 64.
  cover::CoverParameters p = moving(128, "2026-06-21T05:00Z");
  p.warp_grid = 64;
  p.noise_grid_nodes = 5.0f;  // 10.7 and 5.3 nodes per cell, then 2.7
  CHECK(cover::noise_grid_octaves(p) == 2);
  p.noise_grid_nodes = 0.0f;
  CHECK(cover::noise_grid_octaves(p) == 0);
  p.noise_grid_nodes = 5.0f;
  p.warp_grid = 0;  // no warp grid: nothing to carry the octaves
  CHECK(cover::noise_grid_octaves(p) == 0);
}

TEST_CASE("curl mode auto takes spline for the steady flow and for the moving flow the way with fewer curl evaluations",
          "[fast][moving]") {
  cover::CoverParameters p;
  REQUIRE(p.curl_mode == cover::CurlMode::automatic);
  p.flow = cover::Flow::steady;
  for (int size : {8, 128, 4096}) {
    p.size = size;
    CHECK(cover::resolved_curl_mode(p) == cover::CurlMode::spline);
  }
  // Moving, defaults (T = 0.3, h = 0.15, nodes h/2 apart over 3T/2: 7 grids of g^2 per face,
  // g = min(256, 128, max(64, size / 2)); trajectories of 2 + 1 steps of 4 stages: 12 size^2):
  // procedural while 12 size^2 < 7 x 64^2, up to 48; a spline above, on a grid of size / 2 up
  // to 128, the finest whose error is not dominated by the grids' spacing in time at h = 0.15.
  p.flow = cover::Flow::moving;
  const std::tuple<int, cover::CurlMode, int> expected[] = {
      {32, cover::CurlMode::procedural, 256}, {48, cover::CurlMode::procedural, 256},
      {49, cover::CurlMode::spline, 64},      {128, cover::CurlMode::spline, 64},
      {200, cover::CurlMode::spline, 100},    {300, cover::CurlMode::spline, 128},
      {1024, cover::CurlMode::spline, 128}};
  for (const auto& [size, mode, grid] : expected) {
    p.size = size;
    INFO("size " << size);
    const cover::CoverParameters resolved = cover::resolved_curl(p);
    CHECK(resolved.curl_mode == mode);
    CHECK(resolved.curl_size == grid);
  }
  // Steps below 0.03, whose grids in time err less than a 128-node spline in space, take up to
  // 256 nodes: 16 steps of 0.019 over the same window.
  p.iterations = 16;
  p.step = 0.019f;
  p.size = 1024;
  CHECK(cover::resolved_curl(p).curl_size == 256);
  p.size = 300;
  CHECK(cover::resolved_curl(p).curl_size == 150);
  p.iterations = 2;
  p.step = 0.15f;
  // A smaller --curl-size caps the grid; a mode given by name is kept with its grid.
  p.size = 1024;
  p.curl_size = 100;
  CHECK(cover::resolved_curl(p).curl_size == 100);
  p.curl_mode = cover::CurlMode::spline;
  p.size = 128;
  CHECK(cover::resolved_curl(p).curl_size == 100);
  p.curl_mode = cover::CurlMode::procedural;
  CHECK(cover::resolved_curl_mode(p) == cover::CurlMode::procedural);
}

TEST_CASE(
    "extreme: the moving cover stays finite, on the sphere and on target for strong, short-lived vortices, "
    "long windows, far dates and tiny cube maps",
    "[moving][extreme]") {
  struct Extreme {
    const char* what;
    cover::CoverParameters p;
  };
  std::vector<Extreme> cases;
  cover::CoverParameters strong = moving(16, "2026-06-21T00:00Z");
  strong.curl_strength = 2.0f;  // 20 times the default's vortices and winds
  strong.vortex_lifetime = 6.0f;
  cases.push_back({"strong vortices living 6 hours", strong});
  cover::CoverParameters long_window = moving(16, "2026-06-21T00:00Z");
  long_window.iterations = 20;  // T = 3: trajectories of 4.5 flow units (400 hours), 30 steps
  cases.push_back({"a window of 400 hours", long_window});
  cases.push_back({"the year 2999", moving(16, "2999-12-31T23:00Z")});
  cases.push_back({"the year 1900", moving(16, "1900-01-01T00:00Z")});
  for (int size = 1; size <= 3; size += 2) cases.push_back({"a tiny cube map", moving(size, "2026-06-21T00:00Z")});
  cover::CoverParameters procedural = strong;
  procedural.curl_mode = cover::CurlMode::procedural;
  cases.push_back({"strong vortices, procedural", procedural});
  test::test_context();
  for (Extreme& c : cases) c.p.profile = cover::flat_profile();
  for (const Extreme& c : cases) {
    INFO(c.what << ", size " << c.p.size);
    cover::GlobalCover cover(c.p);
    cover.run();
    for (const std::vector<float>& warp : {cover.warp_field().read(), cover.young_warp_field().read()})
      for (size_t i = 0; i + 3 < warp.size(); i += 4) {
        const double length = std::sqrt(double(warp[i]) * warp[i] + double(warp[i + 1]) * warp[i + 1] +
                                        double(warp[i + 2]) * warp[i + 2]);
        // Each RK4 step ends with a normalisation (a few ulps); NaN fails the comparison.
        REQUIRE(std::abs(length - 1.0) <= 1e-5);
      }
    for (float value : cover.cover_field().read()) REQUIRE((value >= 0.0f && value <= 1.0f));
    // One threshold (flat profile): the calibration reaches the target within the largest
    // texel's share, as for the steady cover (test_cover_passes.cpp).
    CHECK(std::abs(cover.calibration().achieved_fraction - c.p.coverage) <=
          cover.calibration().max_texel_fraction + 1e-9);
  }
}

TEST_CASE("a looped moving cover repeats after its loop, and differs within it", "[moving]") {
  // --loop 24: 2 generations of vortices (24 / 48 h rounded, at least 2), 2 cloud layers (24 h /
  // 13.3 h rounded) and time nodes of 24 h / 4 fit the day; the noise of generation and layer k
  // is that of k mod their count, so the flow and the clouds at t + 24 h are those at t. The
  // times of the flow count from the frame's own generation origin, a whole number of
  // generations further on, so the frames agree to the rounding of those times. That rounding
  // moves a density now and then across an edge of the calibration's fine bins (range / 256^2,
  // about 1.5e-5 of density), which moves its band's threshold by up to a bin and the band's
  // covers by up to a bin over the softness (3e-4), most bands not at all: an RMS below 1e-4,
  // against more than 0.05 half a loop apart.
  cover::CoverParameters day = moving(32, "2026-06-21T05:00Z");
  day.loop_hours = 24;
  cover::CoverParameters next = day;
  next.time = "2026-06-22T05:00Z";
  cover::CoverParameters half = day;
  half.time = "2026-06-21T17:00Z";
  const std::vector<float> a = cover_at(day), b = cover_at(next), c = cover_at(half);
  INFO("RMS differences: a loop apart " << rms_difference(a, b) << ", half a loop apart " << rms_difference(a, c));
  CHECK(rms_difference(a, b) <= 1e-4);
  CHECK(rms_difference(a, c) > 0.05);
}

TEST_CASE("the ITCZ's cell tables of both cloud layers hold the cells the density would compute", "[moving]") {
  // The tables the density pass reads (itcz_cells.comp) against weather_systems.glsl's itcz_cell
  // in C++, for the older and the younger layer's seeds. The feature points are the same hashes
  // (exact). A radius depends on the presence at the point, whose GPU and CPU values differ by
  // the line's waves' rounding: their sums of 5 terms of size up to 1.5 after up to 10 complex
  // products of unit numbers err by about 20 x 3 x 2^-24 = 4e-6, which moves the line by the
  // meander's 0.026 and the monsoons' unit weight (5e-6 in sin(latitude)); the presence's
  // slope is at most 2 / 0.07 per unit of sin(latitude) (bump^2 over the line's width) and
  // the superclusters' 0.8 x 1.5 / 0.6 per unit of sum: 1.5e-4 in all, taken as kPresence. A
  // cell whose hash lies within kPresence of its presence may be present on one side only (not
  // checked); elsewhere the radius, the full one (at most 0.5 cells) times the excess over 0.25
  // (system_growth), differs by at most 0.5 x 4 kPresence.
  constexpr float kPresence = 2.0e-4f;
  test::test_context();
  cover::CoverParameters p = moving(16, "2000-03-01T06:00Z");
  cover::GlobalCover cover(p);
  cover.run();
  const std::vector<float> tables = cover.itcz_cells().read_floats();
  const double hours = cover::hours_since_epoch(p.time);
  const cover::FrameClock clock = cover::frame_clock(p, hours);
  const glsl::WeatherSystems systems = cover::weather_systems(p, hours);
  const std::uint32_t seeds[2] = {cover::layer_systems_seed(p, clock.young_layer - 1, clock.layers_in_loop),
                                  cover::layer_systems_seed(p, clock.young_layer, clock.layers_in_loop)};
  REQUIRE(seeds[0] != seeds[1]);
  REQUIRE(tables.size() == 2u * 4u * size_t(glsl::ITCZ_TABLE_CELLS));
  int present[2][2] = {{0, 0}, {0, 0}}, undecided = 0, candidates = 0;
  for (int layer = 0; layer < 2; ++layer)
    for (int index = 0; index < glsl::ITCZ_TABLE_CELLS; ++index) {
      const glsl::ivec4 cell = glsl::itcz_table_cell(index);
      const glm::vec4 expected =
          glsl::itcz_cell(cell.w, glsl::ivec3(cell), systems.itcz_latitude, systems.itcz_waves, seeds[layer]);
      const float* got = &tables[4 * (2 * size_t(index) + layer)];
      REQUIRE(got[0] == expected.x);
      REQUIRE(got[1] == expected.y);
      REQUIRE(got[2] == expected.z);
      // The cell's presence and hash, as itcz_cell finds them.
      const std::uint32_t layer_key = glsl::itcz_layer(cell.w) + 1u;
      const glm::vec3 h =
          glsl::hash_to_unit3(glsl::pcg3d(glsl::uvec3(glsl::ivec3(cell)) ^ glsl::noise_key(seeds[layer], layer_key)));
      const float here = glsl::waved_presence(glm::normalize(glm::vec3(glsl::ivec3(cell)) + glm::vec3(expected)),
                                              glsl::itcz_presence(cell.w, systems.itcz_latitude),
                                              glsl::itcz_table_waves(cell.w, systems.itcz_waves), h.y);
      candidates += here > 0.0f ? 1 : 0;
      if (std::abs(h.y - here) < kPresence && here > 0.0f) {
        ++undecided;
        continue;
      }
      REQUIRE(got[3] == Approx(expected.w).epsilon(0).margin(0.5 * 4 * kPresence));
      present[layer][cell.w == glsl::ITCZ_SYSTEMS_TABLE ? 0 : 1] += expected.w > 0.0f ? 1 : 0;
    }
  INFO("cells present: older " << present[0][0] << " and " << present[0][1] << ", younger " << present[1][0] << " and "
                               << present[1][1] << "; undecided " << undecided << " of " << candidates);
  // Both layers' tables hold systems of both lattices, different ones (their own seeds).
  for (int layer = 0; layer < 2; ++layer)
    for (int table = 0; table < 2; ++table) CHECK(present[layer][table] > 10);
  // The hashes are uniform: about 2 kPresence of the cells with a presence are undecided.
  CHECK(undecided <= 3 * 2 * kPresence * candidates + 5);
}
