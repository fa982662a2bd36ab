// Bad input outside the option parser: files (size, kind, UTF-8, JSON keys), times, sizes and
// lists, each refused with exit code 2 and a message naming what the user typed.
#include <catch2/catch.hpp>

#include <sys/stat.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "case_tags.hpp"
#include "io/scene_files.hpp"
#include "io/weather_files.hpp"
#include "cover/cover_limits.hpp"
#include "render/render_limits.hpp"
#include "apps/cli/options.hpp"
#include "cli_support.hpp"
#include "core/input_file.hpp"
#include "core/number_text.hpp"
#include "core/json.hpp"
#include "core/memory.hpp"
#include "cover/equirect.hpp"
#include "gl_support.hpp"
#include "gpu/limits.hpp"
#include "noise/noise_spec.hpp"
#include "regional/scene.hpp"
#include "regional/weather.hpp"

namespace fs = std::filesystem;
using namespace nephele;
using test::Run;
using test::run_without_gl;
using test::TemporaryDirectory;

namespace {

template <class Error, class Work>
std::string error_of(Work work) {
  try {
    work();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

std::string weather_with_times(const std::string& times) {
  return R"({"latitude": 46.95, "longitude": 7.45, "hourly": {"time": )" + times +
         R"(, "cloud_cover": [50], "cloud_cover_low": [10], "cloud_cover_mid": [0], "cloud_cover_high": [5]}})";
}

}  // namespace

TEST_CASE("render refuses an impossible --time naming --time before any GL work", "[bad-input][cli]") {
  TemporaryDirectory out;
  for (const char* time : {"2024-02-31T12:00Z", "2024-06-01T12:nanZ"}) {
    const Run r =
        run_without_gl(std::string("render --view gurten --time ") + time + " --out " + (out.path / "x.png").string());
    INFO(r.output);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Catch::StartsWith("nephele: --time: ") && Catch::Contains(time));
  }
  CHECK_FALSE(fs::exists(out.path));
}

TEST_CASE("a bad or empty time in a weather file names the file and the field", "[fast][bad-input][weather]") {
  for (const char* times : {R"(["2024-02-31T12:00"])", R"([""])", R"(["2024-06-01T12:00+01:00"])"}) {
    INFO(times);
    const std::string message =
        error_of<regional::WeatherError>([&] { io::parse_weather(weather_with_times(times), "station.json"); });
    CHECK_THAT(message, Catch::StartsWith("station.json: hourly.time[0]: "));
  }
}

TEST_CASE("equirect tiles cover the map exactly once and stay within the tile edge", "[fast][bad-input][equirect]") {
  const int width = 4 * 4097, height = 2 * 4097, edge = 4096;  // a cover size past 4096: the map is 16388 wide
  std::vector<std::uint8_t> covered(static_cast<size_t>(width) * height, 0);
  for (const auto& t : cover::equirect_tiles(width, height, edge)) {
    REQUIRE(t.width >= 1);
    REQUIRE(t.height >= 1);
    REQUIRE(t.width <= edge);
    REQUIRE(t.height <= edge);
    for (int y = t.y; y < t.y + t.height; ++y)
      for (int x = t.x; x < t.x + t.width; ++x) ++covered[static_cast<size_t>(y) * width + x];
  }
  CHECK(std::all_of(covered.begin(), covered.end(), [](std::uint8_t c) { return c == 1; }));
}

TEST_CASE("the equirect export gives the same bits in tiles as in one piece", "[bad-input][equirect]") {
  test::test_context();
  const int size = 16, width = 4 * size, height = 2 * size;
  std::vector<float> texels(6 * size * size);
  for (size_t k = 0; k < texels.size(); ++k) texels[k] = static_cast<float>((k * 7919) % 1000) / 999.0f;
  gpu::Texture cube = gpu::Texture::cube(size, GL_R32F);
  cube.write(texels);
  const std::vector<float> whole = cover::equirect_from_cube(cube, width, height, width);
  // Tiles of 7 x 7 leave ragged tiles at the right and bottom edges (64 = 9 * 7 + 1, 32 = 4 * 7 + 4).
  const std::vector<float> tiled = cover::equirect_from_cube(cube, width, height, 7);
  REQUIRE(whole.size() == tiled.size());
  CHECK(std::memcmp(whole.data(), tiled.data(), whole.size() * sizeof(float)) == 0);
}

TEST_CASE("an equirect map wider than the driver's texture limit is exported", "[bad-input][equirect]") {
  test::test_context();
  GLint max_side = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_side);
  const int size = 4, width = max_side + 8, height = 2;
  gpu::Texture cube = gpu::Texture::cube(size, GL_R32F);
  cube.write(std::vector<float>(6 * size * size, 0.25f));
  const std::vector<float> map = cover::equirect_from_cube(cube, width, height);
  REQUIRE(map.size() == static_cast<size_t>(width) * height);
  // Bilinear weights sum to one, so a constant cube gives that constant everywhere, bit for bit.
  CHECK(std::all_of(map.begin(), map.end(), [](float v) { return v == 0.25f; }));
}

TEST_CASE("the host memory probe reads MemAvailable from /proc/meminfo", "[fast][bad-input]") {
  if (!fs::exists("/proc/meminfo")) {
    test::skip_case("no /proc/meminfo");
    return;
  }
  CHECK(core::host_memory_available_bytes() > 0.0);
}

TEST_CASE("image sizes are strict WIDTHxHEIGHT integers within 1 to 16384", "[fast][bad-input][scene]") {
  int w = 0, h = 0;
  regional::parse_size("1280x720", w, h, "--size");
  CHECK(w == 1280);
  CHECK(h == 720);
  for (const char* text : {"4294967297x1", "1x4294967297", "99999999999999999999x1", " 12x7", "+12x7", "12x 7", "12x7 ",
                           "-12x7", "12x-7", "1.5x2", "0x10", "12x0", "16385x1", "x7", "12x", "12by7"}) {
    INFO("'" << text << "'");
    CHECK_THAT(error_of<regional::SceneError>([&] { regional::parse_size(text, w, h, "--size"); }),
               Catch::StartsWith("--size: "));
  }
  CHECK(core::parse_integer("-42") == -42);
  CHECK_FALSE(core::parse_integer("0x10"));
  CHECK_FALSE(core::parse_integer("9223372036854775808"));  // one past the largest long long
}

TEST_CASE("render sizes beyond the driver's image limit are refused naming the option", "[bad-input][render]") {
  gpu::EglContext& context = test::test_context();
  GLint max_side = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_side);
  CHECK_THAT(error_of<core::InputError>([&] { render::check_render_fits(context, max_side + 1, 1, "--size"); }),
             Catch::StartsWith("--size: "));
  CHECK_NOTHROW(render::check_render_fits(context, 64, 32, "--size"));
  if (context.is_software()) {
    // 16384^2 RGBA32F is 4 GiB, past llvmpipe's largest texture: refused, not a failure (exit 1).
    TemporaryDirectory out;
    const Run r = test::run("render --view gurten --size 16384x16384 --out " + (out.path / "x.png").string());
    INFO(r.output);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Catch::StartsWith("nephele: --size: 16384x16384"));
  }
}

TEST_CASE("a scene file that is not a regular file or is too large is refused naming it", "[fast][bad-input][scene]") {
  CHECK_THAT(error_of<regional::SceneError>([] { io::read_scene_file("/dev/zero"); }),
             Catch::StartsWith("/dev/zero: not a regular file"));
  TemporaryDirectory dir(true);
  CHECK_THAT(error_of<regional::SceneError>([&] { io::read_scene_file(dir.path.string()); }),
             Catch::StartsWith(dir.path.string() + ": "));
  const fs::path big = dir.path / "big.json";
  std::ofstream(big) << std::string(17, ' ');
  CHECK_THAT(error_of<core::InputFileError>([&] { core::read_input_file(big.string(), 16); }),
             Catch::StartsWith(big.string() + ": 17 bytes is too large"));
  CHECK(core::read_input_file(big.string(), 17).size() == 17);
  const fs::path fifo = dir.path / "fifo.json";
  REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
  CHECK_THAT(error_of<regional::WeatherError>([&] { io::read_weather_file(fifo.string()); }),
             Catch::StartsWith(fifo.string() + ": not a regular file"));
}

TEST_CASE("invalid UTF-8 in scene and weather files is refused naming the file and byte offset",
          "[fast][bad-input][json]") {
  // The prefix {"description": " is 17 bytes: the value's bytes start at offset 17.
  const std::pair<std::string, size_t> cases[] = {
      {"\xff", 17},              // never a UTF-8 byte
      {"\xc0\xaf", 17},          // overlong '/'
      {"\xed\xa0\x80", 18},      // a UTF-16 surrogate
      {"\xf4\x90\x80\x80", 18},  // past U+10FFFF
      {"ab\x80", 19},            // a lone continuation byte
      {"\xe2\x82", 19},          // cut short by the closing quote
  };
  for (const auto& [bytes, offset] : cases) {
    const std::string text = "{\"description\": \"" + bytes + "\"}";
    INFO("offset " << offset);
    CHECK_THAT(error_of<regional::SceneError>([&] { io::parse_scene(text, "scene.json", "."); }),
               Catch::StartsWith("scene.json: ") && Catch::Contains("byte offset " + std::to_string(offset)));
  }
  CHECK_THAT(error_of<regional::WeatherError>([] { io::parse_weather("{\"latitude\": \"\xfe\"}", "w.json"); }),
             Catch::StartsWith("w.json: ") && Catch::Contains("byte offset 14"));
  // Valid two, three and four byte sequences pass: e acute, euro sign, an emoji.
  CHECK(json::parse("\"\xc3\xa9\xe2\x82\xac\xf0\x9f\x98\x80\"").as_string() == "\xc3\xa9\xe2\x82\xac\xf0\x9f\x98\x80");
}

TEST_CASE("a duplicate key among many is found and named", "[fast][bad-input][json]") {
  // 100000 keys: the hash set finds the repeat of the first at the end (the speed is in the
  // commit message: a per-key scan took 23.5 s for 160k keys).
  std::string text = "{";
  for (int k = 0; k < 100000; ++k) text += "\"k" + std::to_string(k) + "\": 0,";
  const json::Value whole = json::parse(text.substr(0, text.size() - 1) + "}");
  CHECK(whole.as_object().size() == 100000);
  CHECK_THAT(error_of<json::ParseError>([&] { json::parse(text + "\"k0\": 1}"); }),
             Catch::Contains("duplicate key 'k0'"));
}

TEST_CASE("noise cell counts along long axes do not overflow", "[fast][bad-input][noise]") {
  // 65536 cells along a 65536 wide texture give 65536 * 65536 / 65536 cells along the height:
  // the product 2^32 wrapped to 0 in int.
  noise::TextureSpec spec;
  spec.width = spec.height = spec.depth = 1 << 16;
  spec.channels[0].cells = 1 << 16;
  spec.channels[0].octaves = 1;
  CHECK_NOTHROW(noise::validate(spec));
  const auto params = noise::channel_params(spec, 0);
  CHECK(params.fbm.period.x == 1 << 16);
  CHECK(params.fbm.period.y == 1 << 16);
  CHECK(params.fbm.period.z == 1 << 16);
}

TEST_CASE("render messages name the option typed or the scene file's key", "[bad-input][cli]") {
  TemporaryDirectory dir(true);
  const fs::path scene = dir.path / "scene.json";
  std::ofstream(scene) << R"({"view": "nowhere", "outputs": ["a.png"]})";
  const fs::path good = dir.path / "good.json";
  std::ofstream(good) << R"({"view": "gurten", "time": "2024-02-31T12:00Z", "outputs": ["a.png"]})";
  const fs::path fine = dir.path / "fine.json";
  std::ofstream(fine) << R"({"view": "gurten", "time": "2024-02-28T12:00Z", "outputs": ["a.png"]})";
  const fs::path drifting = dir.path / "drifting.json";
  std::ofstream(drifting) << R"({"view": "gurten", "flow": "drifting", "outputs": ["a.png"]})";
  const std::string png = " --out " + (dir.path / "x.png").string();
  const std::pair<std::string, std::string> cases[] = {
      {"render --view gurten --flow drifting" + png, "nephele: --flow: 'drifting'"},
      {"render --scene " + drifting.string() + " --out " + dir.path.string(),
       "nephele: " + drifting.string() + ": 'flow': 'drifting' is not a flow (allowed: steady, moving)"},
      // The orbit view's cover is either read (--cover) or made with a flow, not both.
      {"render --view orbit --flow steady --cover " + dir.path.string() + png, "nephele: --flow: "},
      {"render --view nowhere" + png, "nephele: --view: 'nowhere'"},
      {"render --scene " + scene.string() + " --out " + dir.path.string(),
       "nephele: " + scene.string() + ": 'view': 'nowhere'"},
      {"render --scene " + good.string() + " --out " + dir.path.string(), "nephele: " + good.string() + ": 'time': "},
      // A bad value of an option that overrides a good file is named as the option.
      {"render --scene " + fine.string() + " --time 2023-02-29T00:00Z --out " + dir.path.string(), "nephele: --time: "},
      {"render --at 95,7,500" + png, "nephele: --at: latitude 95"},
      {"render --view gurten --size 20000x10" + png, "nephele: --size: width 20000"},
      {"render --scene /dev/zero" + png, "nephele: /dev/zero: not a regular file"},
  };
  for (const auto& [arguments, expected] : cases) {
    const Run r = run_without_gl(arguments);
    INFO(arguments << "\n" << r.output);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Catch::StartsWith(expected));
  }
}

TEST_CASE("bench --sizes takes strict integers only", "[bad-input][cli]") {
  for (const char* sizes : {"1.5", "0x10", "' 16'", "16,", "16,,32", "0", "16385", "1e2"}) {
    const Run r = run_without_gl(std::string("bench cover --repeat 1 --sizes ") + sizes);
    INFO(sizes << "\n" << r.output);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Catch::StartsWith("nephele: --sizes: "));
  }
}

TEST_CASE("report's lists refuse an empty item like bench's do", "[bad-input][cli]") {
  // std::getline dropped the empty item after a trailing comma, so "16," passed as "16".
  for (const char* option : {"--sizes 16,", "--steps 10,,50", "--tolerances 1e-3,"}) {
    const Run r = run_without_gl(std::string("report --quick --no-render --out /tmp/nephele_never ") + option);
    INFO(option << "\n" << r.output);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Catch::StartsWith(std::string("nephele: ") +
                                           std::string(option).substr(0, std::string(option).find(' ')) + ": "));
  }
}

TEST_CASE("a noise texture over the driver's 3D limit is refused naming the option the user typed",
          "[bad-input][cli]") {
  test::test_context();
  const int max_3d = gpu::max_3d_texture_size();
  if (max_3d >= 65536) return;  // no size the options allow exceeds this driver's limit
  const std::string size = std::to_string(max_3d * 2);
  const auto by_size = test::run("noise --size " + size + " --cells " + size + " --out /tmp/nephele_never.raw");
  CHECK(by_size.exit_code == 2);
  CHECK_THAT(by_size.output, Catch::StartsWith("nephele: --size: " + size));
  const auto by_width = test::run("noise --width " + size + " --cells " + size + " --out /tmp/nephele_never.raw");
  CHECK(by_width.exit_code == 2);
  CHECK_THAT(by_width.output, Catch::StartsWith("nephele: --width: " + size));
}

TEST_CASE("render --at takes three strict decimals, naming the part, within the scene's ranges", "[bad-input][cli]") {
  for (const auto& [at, part] : std::vector<std::pair<std::string, std::string>>{
           {"0x10,7,800", "--at (latitude): "},  // sscanf's %lf read hex as 16 degrees
           {"46.9, 7.4,800", "--at (longitude): "},
           {"46.9,7.4,1e5", "--at: height "},  // in form, out of the table's range
           {"46.9,7.4", "--at: "},
           {"46.9,7.4,800,1", "--at: "}}) {
    const auto r = test::run("render --at '" + at + "' --out /tmp/nephele_never.png");
    INFO(at << ": " << r.output);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Catch::StartsWith("nephele: " + part));
  }
  test::TemporaryDirectory out(true);
  const auto ok = test::run("render --at 46.9,7.44,860 --size 8x4 --view-steps 2 --light-steps 1 --quiet --out " +
                            (out.path / "a.png").string());
  CHECK(ok.exit_code == 0);
}
