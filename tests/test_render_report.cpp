// The render part of `nephele report`: the sweep configurations, the CSV, the diagram, the
// choice of settings against the defaults, the summary section, and the sweep's determinism.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "gl_support.hpp"
#include "regional/scene.hpp"
#include "studies/render_error.hpp"
#include "studies/render_report.hpp"

using namespace nephele;
using studies::RenderErrorRow;

namespace {

std::vector<std::string> fields_of(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream stream(line);
  std::string field;
  while (std::getline(stream, field, ',')) fields.push_back(field);
  return fields;
}

size_t count_of(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// A hand-made sweep: the default is 48 x 6 (rms 0.20, 100 ms).
const std::vector<RenderErrorRow> table{
    {8, 2, 20.0, 0.50, 2.0},    // cheap, far too inaccurate
    {16, 4, 40.0, 0.31, 1.5},   // just over 1.5 x the default's error
    {32, 4, 60.0, 0.29, 1.4},   // within 1.5 x: the cheapest such
    {32, 6, 70.0, 0.25, 1.3},   // within 1.5 x but dearer
    {48, 6, 100.0, 0.20, 1.2},  // the default
    {96, 2, 95.0, 0.18, 1.1},   // within the default's time, less accurate than the next
    {48, 12, 99.0, 0.15, 1.0},  // within the default's time: the most accurate such
    {96, 12, 200.0, 0.05, 0.5}, // more accurate still, but twice the time
};

}  // namespace

TEST_CASE("both render sweeps contain the default step counts and a reference beyond every swept count", "[render][report]") {
  // The report states the default's error, so the default must be among the rows; and a
  // reference is only one if it takes at least as many steps as any row it judges.
  const regional::Scene defaults;
  for (const auto& o : {studies::RenderSweepOptions::full(), studies::RenderSweepOptions::quick()}) {
    CHECK(std::count(o.view_steps.begin(), o.view_steps.end(), defaults.view_steps) == 1);
    CHECK(std::count(o.light_steps.begin(), o.light_steps.end(), defaults.light_steps) == 1);
    CHECK(*std::max_element(o.view_steps.begin(), o.view_steps.end()) <= o.reference_view);
    CHECK(*std::max_element(o.light_steps.begin(), o.light_steps.end()) <= o.reference_light);
    CHECK(o.width > 0);
    CHECK(o.height > 0);
  }
}

TEST_CASE("the render error CSV has the documented columns and one line per row", "[render][report]") {
  auto options = studies::RenderSweepOptions::quick();
  const std::string csv = studies::render_error_csv({{8, 2, 12.5, 0.25, 1.5}, {48, 6, 80.0, 0.0625, 0.75}}, options);
  std::stringstream lines(csv);
  std::string line;
  REQUIRE(std::getline(lines, line));
  CHECK(line == "view_steps,light_steps,clouds_ms,rel_rms,rel_max,reference_view_steps,reference_light_steps,width,height");
  REQUIRE(std::getline(lines, line));
  const auto first = fields_of(line);
  REQUIRE(first.size() == 9);
  CHECK(first[0] == "8");
  CHECK(first[1] == "2");
  CHECK(std::stod(first[2]) == Approx(12.5));
  CHECK(std::stod(first[3]) == Approx(0.25));
  CHECK(std::stod(first[4]) == Approx(1.5));
  CHECK(first[5] == "96");
  CHECK(first[6] == "12");
  CHECK(first[7] == "32");
  CHECK(first[8] == "18");
  REQUIRE(std::getline(lines, line));
  CHECK(fields_of(line)[0] == "48");
  CHECK(std::stod(fields_of(line)[3]) == Approx(0.0625));
  CHECK_FALSE(std::getline(lines, line));
  CHECK(studies::render_error_csv({}, options).find('\n') == csv.find('\n'));  // only the header
}

TEST_CASE("the render diagram draws one polyline per light-step count labels view steps and rings the default",
          "[render][report]") {
  const std::string svg = studies::render_error_svg(table, "title & <device>", "subtitle", 48, 6);
  CHECK(count_of(svg, "<polyline") == 4);  // light 2, 4, 6, 12
  CHECK(count_of(svg, "r='8'") == 1);      // the ring around the default
  CHECK(count_of(svg, "<circle") == table.size() + 1);
  CHECK(svg.find(">96</text>") != std::string::npos);  // a view-step label
  CHECK(svg.find("12 light steps") != std::string::npos);
  CHECK(svg.find("title &amp; &lt;device&gt;") != std::string::npos);
  CHECK(svg.rfind("</svg>") != std::string::npos);
  // A zero error (the reference's own steps) has no place on a log scale: left out, and said so.
  std::vector<RenderErrorRow> with_zero = table;
  with_zero.push_back({384, 24, 900.0, 0.0, 0.0});
  const std::string svg_zero = studies::render_error_svg(with_zero, "t", "s", 48, 6);
  CHECK(count_of(svg_zero, "<polyline") == 4);
  CHECK(svg_zero.find("zero-error rows not drawn") != std::string::npos);
}

TEST_CASE("the render step choice finds the cheapest within 1.5x the default's error and the most accurate within its time",
          "[render][report]") {
  const auto c = studies::choose_render_steps(table, 48, 6);
  REQUIRE(c.has_default);
  CHECK(c.default_row.view_steps == 48);
  CHECK(c.default_row.light_steps == 6);
  REQUIRE(c.has_cheapest);
  CHECK(c.cheapest.view_steps == 32);
  CHECK(c.cheapest.light_steps == 4);
  REQUIRE(c.has_most_accurate);
  CHECK(c.most_accurate.view_steps == 48);
  CHECK(c.most_accurate.light_steps == 12);

  // A tighter factor: only 96 x 2 is both cheaper and accurate enough.
  const auto tight = studies::choose_render_steps(table, 48, 6, 1.1);
  REQUIRE(tight.has_cheapest);
  CHECK(tight.cheapest.view_steps == 96);
  CHECK(tight.cheapest.light_steps == 2);

  // When no run beats the default either way, the default itself is both choices.
  const std::vector<RenderErrorRow> sparse{table[0], table[4], table[7]};
  const auto alone = studies::choose_render_steps(sparse, 48, 6);
  REQUIRE(alone.has_cheapest);
  REQUIRE(alone.has_most_accurate);
  CHECK(alone.cheapest.view_steps == 48);
  CHECK(alone.cheapest.light_steps == 6);
  CHECK(alone.most_accurate.view_steps == 48);
  CHECK(alone.most_accurate.light_steps == 6);

  // Without the default in the sweep there is nothing to compare with.
  const auto none = studies::choose_render_steps(table, 64, 6);
  CHECK_FALSE(none.has_default);
  CHECK_FALSE(none.has_cheapest);
  CHECK_FALSE(none.has_most_accurate);
}

TEST_CASE("the render summary section names the defaults their error and the two choices", "[render][report]") {
  const auto options = studies::RenderSweepOptions::full();
  const std::string md = studies::render_summary_markdown(table, options, studies::choose_render_steps(table, 48, 6), 48, 6);
  CHECK(md.find("## Render: image error against run time") == 0);
  CHECK(md.find("160 x 90") != std::string::npos);
  CHECK(md.find("384 view x 24 light steps") != std::string::npos);
  CHECK(md.find("Defaults (of `nephele render` and scene files): 48 view x 6 light steps, rel rms 0.2000") !=
        std::string::npos);
  CHECK(md.find("Cheapest within 1.5x the default's error (rel rms <= 0.3000): 32 view x 4 light steps, rel rms "
                "0.2900, 60.0 ms (0.60x the default's time)") != std::string::npos);
  CHECK(md.find("Most accurate within the default's time (<= 100.0 ms): 48 view x 12 light steps, rel rms 0.1500 "
                "(0.75x the default's error)") != std::string::npos);
  CHECK(count_of(md, "\n| ") == table.size() + 1);  // the header and one table line per row
  const std::string without =
      studies::render_summary_markdown(table, options, studies::choose_render_steps(table, 64, 6), 64, 6);
  CHECK(without.find("not in this sweep") != std::string::npos);
}

TEST_CASE("the render error sweep is exactly zero at the reference's own step counts", "[render][report]") {
  test::test_context();
  regional::Scene scene;  // the default scene, made cheap
  scene.cover_size = 16;
  // A seed whose 16-texel cover (Earth profile, 8 density octaves at gain 0.75) has clouds in
  // this small view: with none in view every step count renders the same sky and the sweep has
  // nothing to measure (seeds 2, 8 and 12 have none).
  scene.seed = 4;
  studies::RenderSweepOptions options;
  options.view_steps = {6, 12};
  options.light_steps = {3};
  options.reference_view = 12;
  options.reference_light = 3;
  options.width = 16;
  options.height = 8;
  int reported = 0;
  const auto rows = studies::render_error_sweep(scene, options, [&](const RenderErrorRow&) { ++reported; });
  REQUIRE(rows.size() == 2);
  CHECK(reported == 2);
  CHECK(rows[0].view_steps == 6);
  CHECK(std::isfinite(rows[0].rms_error));
  CHECK(rows[0].rms_error > 0.0);
  CHECK(rows[0].max_error >= rows[0].rms_error);
  CHECK(rows[1].view_steps == 12);
  CHECK(rows[1].rms_error == 0.0);  // rendering is deterministic
  CHECK(rows[1].max_error == 0.0);
  for (const auto& r : rows) CHECK(r.time_ms > 0.0);
}
