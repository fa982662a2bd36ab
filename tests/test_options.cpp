// The parameter table and the command-line options made from it.
#include <catch2/catch.hpp>

#include <filesystem>
#include <map>
#include <sstream>
#include <set>
#include <string>

#include "io/scene_files.hpp"
#include "io/weather_files.hpp"
#include "apps/cli/options.hpp"
#include "core/json.hpp"
#include "cli_support.hpp"
#include "params/table.hpp"
#include "params/values.hpp"
#include "regional/scene.hpp"
#include "tolerances.hpp"

using namespace nephele;
using namespace nephele::cli;

namespace {

// A float field written as the shortest decimal that reads back as the same float differs from
// the table's double default by at most half a float ulp, 2^-24 relative (6e-8); 1e-7 leaves a
// factor 1.7.
constexpr double kFloatField = 1e-7;
static_assert(kFloatField >= test::kUlp);

std::string message_of(Options& o, const std::vector<std::string>& args) {
  try {
    o.parse(args);
  } catch (const UsageError& e) {
    return std::string(e.what());
  }
  return std::string();
}

}  // namespace

TEST_CASE("options reject bad values with the option's name and allowed range", "[fast][cli]") {
  int size = 512;
  float step = 0.006f;
  Options o("generate", "test", params::generate);
  o.bind(params::cover::size, &size);
  o.bind(params::cover::step, &step);
  CHECK_THAT(message_of(o, {"--size", "0"}), Catch::Contains("--size") && Catch::Contains("1 to 16384"));
  CHECK_THAT(message_of(o, {"--size", "12.5"}), Catch::Contains("not an integer"));
  CHECK_THAT(message_of(o, {"--step", "nan"}), Catch::Contains("--step") && Catch::Contains("0 to 10"));
  CHECK_THAT(message_of(o, {"--step", "inf"}), Catch::Contains("--step"));
  CHECK_THAT(message_of(o, {"--step", "1e999"}), Catch::Contains("--step"));
  CHECK_THAT(message_of(o, {"--step", "0.1x"}), Catch::Contains("not a number"));
  CHECK_THAT(message_of(o, {"--size"}), Catch::Contains("--size"));
  CHECK_THAT(message_of(o, {"--colour", "red"}), Catch::Contains("--colour"));
}

TEST_CASE("numbers are decimal text only: no hex, no spaces, no trailing characters", "[fast][cli]") {
  int size = 512;
  float step = 0.006f;
  Options o("generate", "test", params::generate);
  o.bind(params::cover::size, &size);
  o.bind(params::cover::step, &step);
  for (const char* bad : {"0x10", " 16", "16 ", "+ 16", "16.", "1e2", "", "16,0"})
    CHECK_THAT(message_of(o, {"--size", bad}), Catch::Contains("--size"));
  for (const char* bad : {"0x1p-3", " 0.5", "0.5 ", "0,5", "nan", "-inf"})
    CHECK_THAT(message_of(o, {"--step", bad}), Catch::Contains("--step"));
  CHECK(size == 512);
  CHECK(step == 0.006f);
}

TEST_CASE("both --name VALUE and --name=VALUE set an option, and given() tells which were set", "[fast][cli]") {
  int size = 512;
  float step = 0.006f;
  std::uint32_t seed = 1;
  Options o("generate", "test", params::generate);
  o.bind(params::cover::size, &size);
  o.bind(params::cover::step, &step);
  o.bind(params::cover::seed, &seed);
  CHECK(message_of(o, {"--size=64", "--step", "0.5"}).empty());
  CHECK(size == 64);
  CHECK(step == 0.5f);
  CHECK(o.given(params::cover::size));
  CHECK(o.given(params::cover::step));
  CHECK_FALSE(o.given(params::cover::seed));
}

TEST_CASE("an option given twice is refused, and a list option takes one value per occurrence", "[fast][cli]") {
  int size = 512;
  Options o("generate", "test", params::generate);
  o.bind(params::cover::size, &size);
  CHECK_THAT(message_of(o, {"--size", "64", "--size=32"}), Catch::Contains("--size"));

  std::vector<std::string> weather;
  Options r("render", "test", params::render);
  r.bind(params::scene::weather, &weather);
  CHECK(message_of(r, {"--weather", "a.json", "--weather=b.json"}).empty());
  CHECK(weather == std::vector<std::string>{"a.json", "b.json"});
}

TEST_CASE("text options with listed words refuse other words, naming the option and the words", "[fast][cli]") {
  std::string integrator;
  Options o("generate", "test", params::generate);
  o.bind(params::cover::integrator, &integrator);
  CHECK_THAT(message_of(o, {"--integrator=midpoint"}),
             Catch::Contains("--integrator") && Catch::Contains("euler, heun, rk4, geodesic, adaptive"));
}

TEST_CASE("a command cannot bind a parameter that the table does not give it", "[fast][cli]") {
  int view_steps = 0;
  Options o("generate", "test", params::generate);
  CHECK_THROWS_AS(o.bind(params::scene::view_steps, &view_steps), std::logic_error);
}

TEST_CASE("help lists every option with its range, unit and default from the table", "[fast][cli]") {
  int size = 512;
  Options o("generate", "summary", params::generate);
  o.bind(params::cover::size, &size);
  CHECK_FALSE(o.parse({"--help"}));
  CHECK_THAT(o.help(),
             Catch::Contains("--size") && Catch::Contains("[1 to 16384, texels]") && Catch::Contains("default 512"));
}

TEST_CASE("the parameter table: defaults inside their ranges, one key per command, options from keys",
          "[fast][params]") {
  const std::vector<unsigned> uses = {
      params::generate,     params::bench_cover,  params::report,      params::render,     params::scene_file,
      params::bench_render, params::noise,        params::bench_noise, params::model,      params::model_file,
      params::bench_model,  params::export_cover, params::viewer,      params::bench_view, params::stats};
  for (const params::Parameter* p : params::all()) {
    INFO(p->key);
    CHECK_FALSE(p->help.empty());
    CHECK(p->uses != 0);
    if ((p->type == params::Type::integer || p->type == params::Type::real) && p->default_text.empty())
      CHECK_NOTHROW(params::check_number(*p, p->default_number, p->option()));
    CHECK(p->option().find('_') == std::string::npos);
  }
  for (unsigned use : uses) {
    std::set<std::string_view> keys;
    for (const params::Parameter* p : params::all())
      if (p->used_by(use)) {
        INFO(p->key);
        CHECK(keys.insert(p->key).second);
      }
  }
}

TEST_CASE("every command's --help lists each option the table gives that command", "[cli]") {
  const std::map<std::vector<std::string>, unsigned> commands = {{{"generate"}, params::generate},
                                                                 {{"bench", "cover"}, params::bench_cover},
                                                                 {{"report"}, params::report},
                                                                 {{"render"}, params::render},
                                                                 {{"bench", "render"}, params::bench_render},
                                                                 {{"noise"}, params::noise},
                                                                 {{"bench", "noise"}, params::bench_noise},
                                                                 {{"model"}, params::model},
                                                                 {{"bench", "model"}, params::bench_model},
                                                                 {{"export"}, params::export_cover},
                                                                 {{"view"}, params::viewer},
                                                                 {{"bench", "view"}, params::bench_view},
                                                                 {{"stats"}, params::stats}};
  for (const auto& [words, use] : commands) {
    std::string arguments;
    for (const auto& w : words) arguments += w + " ";
    const auto result = test::run(arguments + "--help");
    INFO(words.front() << (words.size() > 1 ? " " + words[1] : ""));
    CHECK(result.exit_code == 0);
    for (const params::Parameter* p : params::all())
      if (p->used_by(use)) {
        INFO(p->option());
        CHECK_THAT(result.output, Catch::Contains(p->option() + (p->type == params::Type::flag ? "" : " VALUE")));
      }
  }
}

TEST_CASE("cover.json records every cover parameter of the table under its sidecar path", "[params][cli]") {
  test::TemporaryDirectory out;
  // Adaptive (a steady flow's integrator), so that its tolerance and sub-step limit are recorded too.
  const auto r = test::run("generate --size 8 --iterations 2 --flow steady --integrator adaptive --quiet --out " +
                           out.path.string());
  REQUIRE(r.exit_code == 0);
  const json::Value sidecar = json::parse(test::read_file(out.path / "cover.json"));
  const json::Value& recorded = sidecar.at("parameters");
  for (const params::Parameter* p : params::all()) {
    if (!p->used_by(params::cover_sidecar)) continue;
    const std::string path(p->sidecar_path());
    INFO(path);
    const auto dot = path.find('.');
    const json::Value* value =
        dot == std::string::npos ? recorded.find(path) : recorded.at(path.substr(0, dot)).find(path.substr(dot + 1));
    REQUIRE(value != nullptr);
    // Float fields are written as the shortest decimal that reads back as the same float, so
    // they differ from the table's double default by at most half a float ulp (kFloatField).
    if (p->type == params::Type::text)
      CHECK(value->as_string() == std::string(p == &params::cover::integrator ? "adaptive"
                                              : p == &params::cover::flow     ? "steady"
                                              // auto is recorded as the mode it resolved to
                                              : p == &params::cover::curl_mode ? "spline"
                                                                               : p->default_text));
    else
      CHECK(value->as_number() == Approx(p == &params::cover::size         ? 8
                                         : p == &params::cover::iterations ? 2
                                                                           : p->default_number)
                                      .epsilon(kFloatField));
  }
}

TEST_CASE("render takes --pitch=X, --fov=X and --exposure=X like the spaced form, and options override the scene file",
          "[cli]") {
  test::TemporaryDirectory out(true);
  const std::string scene = (out.path / "scene.json").string();
  std::ofstream(scene) << R"({"view": "gurten", "pitch": 5, "fov": 70, "view_steps": 48, "size": "16x8"})";
  const auto r =
      test::run("render --scene " + scene + " --pitch=30 --fov=40 --exposure=2 --view-steps=2 --light-steps 1 " +
                "--quiet --out " + (out.path / "a.png").string());
  REQUIRE(r.exit_code == 0);
  const json::Value sidecar = json::parse(test::read_file(out.path / "a.json"));
  CHECK(sidecar.at("camera").at("pitch_deg").as_number() == 30);
  CHECK(sidecar.at("camera").at("fov_deg").as_number() == 40);
  CHECK(sidecar.at("exposure").as_number() == 2);
  CHECK(sidecar.at("steps").at("view").as_number() == 2);
}

TEST_CASE("scene files refuse every numeric key just outside the range the table declares, naming the key",
          "[fast][params]") {
  for (const params::Parameter* p : params::all()) {
    if (!p->used_by(params::scene_file) || (p->type != params::Type::integer && p->type != params::Type::real))
      continue;
    const std::string key(p->key);
    const bool nested = p == &params::scene::latitude || p == &params::scene::longitude || p == &params::scene::height;
    for (const double value : {p->min - 1.0, p->max + 1.0}) {
      std::ostringstream text;
      text.precision(17);
      if (nested) {
        std::map<std::string, double> at = {{"latitude", 46.9}, {"longitude", 7.4}, {"height", 860}};
        at[key] = value;
        text << R"({"at": {"latitude": )" << at["latitude"] << R"(, "longitude": )" << at["longitude"]
             << R"(, "height": )" << at["height"] << "}}";
      } else {
        text << "{\"" << key << "\": " << value << "}";
      }
      INFO(text.str());
      try {
        io::parse_scene(text.str(), "scene.json", ".");
        FAIL("accepted");
      } catch (const core::InputError& e) {
        CHECK_THAT(e.what(), Catch::Contains(key));
      }
    }
  }
}

TEST_CASE("a scene file's terrain land cover and surface keep their words and resolve files against its folder",
          "[fast][cli]") {
  const regional::Scene words =
      io::parse_scene(R"({"terrain": "flat", "land_cover": "none", "surface": "etopo5"})", "scenes/a.json", "scenes");
  CHECK(words.terrain == "flat");
  CHECK(words.land_cover == "none");
  CHECK(words.cover_surface == "etopo5");
  const regional::Scene files =
      io::parse_scene(R"({"terrain": "relief.cdf", "land_cover": "/data/maps.json", "surface": "mask.png"})",
                      "scenes/a.json", "scenes");
  CHECK(files.terrain == (std::filesystem::path("scenes") / "relief.cdf").string());
  CHECK(files.land_cover == "/data/maps.json");
  CHECK(files.cover_surface == (std::filesystem::path("scenes") / "mask.png").string());
  // A word of another key is a file here ("flat" is no land/ocean mask).
  CHECK(io::parse_scene(R"({"surface": "flat"})", "scenes/a.json", "scenes").cover_surface ==
        (std::filesystem::path("scenes") / "flat").string());
}

TEST_CASE("a panorama without a size is the 2:1 view sphere, in a scene file as with --panorama", "[fast][cli]") {
  const regional::Scene bare = io::parse_scene(R"({"panorama": true})", "scene.json", ".");
  CHECK(bare.panorama);
  CHECK(bare.width == regional::panorama_width);
  CHECK(bare.height == regional::panorama_height);
  CHECK(bare.width == 2 * bare.height);
  const regional::Scene sized = io::parse_scene(R"({"size": "640x480", "panorama": true})", "scene.json", ".");
  CHECK(sized.panorama);
  CHECK(sized.width == 640);
  CHECK(sized.height == 480);
  regional::Scene flags;
  regional::make_panorama(flags, false);
  CHECK(flags.width == regional::panorama_width);
  CHECK(flags.height == regional::panorama_height);
}
