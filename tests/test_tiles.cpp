// A cover computed in tiles (src/cover/tiled_cover.hpp): the same cover as the whole map to the
// bit, and the same calibration and diagnosis, for every way of cutting the faces.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <vector>

#include "cover/cover_limits.hpp"
#include "cover/cube_tiles.hpp"
#include "cover/global_cover.hpp"
#include "cover/equirect.hpp"
#include "cover/latitude_profile.hpp"
#include "cover/streamed_equirect.hpp"
#include "cover/surface_bias.hpp"
#include "cover/tiled_cover.hpp"
#include "cli_support.hpp"
#include "core/json.hpp"
#include "files/atomic_output.hpp"
#include "gl_support.hpp"
#include "steady_cover.hpp"

using namespace nephele;

namespace {

struct TiledResult {
  std::vector<float> cover;                         // faces in order, rows from 0, as GlobalCover::cover_field().read()
  std::vector<float> optical_thickness, cloud_top;  // the same way
  cover::CoverageCalibration calibration;
  std::optional<cover::BandCalibration> bands;
  cover::WarpDiagnostics diagnostics;
};

// Every tile run, calibrated and remapped in memory, the covers put back in their places.
TiledResult run_tiled(const cover::CoverParameters& p, int count) {
  const cover::CubeTiling tiling{p.size, count};
  cover::TileRunner runner(p, tiling);
  std::vector<cover::TileDensity> tiles;
  cover::DiagnosisSums sums;
  std::pair<float, float> range{INFINITY, -INFINITY};
  for (int t = 0; t < count; ++t) {
    tiles.push_back(runner.run(t));
    sums.add(tiles.back().diagnosis);
    range.first = std::min(range.first, tiles.back().density_min);
    range.second = std::max(range.second, tiles.back().density_max);
  }
  cover::TiledCoverage coverage(p, tiling);
  const auto load = [&](int index) { return tiles[static_cast<size_t>(index)].density; };
  coverage.calibrate(range, load);
  TiledResult result;
  result.cover.assign(6 * static_cast<size_t>(p.size) * p.size, -1.0f);
  const auto load_cloud_top = [&](int index) { return tiles[static_cast<size_t>(index)].cloud_top; };
  const auto load_contrast = [&](int index) { return tiles[static_cast<size_t>(index)].cover_contrast; };
  result.optical_thickness = result.cloud_top = result.cover;
  result.calibration =
      coverage.remap(load, load_cloud_top, load_contrast, [&](int index, const cover::CoverPlanes& planes) {
        const cover::CubeRegion region = cover::owned_region(tiling.tile(index));
        const size_t offset = (static_cast<size_t>(region.face) * p.size + region.first_row) * p.size;
        REQUIRE(planes.cover.size() == static_cast<size_t>(region.owned_texels()));
        std::copy(planes.cover.begin(), planes.cover.end(), result.cover.begin() + static_cast<std::ptrdiff_t>(offset));
        std::copy(planes.optical_thickness.begin(), planes.optical_thickness.end(),
                  result.optical_thickness.begin() + static_cast<std::ptrdiff_t>(offset));
        std::copy(planes.cloud_top.begin(), planes.cloud_top.end(),
                  result.cloud_top.begin() + static_cast<std::ptrdiff_t>(offset));
      });
  result.bands = coverage.bands();
  const cover::TexelWeightUnits units = cover::texel_weight_units(p.size);
  result.diagnostics =
      cover::diagnostics_from_sums(sums, units, runner.parameters().integrator, p.step, p.flow == cover::Flow::moving);
  return result;
}

bool same_bits(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

void check_tiles_match_whole(const cover::CoverParameters& p, std::initializer_list<int> counts) {
  test::test_context();
  cover::GlobalCover whole(p);
  whole.run();
  const cover::WarpDiagnostics& diagnosed = whole.diagnose();
  const std::vector<float> expected = whole.cover_field().read();
  for (int count : counts) {
    INFO(count << " tiles of a cover of " << p.size << " per face");
    const TiledResult tiled = run_tiled(p, count);
    CHECK(same_bits(tiled.cover, expected));
    // The remap's other fields too: the ranks' tails are sums of integer units (any cut into
    // tiles gives the same histograms) and the tops the density pass's, texel by texel.
    CHECK(same_bits(tiled.optical_thickness, whole.optical_thickness_field().read()));
    CHECK(same_bits(tiled.cloud_top, whole.cloud_top_field().read()));
    CHECK(tiled.calibration.density_min == whole.calibration().density_min);
    CHECK(tiled.calibration.density_max == whole.calibration().density_max);
    CHECK(tiled.calibration.threshold == whole.calibration().threshold);
    CHECK(tiled.calibration.achieved_fraction == whole.calibration().achieved_fraction);
    REQUIRE(tiled.bands.has_value() == whole.band_calibration().has_value());
    if (tiled.bands) CHECK(tiled.bands->thresholds == whole.band_calibration()->thresholds);
    // Integer sums and extremes are exact; the double sums of the area error differ in the order
    // of addition only: a few ulp of the sum relative.
    const cover::WarpDiagnostics& d = tiled.diagnostics;
    CHECK(d.folding.folded_fraction == diagnosed.folding.folded_fraction);
    CHECK(d.stiffness.beyond_fraction == diagnosed.stiffness.beyond_fraction);
    CHECK(d.stiffness.max_rate == diagnosed.stiffness.max_rate);
    CHECK(d.folding.jacobian_min == diagnosed.folding.jacobian_min);
    CHECK(d.folding.jacobian_max == diagnosed.folding.jacobian_max);
    CHECK(d.folding.area_error_rms == Approx(diagnosed.folding.area_error_rms).epsilon(1e-12));
    CHECK(d.substeps.mean_attempts == Approx(diagnosed.substeps.mean_attempts).epsilon(1e-12));
    CHECK(d.substeps.capped_texels == diagnosed.substeps.capped_texels);
    CHECK(d.warnings == diagnosed.warnings);
  }
}

}  // namespace

TEST_CASE("tiles of whole and uneven rows tile every face exactly once, halos only inside a face", "[fast][tiles]") {
  for (int size : {1, 7, 30, 64}) {
    for (int count : {6, 12, 24, 6 * size}) {
      if (!cover::tile_count_problem(size, count).empty()) continue;
      const cover::CubeTiling tiling{size, count};
      std::vector<int> owner(6 * static_cast<size_t>(size), -1);
      for (int t = 0; t < count; ++t) {
        const cover::CubeRegion r = tiling.tile(t);
        INFO("size " << size << ", " << count << " tiles, tile " << t);
        CHECK(r.layers == 1);
        CHECK(r.owned_rows() >= size / tiling.strips_per_face());
        CHECK(r.owned_rows() <= size / tiling.strips_per_face() + 1);
        // A halo row beyond each edge that is not the face's.
        const int owned_first = r.first_row + r.owned_begin, owned_last = r.first_row + r.owned_end;
        CHECK(r.owned_begin == (owned_first > 0 ? 1 : 0));
        CHECK(r.rows - r.owned_end == (owned_last < size ? 1 : 0));
        CHECK(r.first_row >= 0);
        CHECK(r.first_row + r.rows <= size);
        for (int row = r.owned_begin; row < r.owned_end; ++row) {
          int& o = owner[static_cast<size_t>(r.face) * size + r.first_row + row];
          CHECK(o == -1);
          o = t;
        }
      }
      CHECK(std::count(owner.begin(), owner.end(), -1) == 0);
    }
  }
  CHECK_FALSE(cover::tile_count_problem(64, 4).empty());
  CHECK_FALSE(cover::tile_count_problem(64, 0).empty());
  CHECK_FALSE(cover::tile_count_problem(2, 18).empty());
  CHECK(cover::tile_count_problem(2, 12).empty());
  CHECK_THROWS(cover::CubeTiling{8, 12}.tile(12));
}

TEST_CASE("a cover in tiles equals the whole map's to the bit: the moving flow with the latitude profile", "[tiles]") {
  cover::CoverParameters p;
  p.size = 30;
  p.curl_size = 32;
  check_tiles_match_whole(p, {6, 24, 180});
}

TEST_CASE("a cover in tiles equals the whole map's to the bit: the moving flow from a warp grid coarser than the cover",
          "[tiles]") {
  // Every tile reads the same whole-cube grid, traced once per frame (cover::warp_grid_cells).
  cover::CoverParameters p;
  p.size = 30;
  p.curl_size = 32;
  p.warp_grid = 12;
  REQUIRE(cover::warp_grid_cells(p) == 12);
  p.noise_grid_nodes = 1.0f;  // and the noise grid's two octaves (2 and 1 nodes per cell)
  REQUIRE(cover::noise_grid_octaves(p) == 2);
  check_tiles_match_whole(p, {6, 24});
}

TEST_CASE("a cover in tiles equals the whole map's to the bit: the steady spline warp, a flat profile, land bias",
          "[tiles]") {
  cover::CoverParameters p = test::steady_cover();
  p.size = 32;
  p.curl_size = 32;
  p.profile = cover::flat_profile();
  // Land west of longitude 0, for the density pass's texel directions (--surface).
  cover::SurfaceMask land{cover::surface_bias_columns, cover::surface_bias_rows, {}, "test"};
  land.land.resize(static_cast<size_t>(land.columns) * land.rows);
  for (int row = 0; row < land.rows; ++row)
    for (int column = 0; column < land.columns; ++column)
      land.land[static_cast<size_t>(row) * land.columns + column] = column < land.columns / 2 ? 1.0f : 0.0f;
  p.surface = std::make_shared<const cover::SurfaceMask>(land);
  check_tiles_match_whole(p, {12, 30});
}

TEST_CASE("a cover in tiles equals the whole map's to the bit: the adaptive and the long procedural warps", "[tiles]") {
  cover::CoverParameters p = test::steady_cover();
  p.size = 16;
  p.integrator = cover::Integrator::adaptive;
  p.curl_mode = cover::CurlMode::procedural;
  check_tiles_match_whole(p, {12});
  p.integrator = cover::Integrator::rk4;
  p.iterations = 200;  // several dispatches through the scratch map (steps_per_dispatch)
  check_tiles_match_whole(p, {12});
}

TEST_CASE("curl mode sampled is refused for a tile: it reads the curl map anywhere on the sphere", "[tiles]") {
  test::test_context();
  cover::CoverParameters p = test::steady_cover();
  p.size = 16;
  p.curl_mode = cover::CurlMode::sampled;
  CHECK_THROWS_WITH(cover::GlobalCover(p, cover::CubeTiling{16, 6}.tile(0)), Catch::Contains("sampled"));
}

TEST_CASE("generate tiles a cover whose cube maps the driver cannot allocate whatever the budget", "[tiles]") {
  test::test_context();
  const double unlimited = 0.0, ample = 1.0e15;
  // A small cover fits every driver and any ample budget: whole, unless the budget is too small.
  CHECK_FALSE(cover::cover_needs_tiles(64, cover::Flow::moving, unlimited));
  CHECK_FALSE(cover::cover_needs_tiles(64, cover::Flow::moving, ample));
  CHECK(cover::cover_needs_tiles(64, cover::Flow::moving, cover::whole_cover_bytes(64, cover::Flow::moving) / 2));
  // A size beyond the driver's cube maps (llvmpipe: 4096, over its 1 GiB a texture) is tiled with
  // any budget: its tiles' maps are strips of one face.
  for (int size : {4096, 16384}) {
    INFO(size);
    CHECK(cover::cover_needs_tiles(size, cover::Flow::moving, ample) == !cover::whole_cube_fits_driver(size));
  }
  CHECK(cover::whole_cube_fits_driver(64));
}

namespace {

std::string face_bytes(const std::filesystem::path& directory, const char* face) {
  return test::read_file(directory / (std::string("cover_") + face + ".exr"));
}

}  // namespace

TEST_CASE("tile parts made in two runs assemble to the files of one generate, byte for byte", "[tiles][cli]") {
  const test::TemporaryDirectory work(true);
  const std::string cover = "--size 24 --seed 5 --curl-size 32";
  const std::string parts = (work.path / "parts").string();
  const std::string exports = " --export ktx2,flightgear";
  REQUIRE(test::run("generate " + cover + " --files faces,equirect --quiet" + exports + " --out " +
                    (work.path / "whole").string())
              .exit_code == 0);
  REQUIRE(test::run("generate " + cover + " --tiles 12 --tile 0-4 --quiet --out " + parts).exit_code == 0);
  // Parts of one cover only: assemble names the tiles that are missing.
  const test::Run early = test::run("assemble " + parts + " --out " + (work.path / "early").string());
  CHECK(early.exit_code == 2);
  CHECK_THAT(early.output, Catch::Contains("lacks tiles 5, 6, 7, 8, 9, 10, 11"));
  // The second task's range overlaps the first's: complete parts are kept, not made again.
  const test::Run second = test::run("generate " + cover + " --tiles 12 --tile 3-11 --out " + parts);
  REQUIRE(second.exit_code == 0);
  CHECK_THAT(second.output, Catch::Contains("2 already complete, kept"));
  const std::filesystem::path assembled = work.path / "assembled";
  const test::Run assemble =
      test::run("assemble " + parts + " --files faces,equirect --quiet" + exports + " --out " + assembled.string());
  REQUIRE(assemble.exit_code == 0);
  for (const char* face : {"px", "nx", "py", "ny", "pz", "nz", "equirect"}) {
    INFO(face);
    CHECK(face_bytes(assembled, face) == face_bytes(work.path / "whole", face));
  }
  // The presets run on the assembled faces write what they write on the whole map's floats,
  // after assemble and after generate in tiles alike.
  const std::filesystem::path tiled = work.path / "tiled";
  REQUIRE(test::run("generate " + cover + " --tiles 12 --files faces --quiet" + exports + " --out " + tiled.string())
              .exit_code == 0);
  for (const char* file : {"export/ktx2/cover_cube.ktx2", "export/flightgear/clouds_N3.png"}) {
    INFO(file);
    CHECK(test::read_file(assembled / file) == test::read_file(work.path / "whole" / file));
    CHECK(test::read_file(tiled / file) == test::read_file(work.path / "whole" / file));
  }
  const json::Value sidecar = json::parse(test::read_file(assembled / "cover.json"));
  CHECK(sidecar.at("files").at("computed_in_tiles").as_number() == 12);
  // The parts directory holds the parts and nothing else (no temporary file was left).
  int entries = 0;
  for (const auto& entry : std::filesystem::directory_iterator(parts)) {
    CHECK(entry.path().filename().string().rfind("tile_", 0) == 0);
    ++entries;
  }
  CHECK(entries == 12);
}

TEST_CASE("generate refuses tilings that do not cut every face alike, and parts of another cover", "[tiles][cli]") {
  const test::TemporaryDirectory work(true);
  const std::string parts = (work.path / "parts").string();
  const auto refused = [](const std::string& arguments, const std::string& message) {
    const test::Run r = test::run_without_gl(arguments);
    INFO(arguments << "\n" << r.output);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Catch::Contains(message));
  };
  refused("generate --size 8 --tiles 14 --out " + parts, "a multiple of 6");
  refused("generate --size 2 --tiles 18 --out " + parts, "less than a row");
  refused("generate --size 8 --tile 0 --out " + parts, "only with --tiles");
  // A cover in tiles is exported from its face files: they must be written, as floats, losslessly.
  refused("generate --size 8 --tiles 6 --files equirect --export ktx2 --out " + parts, "reads the faces");
  refused("generate --size 8 --tiles 6 --precision half --export ktx2 --out " + parts, "reads the faces");
  refused("generate --size 8 --tiles 12 --tile 5-3 --out " + parts, "0 <= A <= B < 12");
  refused("generate --size 8 --tiles 12 --tile 12 --out " + parts, "0 <= A <= B < 12");
  refused("generate --size 8 --tiles 12 --tile 0 --files faces --out " + parts, "give it to nephele assemble");
  refused("generate --size 8 --tiles 12 --curl-mode sampled --out " + parts, "sampled");
  refused("generate --size 8 --tiles 12 --sequence 2 --out " + parts, "not with --sequence");
  refused("assemble " + (work.path / "none").string() + " --out " + parts, "is not a directory");
  // Beyond the budget even in tiles of one row (with a context: the budget may come from the device).
  const test::Run tiny = test::run("generate --size 4096 --memory-budget 1 --out " + parts);
  CHECK(tiny.exit_code == 2);
  CHECK_THAT(tiny.output, Catch::Contains("--memory-budget: 1 MiB is too little"));
  REQUIRE(test::run("generate --size 8 --seed 1 --tiles 6 --tile 0 --quiet --out " + parts).exit_code == 0);
  const test::Run other = test::run("generate --size 8 --seed 2 --tiles 6 --tile 0-1 --quiet --out " + parts);
  CHECK(other.exit_code == 2);
  CHECK_THAT(other.output, Catch::Contains("tile_000000.part: a part of another cover"));
}

TEST_CASE("a damaged tile part is made again by the next run and named by assemble", "[tiles][cli]") {
  const test::TemporaryDirectory work(true);
  const std::filesystem::path parts = work.path / "parts";
  const std::string make = "generate --size 8 --seed 3 --tiles 6 --tile 0-5 --quiet --out " + parts.string();
  REQUIRE(test::run(make).exit_code == 0);
  const std::filesystem::path part = parts / "tile_000004.part";
  const std::string whole = test::read_file(part);
  std::filesystem::resize_file(part, whole.size() - 4);  // cut short, as by a full disk
  const test::Run assemble = test::run("assemble " + parts.string() + " --out " + (work.path / "c").string());
  CHECK(assemble.exit_code == 2);
  CHECK_THAT(assemble.output, Catch::Contains("lacks tiles 4"));
  const test::Run again = test::run(make);
  REQUIRE(again.exit_code == 0);
  CHECK_THAT(again.output, Catch::Contains("5 already complete, kept"));
  // The same densities, cloud tops and cover contrasts (the header's timings are the new run's):
  // the last 3 x 8 x 8 floats.
  const std::string made = test::read_file(part);
  const size_t block = 8 * 8 * sizeof(float), data = 3 * block;
  REQUIRE(made.size() >= data);
  CHECK(made.substr(made.size() - data) == whole.substr(whole.size() - data));
  // A flipped density byte, then a flipped cloud-top and cover-contrast byte: the header's hashes
  // tell, and assemble names the file.
  for (const auto& [back, what] : {std::pair<size_t, const char*>{2 * block + 3, "densities"},
                                   {block + 3, "cloud tops"},
                                   {3, "cover contrasts"}}) {
    std::string flipped = whole;
    flipped[flipped.size() - back] ^= 0x40;
    files::write_file(part, flipped.data(), flipped.size());
    const test::Run damaged = test::run("assemble " + parts.string() + " --out " + (work.path / "c").string());
    CHECK(damaged.exit_code == 2);
    CHECK_THAT(damaged.output, Catch::Contains(std::string("tile_000004.part: the ") + what + " do not match"));
  }
}

TEST_CASE("the streamed equirect map equals the GPU's within float rounding", "[tiles]") {
  test::test_context();
  // A cover-like field: smooth plus texel noise, values in [0, 1].
  const int n = 48;
  std::vector<float> faces(6 * static_cast<size_t>(n) * n);
  for (size_t k = 0; k < faces.size(); ++k)
    faces[k] = 0.5f + 0.3f * std::sin(0.013f * static_cast<float>(k)) + 0.2f * std::cos(2.7f * static_cast<float>(k));
  const int width = 4 * n, height = 2 * n;
  const std::vector<float> gpu = cover::equirect_from_faces(n, faces, width, height);
  const float* face_rows[6];
  for (int f = 0; f < 6; ++f) face_rows[f] = faces.data() + static_cast<size_t>(f) * n * n;
  std::vector<float> streamed(gpu.size(), -1.0f);
  int next_row = 0;
  cover::streamed_equirect(
      n, face_rows, width, height,
      [&](int first_row, int rows, const std::vector<float>& pixels) {
        CHECK(first_row == next_row);
        next_row += rows;
        std::copy(pixels.begin(), pixels.end(), streamed.begin() + static_cast<std::ptrdiff_t>(first_row) * width);
      },
      7);
  CHECK(next_row == height);
  // The sample point's texel coordinates carry a few ulp of n (the GPU's and the C++ cos, sin
  // and divisions round differently); neighbouring texels differ by at most 1 here, so the
  // bilinear value differs by at most that position error: 8 n 2^-24.
  const double tolerance = 8.0 * n * std::ldexp(1.0, -24);
  double worst = 0.0;
  for (size_t k = 0; k < gpu.size(); ++k) worst = std::max(worst, double(std::abs(gpu[k] - streamed[k])));
  CHECK(worst <= tolerance);
}

TEST_CASE("assemble reads the profile a tile task named by a relative path, from any directory", "[tiles][cli]") {
  const test::TemporaryDirectory work(true);
  files::write_text_file(work.path / "zonal.csv", "latitude_deg,fraction\n-60,0.8\n0,0.4\n60,0.7\n");
  const std::string nephele = NEPHELE_EXECUTABLE;
  // The task runs in the work directory and names the profile relatively; assemble runs elsewhere.
  const test::Run task = test::run_command("cd " + work.path.string() + " && " + nephele +
                                           " generate --size 8 --tiles 6 --tile 0-5 --profile zonal.csv --quiet "
                                           "--out parts");
  REQUIRE(task.exit_code == 0);
  const test::Run assemble = test::run("assemble " + (work.path / "parts").string() + " --files faces --quiet --out " +
                                       (work.path / "cover").string());
  INFO(assemble.output);
  REQUIRE(assemble.exit_code == 0);
  const json::Value sidecar = json::parse(test::read_file(work.path / "cover" / "cover.json"));
  CHECK(sidecar.at("parameters").at("profile").as_string() == (work.path / "zonal.csv").string());
}
