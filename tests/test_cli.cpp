// The nephele executable end to end.
#include <catch2/catch.hpp>

#include "apps/cli/command_table.hpp"
#include "io/export_presets.hpp"
#include "params/render_quality.hpp"

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "cli_support.hpp"
#include "core/error.hpp"
#include "gl_support.hpp"
#include "files/image_files.hpp"
#include "params/table.hpp"
#include "core/json.hpp"
#include "tolerances.hpp"

namespace fs = std::filesystem;
using namespace nephele;
using test::read_file;
using test::Run;
using test::run;
using test::run_with_environment;
using test::TemporaryDirectory;

namespace {

// The PNG preview against the float equirect: the quantisation round(255 v) / 255 moves a value
// by at most half a step, 0.5 / 255; the float products and the read-back division add a few
// roundings of values <= 1 (2^-24 each): 1e-6 (16.8 of them) covers those with room.
constexpr double kQuantisationStep = 0.5 / 255;
constexpr double kQuantisationRounding = 1e-6;
static_assert(kQuantisationRounding >= 4 * test::kUlp);

}  // namespace

TEST_CASE("generate writes every output readable with the right sizes and a valid sidecar", "[cli]") {
  TemporaryDirectory out;
  const Run r =
      run("generate --size 8 --iterations 5 --seed 42 --coverage 0.5 --profile flat --out " + out.path.string());
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  for (const char* face : {"px", "nx", "py", "ny", "pz", "nz"}) {
    const auto image = files::read_image(out.path / (std::string("cover_") + face + ".exr"));
    CHECK(image.width == 8);
    CHECK(image.height == 8);
    // Y, cloud_top, tau (OpenEXR's order by name): coverage in [0, 1], the others >= 0.
    REQUIRE(image.channels == 3);
    for (size_t k = 0; k < image.pixels.size(); ++k) {
      REQUIRE(image.pixels[k] >= 0.0f);
      if (k % 3 == 0) REQUIRE(image.pixels[k] <= 1.0f);
    }
  }
  const auto equirect = files::read_image(out.path / "cover_equirect.exr");
  CHECK(equirect.width == 32);
  CHECK(equirect.height == 16);
  const auto preview = files::read_image(out.path / "cover_equirect.png");
  CHECK(preview.width == 32);
  CHECK(preview.height == 16);
  // The preview is the equirect quantised linearly: round(255 v) / 255.
  for (size_t k = 0; k < preview.pixels.size(); ++k)
    REQUIRE(
        preview.pixels[k] ==
        Approx(equirect.pixels[k * equirect.channels]).epsilon(0).margin(kQuantisationStep + kQuantisationRounding));

  const json::Value sidecar = json::parse(read_file(out.path / "cover.json"));
  CHECK(sidecar.at("parameters").at("seed").as_number() == 42);
  CHECK(sidecar.at("parameters").at("size").as_number() == 8);
  CHECK(sidecar.at("parameters").at("step").as_number() == params::cover::step.default_number);
  CHECK_FALSE(sidecar.at("version").as_string().empty());
  const auto& result = sidecar.at("result");
  CHECK(std::abs(result.at("cloud_fraction").as_number() - 0.5) <= result.at("cloud_fraction_tolerance").as_number());
  for (const char* pass : {"curl", "warp", "density", "coverage", "equirect"})
    CHECK(sidecar.at("timings_ms").at(pass).is_number());
  // The moving flow (the default) makes no identity map: its passes compute the directions.
  CHECK(sidecar.at("timings_ms").find("identity") == nullptr);
  CHECK(sidecar.at("conventions").at("world_axes").is_string());
  // No temporary directories are left behind, in --out or next to it.
  for (const fs::path& place : {out.path, out.path.parent_path()})
    for (const auto& entry : fs::directory_iterator(place))
      CHECK(entry.path().filename().string().rfind(".nephele-" + out.path.filename().string() + "-", 0) != 0);
}

TEST_CASE("generate writes only the images --files names and does not resample without an equirect", "[cli]") {
  TemporaryDirectory out;
  const Run r = run("generate --size 8 --iterations 5 --files faces --out " + out.path.string());
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK(fs::exists(out.path / "cover_px.exr"));
  CHECK_FALSE(fs::exists(out.path / "cover_equirect.exr"));
  CHECK_FALSE(fs::exists(out.path / "cover_equirect.png"));
  const json::Value sidecar = json::parse(read_file(out.path / "cover.json"));
  CHECK(sidecar.at("timings_ms").find("equirect") == nullptr);
  CHECK(sidecar.at("files").find("equirect") == nullptr);
  CHECK(sidecar.at("files").at("faces").as_array().size() == 6);

  TemporaryDirectory png_only;
  REQUIRE(run("generate --size 8 --iterations 5 --files png --out " + png_only.path.string()).exit_code == 0);
  CHECK(fs::exists(png_only.path / "cover_equirect.png"));
  CHECK_FALSE(fs::exists(png_only.path / "cover_px.exr"));
  const json::Value png_sidecar = json::parse(read_file(png_only.path / "cover.json"));
  CHECK(png_sidecar.at("timings_ms").find("read_faces") == nullptr);
}

TEST_CASE("generate --precision half writes the float faces rounded to half, with any compression", "[cli]") {
  TemporaryDirectory full, half;
  REQUIRE(run("generate --size 16 --iterations 5 --files faces,equirect --out " + full.path.string()).exit_code == 0);
  const Run r =
      run("generate --size 16 --iterations 5 --files faces,equirect --precision half --exr-compression piz --out " +
          half.path.string());
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  // Half keeps 11 significant bits: relative rounding error at most 2^-11 (values in [0, 1]
  // below 2^-14 are subnormal, absolute error at most 2^-25).
  const double relative = std::ldexp(1.0, -11), absolute = std::ldexp(1.0, -25);
  for (const char* name : {"cover_px.exr", "cover_nz.exr", "cover_equirect.exr"}) {
    const auto a = files::read_image(full.path / name);
    const auto b = files::read_image(half.path / name);
    REQUIRE(a.pixels.size() == b.pixels.size());
    for (size_t k = 0; k < a.pixels.size(); ++k)
      REQUIRE(std::abs(b.pixels[k] - a.pixels[k]) <= relative * std::abs(a.pixels[k]) + absolute);
  }
  const json::Value sidecar = json::parse(read_file(half.path / "cover.json"));
  CHECK(sidecar.at("files").at("exr_precision").as_string() == "half");
  CHECK(sidecar.at("files").at("exr_compression").as_string() == "piz");
  for (const auto* arguments :
       {"--files faces,faces", "--files", "--files maps", "--precision double", "--exr-compression lzma"}) {
    const Run bad = run(std::string("generate --size 8 ") + arguments + " --out " + half.path.string() + "/x");
    INFO(arguments << ": " << bad.output);
    CHECK(bad.exit_code == 2);
  }
}

TEST_CASE("bad input exits with code 2 naming the option and writes nothing", "[cli]") {
  TemporaryDirectory out;
  const std::string dir = " --out " + out.path.string();
  const std::pair<std::string, std::string> cases[] = {
      {"generate --size 0" + dir, "--size"},
      {"generate --size 100000" + dir, "--size"},
      {"generate --step nan" + dir, "--step"},
      {"generate --coverage 1.5" + dir, "--coverage"},
      {"generate --seed -1" + dir, "--seed"},
      {"generate --iterations 2.5" + dir, "--iterations"},
      {"generate --density-frequency 1000 --density-octaves 6" + dir, "--density-frequency"},
      {"generate --colour red" + dir, "--colour"},
      {"generate --flow drifting" + dir, "--flow"},
      {"generate --flow moving --time 2026-13-01T00:00Z" + dir, "--time"},
      {"generate --flow steady --time 2026-06-21T00:00Z" + dir, "--time"},
      {"generate --flow moving --integrator euler" + dir, "--integrator"},
      {"generate --flow moving --curl-mode sampled" + dir, "--curl-mode"},
      {"generate --flow steady --sequence 3" + dir, "--sequence"},
      {"generate --flow steady --loop 24" + dir, "--loop"},
      {"generate --flow moving --interval 2" + dir, "--interval"},
      {"generate --flow moving --sequence 3 --interval 0" + dir, "--interval"},
      {"frobnicate", "frobnicate"},
  };
  std::vector<std::pair<std::string, std::string>> all(std::begin(cases), std::end(cases));
  for (const auto& [arguments, option] : all) {
    const Run r = run(arguments);
    INFO(arguments << "\n" << r.output);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Catch::Contains(option));
    CHECK_FALSE(fs::exists(out.path));
  }
}

TEST_CASE("generate --sequence writes each frame as a whole cover set with a listing and an animated preview",
          "[cli][moving]") {
  TemporaryDirectory out;
  const Run r =
      run("generate --flow moving --size 16 --curl-size 16 --sequence 3 --interval 1.5 --time "
          "2026-06-21T12:00Z --files equirect,png --out " +
          out.path.string());
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const json::Value listing = json::parse(read_file(out.path / "sequence.json"));
  const auto& frames = listing.at("frames").as_array();
  REQUIRE(frames.size() == 3);
  const char* times[] = {"2026-06-21T12:00:00Z", "2026-06-21T13:30:00Z", "2026-06-21T15:00:00Z"};
  for (size_t k = 0; k < frames.size(); ++k) {
    const std::string folder = frames[k].at("folder").as_string();
    CHECK(folder == "frame_000" + std::to_string(k));
    CHECK(frames[k].at("time").as_string() == times[k]);
    // Each frame is a cover set of its own, its sidecar naming the flow and its time.
    const json::Value sidecar = json::parse(read_file(out.path / folder / "cover.json"));
    CHECK(sidecar.at("parameters").at("flow").as_string() == "moving");
    CHECK(sidecar.at("parameters").at("time").as_string() == times[k]);
    CHECK(fs::exists(out.path / folder / "cover_equirect.png"));
  }
  const files::ImageHeader gif = files::read_image_header(out.path / "sequence.gif");
  CHECK(gif.width == 64);
  CHECK(gif.height == 32);
}

TEST_CASE("bench cover names the curl each size runs with under curl mode auto", "[cli][moving]") {
  // The moving flow's defaults: procedural while 12 size^2 < 7 x 64^2 (up to 48 per face), then
  // a spline of max(64, size / 2) nodes, at most 128 at the default step (cover::resolved_curl).
  const Run r = run("bench cover --sizes 8,64 --repeat 1");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.output, Catch::Contains("curl auto (8: procedural, 64: spline of 64 nodes)"));
  // The first run, which compiles the shaders, is its own column, outside the medians.
  CHECK_THAT(r.output, Catch::Contains("median of 1 runs after a first"));
  CHECK_THAT(r.output, Catch::Contains("Mtexel/s |     first      wall"));
}

TEST_CASE("stats on a sequence finds the clouds moving with the flow's trade winds", "[cli][moving]") {
  TemporaryDirectory out;
  const std::string dir = out.path.string();
  // Without the ITCZ (--itcz 0): its line is tied to the map (its band drawn at the texel, its
  // systems present by their places' latitude against the line's, which the monsoons move over
  // land; docs/climate.md), so the cloud near it moves slower than the air (at 5 N, 3.0 m/s
  // against the flow's 4.6 at this size). The rest of the cloud is carried by the flow.
  REQUIRE(run("generate --flow moving --size 64 --curl-size 64 --sequence 4 --interval 6 --files equirect --quiet "
              "--itcz 0 --out " +
              dir)
              .exit_code == 0);
  const Run r = run("stats " + dir + " --out " + dir + "/motion");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const json::Value motion = json::parse(read_file(out.path / "motion" / "motion.json"));
  CHECK(fs::exists(out.path / "motion" / "motion.svg"));
  // Near the equator the flow's trades blow at about -5 m/s. One pixel of the 256-wide equirect
  // map over 6 hours is 2 pi / 256 x 6371 km / 21600 s = 7.2 m/s; the parabola through the
  // correlation's peak finds the shift to about a fifth of a pixel while the pattern keeps most
  // of its correlation (0.77 after 6 h): 1.5 m/s.
  int trades = 0;
  for (const json::Value& band : motion.at("zonal_speed_by_band").as_array()) {
    const double latitude = band.at("latitude_deg").as_number();
    if (std::abs(latitude) > 10) continue;
    ++trades;
    const double cloud = band.at("cloud_speed_ms").as_number(), flow = band.at("flow_speed_ms").as_number();
    INFO("latitude " << latitude << ": clouds " << cloud << " m/s, flow " << flow << " m/s");
    CHECK(flow < -3);
    CHECK(std::abs(cloud - flow) <= 1.5);
  }
  CHECK(trades == 2);
  // The cover decorrelates as it moves and renews: 1 at lag 0, then falling.
  const auto& correlation = motion.at("correlation_by_lag").as_array();
  REQUIRE(correlation.size() == 4);
  CHECK(correlation[0].as_number() == Approx(1.0).margin(1e-9));
  for (size_t k = 1; k < correlation.size(); ++k) CHECK(correlation[k].as_number() < correlation[k - 1].as_number());
  // Following the clouds (each band shifted by its measured drift) the pattern keeps more of its
  // correlation than at a fixed place, where it also passes by: the same at lag 0, higher at
  // every later lag.
  const auto& comoving = motion.at("comoving_correlation_by_lag").as_array();
  REQUIRE(comoving.size() == 4);
  CHECK(comoving[0].as_number() == Approx(1.0).margin(1e-9));
  for (size_t k = 1; k < comoving.size(); ++k) CHECK(comoving[k].as_number() > correlation[k].as_number());
}

TEST_CASE("an output path that is a file is refused and left intact", "[cli]") {
  TemporaryDirectory out;
  fs::create_directories(out.path);
  const fs::path file = out.path / "not_a_directory";
  std::ofstream(file) << "precious";
  const Run r = run("generate --size 4 --out " + file.string());
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.output, Catch::Contains("--out"));
  CHECK(read_file(file) == "precious");
}

TEST_CASE("a failed run leaves earlier outputs untouched", "[cli]") {
  TemporaryDirectory out;
  REQUIRE(run("generate --size 4 --iterations 2 --out " + out.path.string()).exit_code == 0);
  const std::string before = read_file(out.path / "cover_px.exr");
  CHECK(run("generate --size 4 --coverage 7 --out " + out.path.string()).exit_code == 2);
  CHECK(read_file(out.path / "cover_px.exr") == before);
}

TEST_CASE("help and version exit with code 0", "[cli]") {
  const Run help = run("generate --help");
  CHECK(help.exit_code == 0);
  CHECK_THAT(help.output, Catch::Contains("--size") && Catch::Contains("[1 to 16384"));
  CHECK(run("--help").exit_code == 0);
  CHECK(run("--version").exit_code == 0);
  CHECK(run("").exit_code == 2);
}

TEST_CASE("without an OpenGL 4.5 context generate exits with code 3 naming what was tried", "[cli]") {
  TemporaryDirectory out;
  // Restricting EGL to a platform that cannot give a context here: on machines without a GPU
  // the device platform has no hardware device. Where a GPU is present the run succeeds.
  const Run r = run_with_environment("NEPHELE_EGL_PLATFORM=device",
                                     "generate --size 4 --iterations 1 --out " + out.path.string());
  INFO(r.output);
  if (r.exit_code == 0) {
    WARN("a hardware EGL device is present; the no-context path is not exercised here");
    return;
  }
  CHECK(r.exit_code == 3);
  CHECK_THAT(r.output, Catch::Contains("no headless OpenGL 4.5 core context") && Catch::Contains("device"));
  CHECK_FALSE(fs::exists(out.path));
  const Run bad = run_with_environment("NEPHELE_EGL_PLATFORM=vulkan", "generate --size 4 --out " + out.path.string());
  CHECK(bad.exit_code == 3);
  CHECK_THAT(bad.output, Catch::Contains("NEPHELE_EGL_PLATFORM") && Catch::Contains("surfaceless"));
}

TEST_CASE("render writes a tone-mapped PNG and a sidecar listing the passes", "[cli][render]") {
  TemporaryDirectory out;
  const std::string png = (out.path / "view.png").string();
  const Run r =
      run("render --view bantiger --size 24x12 --view-steps 6 --light-steps 2 --time 2026-06-21T15:00Z "
          "--weather " +
          std::string(NEPHELE_SOURCE_DIR) + "/scenes/weather/bern-summer.json --out " + png);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const auto image = files::read_image(png);
  CHECK(image.width == 24);
  CHECK(image.height == 12);
  CHECK(image.channels == 3);
  const json::Value sidecar = json::parse(read_file(out.path / "view.json"));
  CHECK(sidecar.at("weather_source").as_string() == "stations");
  CHECK(sidecar.at("passes").as_array().size() >= 2);
  // The default quality chose the frames and the divisor; the steps typed override it.
  const params::RenderQuality& quality = params::default_render_quality();
  const json::Value& chosen = sidecar.at("quality");
  CHECK(chosen.at("name").as_string() == "default");
  CHECK(chosen.at("target_display_rms").as_number() == quality.target_display_rms);
  const auto names = [](const json::Value& list) {
    std::vector<std::string> out;
    for (const auto& v : list.as_array()) out.push_back(v.as_string());
    return out;
  };
  CHECK(names(chosen.at("given")) == std::vector<std::string>{"view_steps", "light_steps"});
  CHECK(names(chosen.at("from_quality")) == std::vector<std::string>{"frames", "resolution_divisor"});
  CHECK(sidecar.at("steps").at("view").as_number() == 6);
  CHECK(sidecar.at("steps").at("light").as_number() == 2);
  CHECK(sidecar.at("steps").at("resolution_divisor").as_number() == quality.resolution_divisor);
}

TEST_CASE("render --quality final renders at full resolution with the final steps unless a step is given",
          "[cli][render]") {
  TemporaryDirectory out;
  const std::string png = (out.path / "view.png").string();
  const Run r = run("render --view gurten --size 16x8 --quality final --light-steps 3 --terrain flat --out " + png);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const json::Value sidecar = json::parse(read_file(out.path / "view.json"));
  const params::RenderQuality& final_quality = params::final_render_quality();
  CHECK(sidecar.at("quality").at("name").as_string() == "final");
  CHECK(sidecar.at("steps").at("view").as_number() == final_quality.view_steps);
  CHECK(sidecar.at("steps").at("light").as_number() == 3);
  CHECK(sidecar.at("steps").at("resolution_divisor").as_number() == 1);
  // The scene's cover, made with the default land/ocean mask, as generate would make it again.
  CHECK(sidecar.at("global_cover").at("surface").as_string() == "etopo5");
}

TEST_CASE("render rejects bad input with code 2 naming the key or option", "[cli][render]") {
  TemporaryDirectory out;
  fs::create_directories(out.path);
  const fs::path scene = out.path / "scene.json";
  std::ofstream(scene) << R"({"view": "gurten", "colour": "red", "outputs": ["a.png"]})";
  const fs::path typed = out.path / "typed.json";
  std::ofstream(typed) << R"({"view": "gurten", "fov": "wide", "outputs": ["a.png"]})";
  const fs::path broken_weather = out.path / "weather.json";
  std::ofstream(broken_weather)
      << R"({"latitude": 47, "longitude": 7, "hourly": {"time": ["2026-06-21T00:00"], "cloud_cover": [50]}})";
  const fs::path bad_cape = out.path / "cape.json";
  std::ofstream(bad_cape)
      << R"({"latitude": 47, "longitude": 7, "hourly": {"time": ["2026-06-21T00:00"], "cloud_cover": [50],
    "cloud_cover_low": [50], "cloud_cover_mid": [0], "cloud_cover_high": [0], "cape": [-5]}})";
  const std::string weather = std::string(NEPHELE_SOURCE_DIR) + "/scenes/weather/bern-summer.json";
  const std::string png = " --out " + (out.path / "x.png").string();
  const std::pair<std::string, std::string> cases[] = {
      {"render --scene " + scene.string() + " --out " + out.path.string(), "'colour'"},
      {"render --scene " + typed.string() + " --out " + out.path.string(), "'fov'"},
      {"render --view matterhorn" + png, "matterhorn"},
      {"render --view gurten --size 12by7" + png, "--size"},
      {"render --view gurten --time yesterday" + png, "time"},
      {"render --view gurten --weather " + weather + " --time 2027-01-01T00:00Z" + png, "outside the file's range"},
      {"render --view gurten --weather " + broken_weather.string() + png, "hourly.cloud_cover_low"},
      {"render --view gurten --weather " + bad_cape.string() + png,
       "hourly.cape[0]: -5 is outside the allowed range 0 to 10000"},
      {"render --view gurten --out " + (out.path / "x.jpg").string(), ".png or .exr"},
      {"render --view gurten --fov 200" + png, "--fov"},
      {"render --view gurten --quality best" + png, "--quality"},
      {"render --scene " + (out.path / "quality.json").string() + " --out " + out.path.string(),
       "'quality': 'best' is not a quality (allowed: draft|default|final)"},
      {"render --view gurten --surface " + (out.path / "absent.png").string() + png, "--surface"},
      {"render --scene " + (out.path / "surface.json").string() + " --out " + out.path.string(),
       "surface.json: 'surface'"},
      {"render --view orbit --cover " + out.path.string() + " --surface none" + png, "--surface"},
  };
  std::ofstream(out.path / "surface.json") << R"({"view": "gurten", "surface": "absent.png", "outputs": ["a.png"]})";
  std::ofstream(out.path / "quality.json") << R"({"view": "gurten", "quality": "best", "outputs": ["a.png"]})";
  for (const auto& [arguments, expected] : cases) {
    const Run r = run(arguments);
    INFO(arguments << "\n" << r.output);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Catch::Contains(expected));
    CHECK_FALSE(fs::exists(out.path / "x.png"));
  }
}

TEST_CASE("nephele's usage lists every command of the table and every export preset, and dispatch finds each",
          "[fast][cli]") {
  const std::string text = cli::usage();
  for (const cli::Command& c : cli::commands()) {
    CHECK_THAT(text, Catch::Contains(std::string("  ") + c.name + " "));
    CHECK(cli::find_command(c.name) == &c);
    CHECK(c.run != nullptr);
  }
  for (const io::ExportPreset& p : io::export_presets()) CHECK_THAT(text, Catch::Contains(p.name));
  CHECK(cli::find_command("frobnicate") == nullptr);
}
