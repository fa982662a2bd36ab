// nephele stats (src/studies/cover_statistics.hpp) on fields with known answers, and its files
// and errors.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "cli_support.hpp"
#include "core/json.hpp"
#include "files/image_files.hpp"
#include "shader_math/shader_math.hpp"
#include "studies/cover_statistics.hpp"

using namespace nephele;

namespace {

// Sums of a few thousand solid angles in double: far below 1e-12 relative.
constexpr double kSumRounding = 1e-12;

studies::Equirect blank(int width, int height) {
  return {width, height, std::vector<float>(static_cast<size_t>(width) * height, 0.0f)};
}

void fill_rectangle(studies::Equirect& m, int x0, int y0, int w, int h) {
  for (int y = y0; y < y0 + h; ++y)
    for (int x = x0; x < x0 + w; ++x) m.values[static_cast<size_t>(y) * m.width + (x % m.width)] = 0.5f;
}

}  // namespace

TEST_CASE("coverage by band counts the cloudy solid angle of each band", "[fast][stats]") {
  // Equirect: the southern rows all cloudy, the northern ones in every other column.
  studies::Equirect m = blank(64, 32);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 64; ++x) m.values[y * 64 + x] = y >= 16 || x % 2 == 0 ? 0.3f : 0.0f;
  for (int bands : {18, 90}) {
    const std::vector<double> c = studies::band_coverage_equirect(m, bands);
    for (int b = 0; b < bands; ++b) {
      // 32 rows for 90 bands: some bands hold no row centre and report 0.
      if (bands == 90 && c[b] == 0.0) continue;
      INFO("bands " << bands << " band " << b);
      CHECK(std::abs(c[b] - (b < bands / 2 ? 1.0 : 0.5)) <= kSumRounding);
    }
  }
  // Faces: cloudy where the texel centre lies south of the equator.
  const int size = 24;
  std::vector<float> faces(6 * size * size);
  for (int f = 0; f < 6; ++f)
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i)
        faces[(f * size + j) * size + i] = glsl::texel_direction(f, i, j, size).z < 0.0f ? 1.0f : 0.0f;
  const std::vector<double> c = studies::band_coverage_faces(faces, size, 18);
  for (int b = 0; b < 18; ++b) CHECK(c[b] == (b < 9 ? 1.0 : 0.0));
}

TEST_CASE("squares of many sizes have perimeter dimension 1", "[fast][stats]") {
  // A square of side s: A = s^2 pixels, P = 4 s edges = 4 sqrt(A): log P = log 4 + log A / 2
  // exactly, so D = 2 x 1/2 = 1 up to the fit's rounding.
  studies::Equirect m = blank(1024, 512);
  int x = 2;
  for (int side = 4; side <= 40; side += 3) {
    fill_rectangle(m, x, 200, side, side);
    x += side + 3;
  }
  // One across the longitude seam (counted once) and one on the last row within 60 degrees
  // (cut off there, so left out).
  fill_rectangle(m, 1020, 300, 9, 9);
  fill_rectangle(m, 500, 80, 12, 12);
  const std::vector<studies::CloudObject> objects = studies::cloud_objects(m, 60.0);
  CHECK(objects.size() == 14);
  const studies::PerimeterDimension d = studies::perimeter_dimension(objects, 10);
  CHECK(d.objects == 14);
  CHECK(d.min_area == 16);
  CHECK(d.dimension == Approx(1.0).margin(1e-9));
}

TEST_CASE("discs of many sizes have perimeter dimension close to 1", "[fast][stats]") {
  // A digital disc of radius r has a staircase perimeter of about 8 r (each quadrant's edges
  // sum to 2 r along x and y) and area pi r^2: P ~ sqrt(A), D = 1, up to the digitisation of
  // small discs (a few percent in P from r = 3 on, which tilts the fit by less than 0.05).
  studies::Equirect m = blank(2048, 1024);
  int cx = 40;
  for (double r = 3; r <= 36; r *= 1.25) {
    for (int y = -40; y <= 40; ++y)
      for (int x = -40; x <= 40; ++x)
        if (x * x + y * y <= r * r) m.values[static_cast<size_t>(512 + y) * 2048 + cx + x] = 1.0f;
    cx += static_cast<int>(2.25 * r) + 8;  // this radius and the next, and a gap
  }
  const studies::PerimeterDimension d = studies::perimeter_dimension(studies::cloud_objects(m, 60.0), 10);
  CHECK(d.objects >= 10);
  CHECK(d.dimension == Approx(1.0).margin(0.05));
}

TEST_CASE("a 40 x 10 rectangle at the equator has elongation 4 and a disc has elongation 1", "[fast][stats]") {
  // Second moments of n pixels in a row: (n^2 - 1)/12 of the centres plus 1/12 of each pixel's
  // own extent, n^2/12: the principal ratio of a w x h rectangle is (w/h)^2 exactly, apart from
  // the rows' cos(latitude) (rows within 0.5 degrees of the equator: 4e-5).
  studies::Equirect m = blank(4096, 2048);
  fill_rectangle(m, 100, 1019, 40, 10);
  for (int y = -12; y <= 12; ++y)
    for (int x = -12; x <= 12; ++x)
      if (x * x + y * y <= 144) m.values[static_cast<size_t>(1024 + y) * 4096 + 600 + x] = 1.0f;
  const std::vector<studies::CloudObject> objects = studies::cloud_objects(m, 60.0);
  REQUIRE(objects.size() == 2);
  const studies::CloudObject& rectangle = objects[0].area == 400 ? objects[0] : objects[1];
  const studies::CloudObject& disc = objects[0].area == 400 ? objects[1] : objects[0];
  REQUIRE(rectangle.area == 400);
  CHECK(rectangle.elongation == Approx(4.0).epsilon(1e-3));
  CHECK(disc.elongation == Approx(1.0).epsilon(0.02));  // a digital disc: symmetric up to its staircase
  // Areas on the 6371 km sphere: 400 pixels of (2 pi R / 4096) x (pi R / 2048) km.
  const double pixel_km2 = 6371.0 * 6371.0 * (2 * M_PI / 4096) * (M_PI / 2048);
  CHECK(rectangle.area_km2 == Approx(400 * pixel_km2).epsilon(1e-4));
}

TEST_CASE("object statistics give the largest system's share, the mid-tones and the edge contrast of known maps",
          "[fast][stats]") {
  // Two squares on the same rows, 10 x 10 and 10 x 30 pixels: the larger holds 3/4 of the cloud.
  // The small one is 0.5 inside with a border of 1; the large one is 1: mid-tones (0.25-0.75)
  // are the small one's 8 x 8 inside, 64 of 400 pixels; the edge pixels are all 1 (contrast
  // = 1 over the cloudy mean).
  studies::Equirect m = blank(1024, 512);
  fill_rectangle(m, 100, 250, 10, 10);
  fill_rectangle(m, 300, 250, 30, 10);
  for (float& v : m.values)
    if (v > 0.0f) v = 1.0f;
  for (int y = 251; y < 259; ++y)
    for (int x = 101; x < 109; ++x) m.values[static_cast<size_t>(y) * 1024 + x] = 0.5f;
  const studies::ObjectStatistics o = studies::object_statistics(m, studies::cloud_objects(m, 60.0, true), 60.0);
  CHECK(o.objects == 2);
  // Rows 250..259 straddle the equator (rows 255.5): their cos(latitude) differ by 1e-4.
  CHECK(o.largest_share == Approx(0.75).epsilon(1e-3));
  CHECK(o.mid_tone_share == Approx(64.0 / 400.0).epsilon(1e-3));
  CHECK(o.edge_value == Approx(1.0).epsilon(1e-6));
  CHECK(o.cloudy_mean == Approx((400.0 - 32.0) / 400.0).epsilon(1e-3));
}

TEST_CASE("objects whose areas fall as 1/k have a cumulative size distribution of exponent 1", "[fast][stats]") {
  // Strips one row tall, object k of floor(S/k) pixels, k = 1 .. 400: N(>= a) = floor(S/a),
  // whose log-log slope is -1 up to the floor, below 1/N = 4 % where N >= 24 (the fit's rule);
  // the rows lie within 3 degrees of the equator, so areas in km2 are pixels times one size to
  // 0.14 %. The fitted exponent is 1 within 0.03.
  studies::Equirect m = blank(8192, 4096);
  const int S = 4000;
  int x = 0, y = 2048 - 140;
  for (int k = 1; k <= 400; ++k) {
    const int length = S / k;
    if (x + length + 2 > 8192) x = 0, y += 2;
    fill_rectangle(m, x, y, length, 1);
    x += length + 2;
  }
  REQUIRE(y < 2048 + 140);
  const studies::ObjectStatistics o = studies::object_statistics(m, studies::cloud_objects(m, 60.0, true), 60.0);
  CHECK(o.objects == 400);
  CHECK(o.size_exponent == Approx(1.0).margin(0.03));
  CHECK(o.fit_low_km2 > 0.0);
}

TEST_CASE("the zonal spectrum of a power-law signal has its slope", "[fast][stats]") {
  // Each row sum_k a_k cos(2 pi k x / W + phase_k) with a_k = k^(-beta/2): its DFT has
  // |X_k| = W a_k / 2, so P(k) = a_k^2 / 4 = k^-beta / 4 exactly, with the FFT (W = 512) and
  // the direct sum (W = 192) alike; the fit's slope is -beta to rounding.
  const double beta = 5.0 / 3.0;
  for (int width : {512, 192}) {
    studies::Equirect m = blank(width, width / 2);
    for (int y = 0; y < m.height; ++y)
      for (int x = 0; x < width; ++x) {
        double v = 0.0;
        for (int k = 1; k < width / 2; ++k)
          v += std::pow(k, -beta / 2) * std::cos(2 * M_PI * k * x / width + 0.7 * k * k + 0.1 * y);
        m.values[static_cast<size_t>(y) * width + x] = static_cast<float>(v);
      }
    const std::vector<double> p = studies::zonal_power_spectrum(m, 60.0);
    REQUIRE(p.size() == static_cast<size_t>(width / 2));
    std::vector<double> k(p.size());
    for (size_t i = 0; i < k.size(); ++i) k[i] = double(i + 1);
    INFO("width " << width);
    // Float samples (2^-24 relative of values up to ~4) leave the power within 1e-5 relative.
    CHECK(p[9] == Approx(std::pow(10.0, -beta) / 4).epsilon(1e-5));
    CHECK(studies::fit_power_law(k, p, 2, width / 4).slope == Approx(-beta).margin(1e-4));
  }
}

TEST_CASE("stats writes stats.json and stats.png beside the cover's files", "[stats][cli]") {
  test::TemporaryDirectory cover;
  REQUIRE(test::run("generate --size 32 --files faces,equirect --quiet --out " + cover.path.string()).exit_code == 0);
  const test::Run r = test::run("stats " + cover.path.string());
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK(r.output.find("perimeter dimension") != std::string::npos);
  const json::Value stats = json::parse(test::read_file(cover.path / "stats" / "stats.json"));
  const json::Value& ten = stats.at("coverage_by_latitude").at("bands_10deg");
  CHECK(ten.at("coverage").as_array().size() == 18);
  CHECK(ten.at("target").as_array().size() == 18);
  CHECK(stats.at("zonal_spectrum").at("power").as_array().size() == 64);
  CHECK(stats.at("folding").at("folded_fraction").is_number());
  CHECK(stats.at("cloud_objects").at("size_distribution").at("thresholds_km2").is_array());
  CHECK(r.output.find("edge cover") != std::string::npos);
  double histogram = 0.0;
  for (const json::Value& v : stats.at("histogram").at("fractions").as_array()) histogram += v.as_number();
  CHECK(histogram == Approx(1.0).margin(1e-9));
  const core::ImageData png = files::read_image(cover.path / "stats" / "stats.png");
  CHECK(png.width == 1200);
}

TEST_CASE("stats refuses a missing directory, a malformed cover.json and wrong sizes with code 2", "[stats][cli]") {
  test::TemporaryDirectory cover;
  const test::Run missing = test::run("stats " + (cover.path / "none").string());
  CHECK(missing.exit_code == 2);
  CHECK(missing.output.find("none") != std::string::npos);
  REQUIRE(test::run("generate --size 8 --files equirect --quiet --out " + cover.path.string()).exit_code == 0);
  const std::string sidecar = test::read_file(cover.path / "cover.json");
  std::ofstream(cover.path / "cover.json") << "{\"parameters\": ";
  const test::Run malformed = test::run("stats " + cover.path.string());
  CHECK(malformed.exit_code == 2);
  CHECK(malformed.output.find("cover.json") != std::string::npos);
  // The sidecar of another size than the equirect's.
  std::string other = sidecar;
  other.replace(other.find("\"size\": 8"), 9, "\"size\": 9");
  std::ofstream(cover.path / "cover.json") << other;
  const test::Run wrong = test::run("stats " + cover.path.string());
  CHECK(wrong.exit_code == 2);
  CHECK(wrong.output.find("cover_equirect.exr") != std::string::npos);
  CHECK(!std::filesystem::exists(cover.path / "stats"));
}

TEST_CASE("the climatology notebook runs headless on a small cover and draws its figure", "[stats][notebook]") {
  // notebooks/climatology.ipynb runs nephele generate --size 64 and nephele stats itself
  // (Debian's jupyter-nbconvert, python3-ipykernel, python3-matplotlib, as error_vs_runtime).
  test::TemporaryDirectory out(true);
  const std::filesystem::path notebook =
      std::filesystem::path(__FILE__).parent_path().parent_path() / "notebooks" / "climatology.ipynb";
  REQUIRE(std::filesystem::exists(notebook));
  const std::filesystem::path figure = out.path / "climatology.png";
  const test::Run nb =
      test::run_command("NEPHELE_EXECUTABLE=" + std::string(NEPHELE_EXECUTABLE) + " NEPHELE_FIGURE=" + figure.string() +
                        " jupyter nbconvert --to notebook --execute --ExecutePreprocessor.timeout=300 " +
                        notebook.string() + " --output-dir " + out.path.string() + " --output executed.ipynb");
  INFO(nb.output);
  REQUIRE(nb.exit_code == 0);
  CHECK(std::filesystem::file_size(figure) > 10000);
  CHECK(test::read_file(out.path / "executed.ipynb").find("largest error") != std::string::npos);
}
