// nephele report: the CSV, the comparison with the default, the diagram, the notebook, and
// the numerics options of generate and report on the command line.
#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <tuple>
#include <sstream>

#include "cli_support.hpp"
#include "gl_support.hpp"
#include "studies/work_precision.hpp"
#include "core/json.hpp"

namespace fs = std::filesystem;
using namespace nephele;
using cover::CurlMode;
using cover::Integrator;
using test::read_file;
using test::Run;
using test::run;
using test::run_command;
using test::TemporaryDirectory;

namespace {

std::vector<std::string> split(const std::string& line, char separator) {
  std::vector<std::string> fields;
  std::stringstream stream(line);
  std::string field;
  while (std::getline(stream, field, separator)) fields.push_back(field);
  return fields;
}

studies::SweepRow row(Integrator integrator, CurlMode mode, int steps, double time_ms, double error) {
  studies::SweepRow r;
  r.integrator = integrator;
  r.curl_mode = mode;
  r.size = 64;
  r.steps = steps;
  r.time_ms = time_ms;
  r.warp_err_rms = error;
  r.warp_err_max = 10 * error;
  r.cover_err_rms = error / 2;
  r.cover_err_max = error * 5;
  return r;
}

const char* const header =
    "integrator,curl_mode,size,steps,time_ms,warp_err_rms,warp_err_max,cover_err_rms,cover_err_max";

}  // namespace

TEST_CASE("the error CSV has the documented columns and one line per run", "[fast][report]") {
  const std::string csv = studies::error_csv({row(Integrator::euler, CurlMode::sampled, 50, 12.5, 0.01),
                                              row(Integrator::adaptive, CurlMode::procedural, 17, 80.0, 1e-4)});
  std::stringstream lines(csv);
  std::string line;
  std::getline(lines, line);
  CHECK(line == header);
  std::getline(lines, line);
  const auto first = split(line, ',');
  REQUIRE(first.size() == 9);
  CHECK(first[0] == "euler");
  CHECK(first[1] == "sampled");
  CHECK(first[2] == "64");
  CHECK(first[3] == "50");
  CHECK(std::stod(first[4]) == Approx(12.5));
  CHECK(std::stod(first[5]) == Approx(0.01));
  std::getline(lines, line);
  CHECK(split(line, ',')[0] == "adaptive");
  CHECK(split(line, ',')[1] == "procedural");
  CHECK(!std::getline(lines, line));
}

TEST_CASE("the comparison finds the fastest run at the default's error and the most accurate within its time",
          "[fast][report]") {
  const std::vector<studies::SweepRow> rows{
      row(Integrator::euler, CurlMode::sampled, 50, 100.0, 0.010),  // the default
      row(Integrator::euler, CurlMode::sampled, 100, 190.0, 0.006),
      row(Integrator::heun, CurlMode::sampled, 10, 40.0, 0.012),  // cheaper, less accurate
      row(Integrator::heun, CurlMode::sampled, 20, 60.0, 0.009),  // equal error, fastest
      row(Integrator::rk4, CurlMode::sampled, 20, 95.0, 0.004),   // equal time, most accurate
      row(Integrator::rk4, CurlMode::procedural, 20, 900.0, 0.001)};
  const auto comparisons = studies::compare_with_default(rows);
  REQUIRE(comparisons.size() == 1);
  const auto& c = comparisons[0];
  REQUIRE(c.has_baseline);
  REQUIRE(c.has_equal_error);
  CHECK(c.equal_error.integrator == Integrator::heun);
  CHECK(c.speedup == Approx(100.0 / 60.0));
  REQUIRE(c.has_equal_time);
  CHECK(c.equal_time.integrator == Integrator::rk4);
  CHECK(c.equal_time.curl_mode == CurlMode::sampled);
  CHECK(c.error_ratio == Approx(0.010 / 0.004));
}

TEST_CASE("the work-precision diagram draws one line per integrator curl mode and size", "[fast][report]") {
  const std::string svg = studies::work_precision_svg({row(Integrator::euler, CurlMode::sampled, 10, 20.0, 0.05),
                                                       row(Integrator::euler, CurlMode::sampled, 50, 100.0, 0.01),
                                                       row(Integrator::rk4, CurlMode::procedural, 10, 500.0, 1e-3)},
                                                      "test");
  size_t lines = 0;
  for (size_t at = svg.find("<polyline"); at != std::string::npos; at = svg.find("<polyline", at + 1)) ++lines;
  CHECK(lines == 4);                                         // two series in each of the two panels
  CHECK(svg.find("stroke-dasharray") != std::string::npos);  // the procedural series
  CHECK(svg.rfind("</svg>") != std::string::npos);
}

namespace {

// The warp part of the report made as small as it goes: one size, one step count and one
// tolerance still give every integrator and curl mode (16 rows).
const std::string small_warp = "--quick --sizes 8 --steps 10 --tolerances 1e-2 --samples 1";

// The warp part of `report --quick` alone (--no-render), run once for the tests that read its
// files: the sweep is the slow part of this file.
struct NoRenderReport {
  TemporaryDirectory out;
  Run result;
  NoRenderReport() : result(run("report " + small_warp + " --no-render --out " + out.path.string())) {}
};
const NoRenderReport& no_render_report() {
  static const NoRenderReport report;
  return report;
}

}  // namespace

TEST_CASE("report --quick writes the CSV the diagram and the summary and the notebook draws the CSV", "[report][cli]") {
  // The render part has its own test below.
  const NoRenderReport& report = no_render_report();
  const TemporaryDirectory& out = report.out;
  const Run& r = report.result;
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const std::string csv = read_file(out.path / "error_vs_runtime.csv");
  std::stringstream lines(csv);
  std::string line;
  std::getline(lines, line);
  CHECK(line == header);
  std::set<std::string> integrators, modes;
  int rows = 0;
  while (std::getline(lines, line)) {
    const auto fields = split(line, ',');
    REQUIRE(fields.size() == 9);
    integrators.insert(fields[0]);
    modes.insert(fields[1]);
    for (size_t k = 2; k < fields.size(); ++k) {
      const double v = std::stod(fields[k]);
      REQUIRE(std::isfinite(v));
      REQUIRE(v >= 0.0);
    }
    ++rows;
  }
  CHECK(integrators == std::set<std::string>{"euler", "heun", "rk4", "geodesic", "adaptive"});
  CHECK(modes == std::set<std::string>{"sampled", "procedural", "spline"});
  CHECK(rows >= 10);
  CHECK(read_file(out.path / "error_vs_runtime.svg").find("<polyline") != std::string::npos);
  const std::string summary = read_file(out.path / "summary.md");
  CHECK(summary.find("speed-up") != std::string::npos);
  CHECK(summary.find("Best speed-up at equal error") != std::string::npos);
  CHECK(read_file(out.path / "stability.csv").find("stiffness") != std::string::npos);
  // The moving flow: both sweeps, every row finite; RK4 converges towards the reference as the
  // step shrinks (procedural: no other error; at least 8 times smaller over 4 times the steps,
  // order 4 allowing for the smooth potential's limited smoothness), and a longer window errs more.
  std::stringstream moving(read_file(out.path / "moving_error.csv"));
  std::getline(moving, line);
  CHECK(line.rfind("sweep,curl_mode,curl_size,iterations,step,window_hours,time_ms,", 0) == 0);
  std::map<std::string, double> procedural_error;
  int moving_rows = 0;
  while (std::getline(moving, line)) {
    const auto fields = split(line, ',');
    REQUIRE(fields.size() == 13);
    CHECK(fields[11] == "1");
    for (size_t k = 4; k < 11; ++k) REQUIRE(std::isfinite(std::stod(fields[k])));
    if (fields[1] == "procedural") procedural_error[fields[0] + fields[3]] = std::stod(fields[10]);
    ++moving_rows;
  }
  // 3 step counts x (procedural, spline 32), 3 windows x the two, and one warp grid (8 nodes).
  CHECK(moving_rows == 13);
  CHECK(procedural_error["step4"] * 8 <= procedural_error["step1"]);
  CHECK(procedural_error["window4"] > procedural_error["window1"]);
  CHECK(summary.find("## The moving flow: error against run time and window") != std::string::npos);
  CHECK(read_file(out.path / "moving_error_vs_runtime.svg").find("<polyline") != std::string::npos);
  // The noise grid: the reference without error, the two scales, and the thresholds 4, 2, 1 taking
  // 1, 2, 3 octaves at 64 per face from a grid of 32; each octave more from the grid adds its own
  // error to the density (the octaves' errors are independent, so the rms grows).
  std::stringstream noise_grid(read_file(out.path / "noise_grid_error.csv"));
  std::getline(noise_grid, line);
  CHECK(line ==
        "kind,noise_grid_nodes,grid_octaves,time_ms,density_err_rms,density_err_max,cover_err_rms,flipped,"
        "density_spread");
  std::vector<std::vector<std::string>> grid_rows;
  while (std::getline(noise_grid, line)) grid_rows.push_back(split(line, ','));
  REQUIRE(grid_rows.size() == 6);
  CHECK(grid_rows[0][0] == "every octave at every texel");
  CHECK(std::stod(grid_rows[0][4]) == 0.0);
  CHECK(grid_rows[1][0] == "trajectories from every texel");
  CHECK(grid_rows[2][0] == "ten minutes later");
  CHECK(std::stod(grid_rows[2][4]) > 0.0);
  for (int k = 3; k < 6; ++k) {
    CHECK(grid_rows[k][0] == "noise grid");
    CHECK(std::stoi(grid_rows[k][2]) == k - 2);
    CHECK(std::stod(grid_rows[k][4]) > (k == 3 ? 0.0 : std::stod(grid_rows[k - 1][4])));
  }
  CHECK(summary.find("## The noise grid") != std::string::npos);
  CHECK(read_file(out.path / "noise_grid_error_vs_runtime.svg").find("<polyline") != std::string::npos);

  // The notebook reads that CSV and draws the same diagram, headless (Debian's
  // jupyter-nbconvert, python3-ipykernel, python3-matplotlib; scripts/debian-packages.txt).
  const fs::path notebook = fs::path(__FILE__).parent_path().parent_path() / "notebooks" / "error_vs_runtime.ipynb";
  REQUIRE(fs::exists(notebook));
  const fs::path figure = out.path / "notebook_figure.png";
  const Run nb = run_command("NEPHELE_REPORT_DIR=" + out.path.string() + " NEPHELE_FIGURE=" + figure.string() +
                             " jupyter nbconvert --to notebook --execute --ExecutePreprocessor.timeout=300 " +
                             notebook.string() + " --output-dir " + out.path.string() + " --output executed.ipynb");
  INFO(nb.output);
  REQUIRE(nb.exit_code == 0);
  CHECK(fs::file_size(figure) > 10000);
  const std::string executed = read_file(out.path / "executed.ipynb");
  CHECK(executed.find("runs from") != std::string::npos);
}

TEST_CASE("report render writes the render error CSV and diagram its summary section and the qualities",
          "[report][render][cli]") {
  // The quick render sweep alone (view 8, 16, 48 x light 2, 12, the defaults over 2 frames and at
  // 1/2 resolution, against 96 x 12 steps over 2 frames), at a frame size of its own: `report`
  // without `render` writes the same files beside the warp part's (whose files the test above
  // reads from a run with --no-render).
  TemporaryDirectory out;
  const Run r = run("report render --quick --render-size 24x12 --out " + out.path.string());
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK(r.output.find("render sweep") != std::string::npos);
  std::stringstream lines(read_file(out.path / "render_error.csv"));
  std::string line;
  std::getline(lines, line);
  CHECK(line ==
        "view_steps,light_steps,frames,divisor,clouds_ms,display_rms,rel_rms,rel_max,reference_view_steps,"
        "reference_light_steps,reference_frames,width,height");
  std::set<std::tuple<int, int, int, int>> variants;
  int rows = 0;
  while (std::getline(lines, line)) {
    const auto fields = split(line, ',');
    REQUIRE(fields.size() == 13);
    variants.insert({std::stoi(fields[0]), std::stoi(fields[1]), std::stoi(fields[2]), std::stoi(fields[3])});
    for (size_t k = 4; k < 8; ++k) {
      const double v = std::stod(fields[k]);
      CHECK(std::isfinite(v));
      CHECK(v >= 0.0);
    }
    // None of the quick runs is the reference (96 x 12 over 2 frames); display values lie in [0, 1].
    CHECK(std::stod(fields[5]) > 0.0);
    CHECK(std::stod(fields[5]) <= 1.0);
    CHECK(fields[8] == "96");
    CHECK(fields[9] == "12");
    CHECK(fields[10] == "2");
    CHECK(fields[11] == "24");
    CHECK(fields[12] == "12");
    ++rows;
  }
  CHECK(rows == 8);
  CHECK(variants == std::set<std::tuple<int, int, int, int>>{{8, 2, 1, 1},
                                                             {8, 12, 1, 1},
                                                             {16, 2, 1, 1},
                                                             {16, 12, 1, 1},
                                                             {48, 2, 1, 1},
                                                             {48, 12, 1, 1},
                                                             {48, 12, 2, 1},
                                                             {48, 12, 1, 2}});
  const std::string svg = read_file(out.path / "render_error_vs_runtime.svg");
  size_t polylines = 0;
  for (size_t at = svg.find("<polyline"); at != std::string::npos; at = svg.find("<polyline", at + 1)) ++polylines;
  CHECK(polylines == 2);
  CHECK(svg.find(">48x12 2f</text>") != std::string::npos);
  CHECK(svg.find(">48x12 1/2</text>") != std::string::npos);
  const std::string summary = read_file(out.path / "summary.md");
  CHECK(summary.find("## Render: image error against run time") == 0);
  CHECK(summary.find("speed-up") == std::string::npos);  // no warp part
  CHECK(summary.find("Defaults (the final quality, `--quality final`, and the library's): 48 view x 12 light steps, "
                     "display rms") != std::string::npos);
  CHECK(summary.find("Cheapest within 1.5x the default's error") != std::string::npos);
  CHECK(summary.find("Most accurate within the default's time") != std::string::npos);
  CHECK_FALSE(fs::exists(out.path / "error_vs_runtime.csv"));

  // The qualities of render --quality, each with its target and whether it meets it.
  std::stringstream quality_lines(read_file(out.path / "render_quality.csv"));
  std::string quality_line;
  std::getline(quality_lines, quality_line);
  CHECK(quality_line.rfind("quality,target_display_rms,", 0) == 0);
  int qualities = 0;
  while (std::getline(quality_lines, quality_line)) ++qualities;
  CHECK(qualities == 3);
  CHECK(summary.find("## Render: qualities") != std::string::npos);
  CHECK(summary.find("| default | 16 view x 4 light steps, 1/4 resolution | 0.01 |") != std::string::npos);

  // --no-render writes neither render file.
  const TemporaryDirectory& skipped = no_render_report().out;
  const Run& no_render = no_render_report().result;
  INFO(no_render.output);
  REQUIRE(no_render.exit_code == 0);
  CHECK(fs::exists(skipped.path / "summary.md"));
  CHECK_FALSE(fs::exists(skipped.path / "render_error.csv"));
  CHECK_FALSE(fs::exists(skipped.path / "render_error_vs_runtime.svg"));
  CHECK(read_file(skipped.path / "summary.md").find("Not run (--no-render)") != std::string::npos);
}

TEST_CASE("report and generate reject bad numerics options with exit code 2 and write nothing", "[report][cli]") {
  struct Case {
    std::string arguments, option;
  };
  const std::vector<Case> cases{
      {"report --sizes 0", "--sizes"},
      {"report --sizes 32,abc", "--sizes"},
      {"report --steps 2.5", "--steps"},
      {"report --tolerances 0", "--tolerances"},
      {"report --samples 65", "--samples"},
      {"report --render-size 0x90", "--render-size"},
      {"report --render-size wide", "--render-size"},
      {"generate --integrator rk5", "--integrator"},
      {"generate --curl-mode exact", "--curl-mode"},
      {"generate --tolerance 0", "--tolerance"},
      {"generate --max-substeps 0", "--max-substeps"},
      {"generate --noise-offset 1e10", "--noise-offset"},
      {"generate --noise-offset far", "--noise-offset"},
  };
  for (const Case& c : cases) {
    TemporaryDirectory out;
    const Run r = run(c.arguments + " --out " + out.path.string());
    INFO(c.arguments << ": " << r.output);
    CHECK(r.exit_code == 2);
    CHECK(r.output.find(c.option) != std::string::npos);
    CHECK(!fs::exists(out.path));
  }
  const Run help = run("generate --help");
  CHECK(help.output.find("--integrator") != std::string::npos);
  CHECK(help.output.find("euler, heun, rk4, geodesic, adaptive") != std::string::npos);
}

TEST_CASE("generate warns about a stiff warp and records it in cover.json while adaptive sub-steps", "[report][cli]") {
  const std::string stiff =
      "--flow steady --size 32 --curl-frequency 64 --curl-octaves 1 --curl-strength 0.1 --iterations 6 --step 0.05 "
      "--curl-mode sampled";
  // Warnings other than the stiffness one: the texels of size 32 cannot resolve this flow's
  // stretching, so the fold warning stands beside it.
  auto stiffness_warnings = [](const json::Value& numerics) {
    int n = 0;
    for (const auto& w : numerics.at("warnings").as_array()) n += w.as_string().find("stiffness") != std::string::npos;
    return n;
  };
  {
    TemporaryDirectory out;
    const Run r = run("generate " + stiff + " --integrator euler --out " + out.path.string());
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    CHECK(r.output.find("warning") != std::string::npos);
    CHECK(r.output.find("stiffness") != std::string::npos);
    const json::Value sidecar = json::parse(read_file(out.path / "cover.json"));
    CHECK(sidecar.at("parameters").at("integrator").as_string() == "euler");
    const json::Value& numerics = sidecar.at("result").at("numerics");
    CHECK(numerics.at("stiffness").at("stiffness_number").as_number() >
          numerics.at("stiffness").at("stable_limit").as_number());
    CHECK(stiffness_warnings(numerics) == 1);
    CHECK(numerics.at("folding").at("folded_fraction").as_number() >= 0.0);
  }
  {
    TemporaryDirectory out;
    const Run r = run("generate " + stiff + " --integrator adaptive --tolerance 1e-4 --out " + out.path.string());
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    CHECK(r.output.find("stiffness") == std::string::npos);
    const json::Value sidecar = json::parse(read_file(out.path / "cover.json"));
    CHECK(sidecar.at("parameters").at("integrator").as_string() == "adaptive");
    CHECK(sidecar.at("parameters").at("tolerance").as_number() == Approx(1e-4));
    const json::Value& numerics = sidecar.at("result").at("numerics");
    CHECK(numerics.at("substeps").at("mean").as_number() > 6.0);
    CHECK(numerics.at("substeps").at("capped_texels").as_number() == 0.0);
    CHECK(stiffness_warnings(numerics) == 0);
  }
  {
    // The moving flow (RK4 only) warns of the same stiff vortices and advises the step alone.
    TemporaryDirectory out;
    const Run r = run("generate --size 16 --curl-frequency 64 --curl-octaves 1 --iterations 6 --step 0.05 --out " +
                      out.path.string());
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    CHECK(r.output.find("stiffness") != std::string::npos);
    CHECK(r.output.find("--integrator adaptive") == std::string::npos);
    const json::Value sidecar = json::parse(read_file(out.path / "cover.json"));
    CHECK(sidecar.at("parameters").at("flow").as_string() == "moving");
    CHECK(stiffness_warnings(sidecar.at("result").at("numerics")) == 1);
  }
}

TEST_CASE("generate warns with the figure where the warp folds and not on the default flow", "[report][cli]") {
  {
    TemporaryDirectory out;
    const Run r = run("generate --size 16 --curl-strength 0.5 --files png --out " + out.path.string());
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    CHECK(r.output.find("warning: the warp folds the sphere over itself on ") != std::string::npos);
    const json::Value numerics = json::parse(read_file(out.path / "cover.json")).at("result").at("numerics");
    CHECK(numerics.at("folding").at("folded_fraction").as_number() > 0.0);
    CHECK(numerics.at("warnings").as_array().size() >= 1);
  }
  {
    TemporaryDirectory out;
    // 64 texels a face resolve the default flow's stretching (16 do not: the finite differences
    // of the warp then see folds that the exact flow map, a diffeomorphism, never has).
    const Run r = run("generate --size 64 --files png --out " + out.path.string());
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    CHECK(r.output.find("warning") == std::string::npos);
    const json::Value numerics = json::parse(read_file(out.path / "cover.json")).at("result").at("numerics");
    CHECK(numerics.at("folding").at("folded_fraction").as_number() == 0.0);
    CHECK(numerics.at("folding").at("jacobian_min").as_number() > 0.0);
  }
}

TEST_CASE("the observed order is minus the slope of log error against log steps above the floor", "[fast][report]") {
  // err = 0.3 K^-3 exactly, plus one run below the floor that the fit must leave out.
  std::vector<studies::SweepRow> rows;
  for (int k : {2, 4, 8}) rows.push_back(row(Integrator::rk4, CurlMode::procedural, k, 1.0, 0.3 * std::pow(k, -3.0)));
  rows.push_back(row(Integrator::rk4, CurlMode::procedural, 64, 1.0, 0.5 * studies::order_error_floor));
  rows.push_back(row(Integrator::euler, CurlMode::procedural, 50, 1.0, 1e-3));  // one run: no fit
  const auto orders = studies::observed_orders(rows);
  REQUIRE(orders.size() == 1);
  CHECK(orders[0].runs == 3);
  CHECK(orders[0].order == Approx(3.0).epsilon(0).margin(1e-12));
}

namespace {
// Observed orders on the default flow with the analytic curl of the smooth potential. The
// step counts 1, 2, 4, 8 keep the errors between the pre-asymptotic range and the float floor
// (measured at size 32 with 2, 4, 8 steps: Euler 1.6e-2 .. 4.2e-3, Heun 3.7e-3 .. 2.1e-4, RK4
// 8.6e-5 .. 3.0e-7, ratios 2.0, 4.2 and 17.9 per halving; RK4's 3e-7 falls under the fit's
// floor, so 1 step is added); the slack covers the pre-asymptotic drift of the first halvings
// and the 96-point sample.
constexpr double kEulerOrderSlack = 0.2;
constexpr double kHeunOrderSlack = 0.3;
constexpr double kRk4OrderSlack = 0.6;
}  // namespace

TEST_CASE("the report observes order 1 for Euler 2 for Heun and 4 for RK4 on the default smooth flow",
          "[report][gpu]") {
  // Both smooth velocities: the analytic curl, and its spline at the default grid (the default
  // curl mode), whose warp differs from the procedural one by about 1e-6 rms (docs/numerics.md,
  // "The spline velocity"), below the errors the fit uses (order_error_floor and up).
  test::test_context();
  for (CurlMode mode : {CurlMode::procedural, CurlMode::spline}) {
    auto options = studies::SweepOptions::quick(cover::CoverParameters{});
    options.sizes = {8};
    options.integrators = {Integrator::euler, Integrator::heun, Integrator::rk4};
    options.curl_modes = {mode};
    options.steps = {1, 2, 4, 8};
    options.budget_ms = 1e7;
    const auto result = studies::run_sweep(options, [](const std::string&) {});
    std::map<Integrator, double> order;
    for (const auto& o : result.orders) order[o.integrator] = o.order;
    INFO(cover::curl_mode_name(mode) << ": euler " << order[Integrator::euler] << ", heun " << order[Integrator::heun]
                                     << ", rk4 " << order[Integrator::rk4]);
    CHECK(order[Integrator::euler] == Approx(1.0).epsilon(0).margin(kEulerOrderSlack));
    CHECK(order[Integrator::heun] == Approx(2.0).epsilon(0).margin(kHeunOrderSlack));
    CHECK(order[Integrator::rk4] == Approx(4.0).epsilon(0).margin(kRk4OrderSlack));
  }
}
