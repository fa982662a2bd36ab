// The render part of `nephele report`: the sweep configurations, the CSV, the diagram, the
// choice of settings against the defaults, the summary section, and the sweep's determinism.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "gl_support.hpp"
#include "params/render_quality.hpp"
#include "regional/scene.hpp"
#include "render/upsample.hpp"
#include "shader_math/shader_math.hpp"
#include "studies/render_error.hpp"
#include "studies/render_report.hpp"
#include "render/cloud_renderer.hpp"

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

// A row of one frame at full resolution: display RMS `display`, the radiance errors twice it.
RenderErrorRow row(int view, int light, double ms, double display, int frames = 1, int divisor = 1) {
  return {view, light, frames, divisor, ms, display, 2 * display, 8 * display};
}

// A hand-made sweep: the default is 48 x 6 (display rms 0.20, 100 ms).
const std::vector<RenderErrorRow> table{
    row(8, 2, 20.0, 0.50),         // cheap, far too inaccurate
    row(16, 4, 40.0, 0.31),        // just over 1.5 x the default's error
    row(32, 4, 60.0, 0.29),        // within 1.5 x: the cheapest such
    row(32, 6, 70.0, 0.25),        // within 1.5 x but dearer
    row(48, 6, 100.0, 0.20),       // the default
    row(96, 2, 95.0, 0.18),        // within the default's time, less accurate than the next
    row(48, 12, 99.0, 0.15),       // within the default's time: the most accurate such
    row(96, 12, 200.0, 0.05),      // more accurate still, but twice the time
    row(48, 6, 400.0, 0.10, 4),    // the default's steps over 4 frames: not the default
    row(48, 6, 30.0, 0.40, 1, 2),  // at half resolution: not the default either
};

}  // namespace

TEST_CASE("both render sweeps contain the default settings and a reference beyond every swept setting",
          "[fast][render][report]") {
  // The report states the default's error, so the default must be among the rows; and a
  // reference is only one if it takes at least as many steps and frames as any row it judges.
  const regional::Scene defaults;
  for (const auto& o : {studies::RenderSweepOptions::full(), studies::RenderSweepOptions::quick()}) {
    const auto variants = o.variants();
    CHECK(std::count_if(variants.begin(), variants.end(), [&](const studies::RenderVariant& v) {
            return v.view_steps == defaults.view_steps && v.light_steps == defaults.light_steps && v.frames == 1 &&
                   v.divisor == 1;
          }) == 1);
    for (const auto& v : variants) {
      CHECK(v.view_steps <= o.reference_view);
      CHECK(v.light_steps <= o.reference_light);
      CHECK(v.frames <= o.reference_frames);
      CHECK(v.divisor >= 1);
      CHECK(o.width / v.divisor >= 1);
    }
    // Frame counts and resolutions are swept, not only steps.
    CHECK(std::any_of(variants.begin(), variants.end(), [](const auto& v) { return v.frames > 1; }));
    CHECK(std::any_of(variants.begin(), variants.end(), [](const auto& v) { return v.divisor > 1; }));
    CHECK(o.width > 0);
    CHECK(o.height > 0);
  }
  // The reference: more steps than any variant, yet within llvmpipe's loop limit on the longest
  // grazing interval (4 x the view steps, each in VIEW_REFINE sub-steps with a light march and
  // 3 scattering octaves; the sky's 17 per sample besides): a reference cut short is none.
  const auto full = studies::RenderSweepOptions::full();
  const auto variants = full.variants();
  for (const auto& v : variants) {
    CHECK(full.reference_view > v.view_steps);
    CHECK(full.reference_light > v.light_steps);
  }
  const int loops =
      full.reference_view * 4 * glsl::VIEW_REFINE * (full.reference_light + 3) + 17 * regional::Scene{}.sky_steps;
  CHECK(loops < glsl::LOOP_LIMIT);
  CHECK(full.reference_frames == std::max_element(variants.begin(), variants.end(), [](const auto& a, const auto& b) {
                                   return a.frames < b.frames;
                                 })->frames);
}

TEST_CASE("bilinear upsampling lines up pixel centres and clamps at the edges", "[fast][render][report]") {
  const core::ImageData two{2, 1, 1, {0.0f, 1.0f}};
  // Output centres at source x = (i + 1/2) 2/4 - 1/2 = -0.25, 0.25, 0.75, 1.25; clamped to [0, 1].
  const auto four = render::upsample_bilinear(two, 4, 1);
  REQUIRE(four.pixels.size() == 4);
  CHECK(four.pixels[0] == 0.0f);
  CHECK(four.pixels[1] == Approx(0.25f));
  CHECK(four.pixels[2] == Approx(0.75f));
  CHECK(four.pixels[3] == 1.0f);
  // The same size is the identity; a constant image stays constant; channels kept apart.
  const core::ImageData rgba{2, 2, 4, {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16}};
  CHECK(render::upsample_bilinear(rgba, 2, 2).pixels == rgba.pixels);
  const core::ImageData flat{3, 2, 2, std::vector<float>(12, 0.5f)};
  for (float v : render::upsample_bilinear(flat, 7, 5).pixels) CHECK(v == Approx(0.5f));
  const auto down_the_middle = render::upsample_bilinear(rgba, 4, 4);
  // Pixel (1, 1) of 4x4 sits at source (0.25, 0.25): 0.75^2 p00 + 0.75 0.25 (p10 + p01) + 0.25^2 p11.
  CHECK(down_the_middle.pixels[(1 * 4 + 1) * 4 + 0] == Approx(0.5625 * 1 + 0.1875 * (5 + 9) + 0.0625 * 13));
}

TEST_CASE("guided likeness is 1 within the sky, 0 across the horizon and falls with the log of the distance ratio",
          "[fast][render][report]") {
  CHECK(render::guided_likeness(-1.0f, -1.0f) == 1.0);
  CHECK(render::guided_likeness(-1.0f, 500.0f) == 0.0);
  CHECK(render::guided_likeness(500.0f, -1.0f) == 0.0);
  CHECK(render::guided_likeness(NAN, 500.0f) == 0.0);  // no distance counts as sky
  CHECK(render::guided_likeness(2000.0f, 2000.0f) == 1.0);
  // exp(-(ln r)^2 / (2 0.3^2)): symmetric in a and b.
  const double r135 = std::exp(-0.5 * std::pow(std::log(1.35) / 0.3, 2));
  CHECK(render::guided_likeness(1000.0f, 1350.0f) == Approx(r135).epsilon(1e-6));
  CHECK(render::guided_likeness(1350.0f, 1000.0f) == Approx(r135).epsilon(1e-6));
  CHECK(render::guided_likeness(1000.0f, 2000.0f) ==
        Approx(std::exp(-0.5 * std::pow(std::log(2.0) / 0.3, 2))).epsilon(1e-6));
}

namespace {

// A 4 x 4 image upsampled to 16 x 16 whose lower rows are ground: sky value 1 above, ground
// value 0 below, the low rows' guide -1 (sky) or 1000 m; the full-size guide says sky above row
// `horizon`, ground (1000 m) from it on.
struct Horizon {
  core::ImageData image{4, 4, 1, {}}, guide{4, 4, 1, {}}, full{16, 16, 1, {}};
  explicit Horizon(int low_horizon, int horizon) {
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 4; ++x) {
        image.pixels.push_back(y < low_horizon ? 1.0f : 0.0f);
        guide.pixels.push_back(y < low_horizon ? -1.0f : 1000.0f);
      }
    for (int y = 0; y < 16; ++y)
      for (int x = 0; x < 16; ++x) full.pixels.push_back(y < horizon ? -1.0f : 1000.0f);
  }
};

}  // namespace

TEST_CASE("guided upsampling keeps the horizon where the full-size guide has it, with no blend across it",
          "[fast][render][report]") {
  // Low rows 0, 1 sky and 2, 3 ground; the full-size horizon at row 7, inside the source cell
  // between low rows 1 and 2 (source y = (y + 1/2) / 4 - 1/2 in [1, 2) for rows 6 to 9).
  const Horizon h(2, 7);
  const auto out = render::upsample_guided(h.image, h.guide, h.full);
  REQUIRE(out.width == 16);
  REQUIRE(out.height == 16);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      INFO("pixel " << x << ", " << y);
      CHECK(out.pixels[y * 16 + x] == (y < 7 ? 1.0f : 0.0f));
    }
  // Bilinear blends rows 6 to 9 (the source cell): what the guide removes.
  const auto blurred = render::upsample_bilinear(h.image, 16, 16);
  CHECK(blurred.pixels[7 * 16] == Approx(0.625f));
  // A full-size sky pixel below the reduced image's horizon (the low rows call it ground) takes
  // the nearest sky pixel of the 4 x 4 about it: row 10 (source y 2.125) finds row 1's sky.
  const Horizon lower(2, 11);
  const auto found = render::upsample_guided(lower.image, lower.guide, lower.full);
  CHECK(found.pixels[10 * 16 + 3] == 1.0f);
}

TEST_CASE("guided upsampling is bilinear where the guide is uniform or missing", "[fast][render][report]") {
  const core::ImageData rgba{2, 2, 4, {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16}};
  const auto bilinear = render::upsample_bilinear(rgba, 4, 4);
  // All sky: every weight is bilinear's.
  const core::ImageData sky_low{2, 2, 1, std::vector<float>(4, -1.0f)};
  const core::ImageData sky_full{4, 4, 1, std::vector<float>(16, -1.0f)};
  const auto sky = render::upsample_guided(rgba, sky_low, sky_full);
  for (size_t k = 0; k < bilinear.pixels.size(); ++k) CHECK(sky.pixels[k] == Approx(bilinear.pixels[k]).epsilon(1e-6));
  // No full-size guide (NaN, as render_clouds leaves pixels away from edges): bilinear even
  // where the reduced image's guide has an edge.
  const core::ImageData edge_low{2, 2, 1, {-1.0f, -1.0f, 800.0f, 800.0f}};
  const core::ImageData none{4, 4, 1, std::vector<float>(16, NAN)};
  const auto plain = render::upsample_guided(rgba, edge_low, none);
  for (size_t k = 0; k < bilinear.pixels.size(); ++k) CHECK(plain.pixels[k] == bilinear.pixels[k]);
  // Guides of the wrong size or channels are refused.
  CHECK_THROWS_AS(render::upsample_guided(rgba, sky_full, sky_full), std::invalid_argument);
}

TEST_CASE("the guide is needed exactly at the full-size pixels whose source cell crosses an edge",
          "[fast][render][report]") {
  // Sky in low rows 0, 1, ground from row 2: only the cells between rows 1 and 2 are edges; the
  // full-size rows whose source y lies in [1, 2) are 6 to 9 (16 / 4 = 4 rows a source row).
  const Horizon h(2, 7);
  const auto pixels = render::guide_pixels(h.guide, 16, 16);
  CHECK(pixels.size() == 4u * 16u);
  for (const auto& p : pixels) CHECK((p.y >= 6 && p.y <= 9));
  // Ground at distances within 35 % (likeness above 1/2) is no edge; at twice the distance it is.
  core::ImageData near_far{2, 2, 1, {1000.0f, 1000.0f, 1300.0f, 1300.0f}};
  CHECK(render::guide_pixels(near_far, 8, 8).empty());
  // Twice as far: the cell between the two rows is an edge; the full-size rows whose source y
  // = (y + 1/2) / 4 - 1/2 (clamped at 0) lies below 1 are 0 to 5.
  near_far.pixels = {1000.0f, 1000.0f, 2000.0f, 2000.0f};
  CHECK(render::guide_pixels(near_far, 8, 8).size() == 6u * 8u);
}

TEST_CASE("the qualities' sweep renders every quality against a reference beyond them at 1280 x 720",
          "[fast][render][report]") {
  for (const bool quick : {false, true}) {
    const auto o = studies::RenderSweepOptions::qualities(quick);
    const auto variants = o.variants();
    REQUIRE(variants.size() == std::size(params::render_qualities));
    for (size_t k = 0; k < variants.size(); ++k) {
      const params::RenderQuality& q = params::render_qualities[k];
      CHECK(variants[k].view_steps == q.view_steps);
      CHECK(variants[k].light_steps == q.light_steps);
      CHECK(variants[k].frames == q.frames);
      CHECK(variants[k].divisor == q.resolution_divisor);
      CHECK(variants[k].view_steps < o.reference_view);
      CHECK(variants[k].light_steps <= o.reference_light);
      CHECK(o.width / variants[k].divisor >= 1);
    }
    CHECK(o.reference_frames == 1);
    CHECK(o.width == (quick ? 64 : 1280));
    CHECK(o.height == (quick ? 36 : 720));
  }
  // Each quality is cheaper and coarser than the next, and final is the library's default.
  for (size_t k = 1; k < std::size(params::render_qualities); ++k) {
    CHECK(params::render_qualities[k].target_display_rms < params::render_qualities[k - 1].target_display_rms);
    CHECK(params::render_qualities[k].resolution_divisor <= params::render_qualities[k - 1].resolution_divisor);
  }
  const regional::Scene library;
  CHECK(library.view_steps == params::final_render_quality().view_steps);
  CHECK(library.resolution_divisor == 1);
  // A step given by name survives the quality; the others take the quality's.
  regional::Scene given;
  regional::give_step(given, params::scene::light_steps, 7);
  given.quality = "draft";
  regional::apply_render_quality(given, "test");
  CHECK(given.light_steps == 7);
  CHECK(given.view_steps == params::render_qualities[0].view_steps);
  CHECK(given.resolution_divisor == params::render_qualities[0].resolution_divisor);
  CHECK_THROWS_AS(regional::give_step(given, params::scene::sky_steps, 4), std::logic_error);
}

TEST_CASE("the qualities' CSV and summary name each quality, its target and whether it meets it",
          "[fast][render][report]") {
  const auto o = studies::RenderSweepOptions::qualities(true);
  std::vector<RenderErrorRow> rows;
  for (const auto& v : o.variants()) rows.push_back(row(v.view_steps, v.light_steps, 10.0, 0.001, v.frames, v.divisor));
  rows[0].display_rms = 0.03;  // draft misses its 0.02
  const std::string csv = studies::render_quality_csv(rows, o);
  std::stringstream lines(csv);
  std::string line;
  std::getline(lines, line);
  CHECK(line ==
        "quality,target_display_rms,view_steps,light_steps,frames,divisor,display_rms,rel_rms,render_ms,clouds_ms,"
        "reference_view_steps,reference_light_steps,reference_frames,width,height");
  int n = 0;
  while (std::getline(lines, line)) {
    const auto fields = fields_of(line);
    REQUIRE(fields.size() == 15u);
    CHECK(fields[0] == std::string(params::render_qualities[n].name));
    ++n;
  }
  CHECK(n == static_cast<int>(rows.size()));
  const std::string md = studies::render_quality_markdown(rows, o);
  CHECK(md.find("| draft |") != std::string::npos);
  CHECK(count_of(md, "| no |") == 1);
  CHECK(count_of(md, "| yes |") == rows.size() - 1);
  rows.pop_back();
  CHECK_THROWS_AS(studies::render_quality_csv(rows, o), std::invalid_argument);
}

TEST_CASE("the render error of an image is measured in display values and relative radiance",
          "[fast][render][report]") {
  // Two pixels: the reference is grey 0.1 and 0.3; the image is off by 0.02 in one channel of one pixel.
  const double exposure = 4.0;
  const core::ImageData reference{2, 1, 4, {0.1f, 0.1f, 0.1f, 1.0f, 0.3f, 0.3f, 0.3f, 0.0f}};
  core::ImageData image = reference;
  image.pixels[4] += 0.02f;
  RenderErrorRow r;
  studies::measure_render_error(image, reference, exposure, {}, r);
  // Relative to the mean radiance 0.2: rms sqrt(0.02^2 / 6) / 0.2, max 0.02 / 0.2.
  CHECK(r.rms_error == Approx(std::sqrt(0.0004 / 6.0) / 0.2).epsilon(1e-5));
  CHECK(r.max_error == Approx(0.1).epsilon(1e-5));
  // Display: the one channel's difference through the PNG's encoding, over 6 values.
  const auto shown = render::tone_map(image, exposure);
  const auto shown_reference = render::tone_map(reference, exposure);
  const double d = shown.pixels[3] - shown_reference.pixels[3];
  CHECK(d > 0.0);
  CHECK(r.display_rms == Approx(std::abs(d) / std::sqrt(6.0)).epsilon(1e-6));
  RenderErrorRow same;
  studies::measure_render_error(reference, reference, exposure, {}, same);
  CHECK(same.display_rms == 0.0);
  CHECK(same.rms_error == 0.0);
  CHECK_THROWS(
      studies::measure_render_error(render::upsample_bilinear(reference, 4, 2), reference, exposure, {}, same));
  // The differing pixel left out (a reference pixel cut short): no error; the other left out:
  // the same difference over 3 values, relative to the mean 0.3.
  RenderErrorRow without_second;
  studies::measure_render_error(image, reference, exposure, {false, true}, without_second);
  CHECK(without_second.display_rms == 0.0);
  CHECK(without_second.max_error == 0.0);
  RenderErrorRow without_first;
  studies::measure_render_error(image, reference, exposure, {true, false}, without_first);
  CHECK(without_first.display_rms == Approx(std::abs(d) / std::sqrt(3.0)).epsilon(1e-6));
  CHECK(without_first.rms_error == Approx(std::sqrt(0.0004 / 3.0) / 0.3).epsilon(1e-5));
}

TEST_CASE("the render error CSV has the documented columns and one line per row", "[fast][render][report]") {
  auto options = studies::RenderSweepOptions::quick();
  const std::string csv = studies::render_error_csv({row(8, 2, 12.5, 0.25, 4, 2), row(48, 6, 80.0, 0.0625)}, options);
  std::stringstream lines(csv);
  std::string line;
  REQUIRE(std::getline(lines, line));
  CHECK(line ==
        "view_steps,light_steps,frames,divisor,clouds_ms,display_rms,rel_rms,rel_max,reference_view_steps,"
        "reference_light_steps,reference_frames,width,height");
  REQUIRE(std::getline(lines, line));
  const auto first = fields_of(line);
  REQUIRE(first.size() == 13);
  CHECK(first[0] == "8");
  CHECK(first[1] == "2");
  CHECK(first[2] == "4");
  CHECK(first[3] == "2");
  CHECK(std::stod(first[4]) == Approx(12.5));
  CHECK(std::stod(first[5]) == Approx(0.25));
  CHECK(std::stod(first[6]) == Approx(0.5));
  CHECK(std::stod(first[7]) == Approx(2.0));
  CHECK(first[8] == "96");
  CHECK(first[9] == "12");
  CHECK(first[10] == "2");
  CHECK(first[11] == "32");
  CHECK(first[12] == "18");
  REQUIRE(std::getline(lines, line));
  CHECK(fields_of(line)[0] == "48");
  CHECK(std::stod(fields_of(line)[5]) == Approx(0.0625));
  CHECK_FALSE(std::getline(lines, line));
  CHECK(studies::render_error_csv({}, options).find('\n') == csv.find('\n'));  // only the header
}

TEST_CASE("the render diagram draws one polyline per light-step count labels view steps and rings the default",
          "[fast][render][report]") {
  const std::string svg = studies::render_error_svg(table, "title & <device>", "subtitle", 48, 6);
  CHECK(count_of(svg, "<polyline") == 4);  // light 2, 4, 6, 12: the one-frame full-resolution rows
  CHECK(count_of(svg, "r='8'") == 1);      // the ring around the default, not around its 4-frame twin
  CHECK(count_of(svg, "<circle") == table.size() - 2 + 1);
  CHECK(svg.find(">48x6 4f</text>") != std::string::npos);  // the other variants, labelled
  CHECK(svg.find(">48x6 1/2</text>") != std::string::npos);
  CHECK(svg.find(">96</text>") != std::string::npos);  // a view-step label
  CHECK(svg.find("12 light steps") != std::string::npos);
  CHECK(svg.find("title &amp; &lt;device&gt;") != std::string::npos);
  CHECK(svg.rfind("</svg>") != std::string::npos);
  // A zero error (the reference's own steps) has no place on a log scale: left out, and said so.
  std::vector<RenderErrorRow> with_zero = table;
  with_zero.push_back(row(384, 24, 900.0, 0.0));
  const std::string svg_zero = studies::render_error_svg(with_zero, "t", "s", 48, 6);
  CHECK(count_of(svg_zero, "<polyline") == 4);
  CHECK(svg_zero.find("zero-error rows not drawn") != std::string::npos);
}

TEST_CASE(
    "the render step choice finds the cheapest within 1.5x the default's error and the most accurate within its time",
    "[fast][render][report]") {
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

TEST_CASE("the render summary section names the defaults their error and the two choices", "[fast][render][report]") {
  const auto options = studies::RenderSweepOptions::full();
  const std::string md =
      studies::render_summary_markdown(table, options, studies::choose_render_steps(table, 48, 6), 48, 6);
  CHECK(md.find("## Render: image error against run time") == 0);
  CHECK(md.find("160 x 90") != std::string::npos);
  CHECK(md.find("192 view x 24 light steps over 4 frames") != std::string::npos);
  CHECK(md.find("Defaults (the final quality, `--quality final`, and the library's): 48 view x 6 light steps, display "
                "rms 0.2000") != std::string::npos);
  CHECK(md.find("Cheapest within 1.5x the default's error (display rms <= 0.3000): 48 view x 6 light steps, 1/2 "
                "resolution, display rms 0.4000") == std::string::npos);  // half resolution is too inaccurate here
  CHECK(md.find("Cheapest within 1.5x the default's error (display rms <= 0.3000): 32 view x 4 light steps, display "
                "rms 0.2900, 60.0 ms (0.60x the default's time)") != std::string::npos);
  CHECK(md.find("Most accurate within the default's time (<= 100.0 ms): 48 view x 12 light steps, display rms 0.1500 "
                "(0.75x the default's error)") != std::string::npos);
  CHECK(md.find("| 48 | 6 | 4 | 1/1 | 400.0 |") != std::string::npos);
  CHECK(count_of(md, "\n| ") == table.size() + 1);  // the header and one table line per row
  CHECK(md.find("left out of every error") == std::string::npos);
  CHECK(md.find("own error") == std::string::npos);
  studies::ReferenceCheck check;
  check.limited = 17;
  check.half_steps = {96, 12, 4, 1, 0.0, 0.00123, 0.00456, 0.01};
  const std::string limited =
      studies::render_summary_markdown(table, options, studies::choose_render_steps(table, 48, 6), 48, 6, check);
  CHECK(limited.find("17 of the reference's 14400 pixels (those that needed 65535 or more") != std::string::npos);
  CHECK(limited.find("half its steps (96 view x 12 light): display rms 0.00123, rel rms 0.00456") != std::string::npos);
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
  // nothing to measure (seeds 2, 8 and 12 have none, and seed 4 since the cyclones keep to the
  // oceans' storm tracks).
  scene.seed = 1;
  studies::RenderSweepOptions options;
  options.view_steps = {6, 12};
  options.light_steps = {3};
  options.extra = {{12, 3, 2, 1}, {12, 3, 1, 2}};
  options.reference_view = 12;
  options.reference_light = 3;
  options.reference_frames = 1;
  options.width = 16;
  options.height = 8;
  int reported = 0;
  studies::ReferenceCheck check;
  check.limited = 99;
  const auto rows = studies::render_error_sweep(
      scene, options, [&](const RenderErrorRow&) { ++reported; }, &check);
  const unsigned limited = check.limited;
  // The reference's own error: rendered at half its steps (6 x 1), it differs, like the 6-step row.
  CHECK(check.half_steps.view_steps == 6);
  CHECK(check.half_steps.light_steps == 1);
  CHECK(check.half_steps.display_rms > 0.0);
  REQUIRE(rows.size() == 4);
  CHECK(reported == 4);
  CHECK(limited == 0);
  CHECK(rows[0].view_steps == 6);
  CHECK(std::isfinite(rows[0].rms_error));
  CHECK(rows[0].rms_error > 0.0);
  CHECK(rows[0].max_error >= rows[0].rms_error);
  CHECK(rows[1].view_steps == 12);
  CHECK(rows[1].rms_error == 0.0);  // rendering is deterministic
  CHECK(rows[1].max_error == 0.0);
  CHECK(rows[1].display_rms == 0.0);
  // The same steps over two frames (another jitter added) and at half resolution differ from it.
  CHECK(rows[2].frames == 2);
  CHECK(rows[2].display_rms > 0.0);
  CHECK(rows[3].divisor == 2);
  CHECK(rows[3].display_rms > 0.0);
  for (const auto& r : rows) {
    CHECK(r.time_ms > 0.0);
    CHECK(r.display_rms <= 1.0);
  }
}
