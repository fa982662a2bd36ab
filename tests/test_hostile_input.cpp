// Inputs that once broke nephele (a 30000-digit number, escape sequences in a value, sizes that
// overflow): each is refused with exit code 2 and a message naming what the user typed.
#include <catch2/catch.hpp>

#include <sys/stat.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "core/error.hpp"
#include "core/number_text.hpp"
#include "core/printable_text.hpp"
#include "files/image_files.hpp"
#include "model/cloud_model.hpp"
#include "params/table.hpp"
#include "params/values.hpp"
#include "regional/scene.hpp"

namespace fs = std::filesystem;
using namespace nephele;
using test::Run;
using test::run_without_gl;
using test::TemporaryDirectory;

namespace {

const std::string many_digits(30000, '1');

}  // namespace

TEST_CASE("the number scanner takes whole decimal texts of at most 64 characters", "[fast][bad-input][numbers]") {
  using core::NumberForm;
  for (const char* text : {"0", "-7", "+7", "123456789"}) {
    INFO(text);
    CHECK(core::is_decimal_number(text, NumberForm::integer));
    CHECK(core::is_decimal_number(text, NumberForm::real));
  }
  for (const char* text : {"1.5", ".5", "5.", "-1e-3", "2E+10", "0.000001"}) {
    INFO(text);
    CHECK(core::is_decimal_number(text, NumberForm::real));
    CHECK_FALSE(core::is_decimal_number(text, NumberForm::integer));
  }
  for (const char* text : {"", "-", ".", "e5", "1e", "1e+", "1.2.3", " 1", "1 ", "0x10", "inf", "nan", "1,5", "--1"}) {
    INFO("'" << text << "'");
    CHECK_FALSE(core::is_decimal_number(text, NumberForm::real));
  }
  CHECK(core::is_decimal_number(std::string(64, '9'), NumberForm::integer));
  CHECK_FALSE(core::is_decimal_number(std::string(65, '9'), NumberForm::integer));
  // A text far longer than any stack could recurse over is refused without reading it all.
  CHECK_FALSE(core::is_decimal_number(std::string(10'000'000, '1'), NumberForm::real));
  CHECK(core::parse_decimal("-2.5e1", NumberForm::real) == -25.0);
  CHECK(std::isinf(*core::parse_decimal("1e999", NumberForm::real)));
}

TEST_CASE("a number of 30000 digits is refused naming the option wherever numbers are read",
          "[bad-input][numbers][cli]") {
  TemporaryDirectory out;
  const std::string profile = (out.path.parent_path() / (out.path.filename().string() + "_profile.csv")).string();
  std::ofstream(profile) << "latitude_deg,fraction\n-90,0.5\n0," << many_digits << "\n90,0.5\n";
  const struct {
    std::string arguments, option;
  } cases[] = {
      {"generate --size " + many_digits + " --out OUT", "--size"},
      {"generate --step " + many_digits + " --out OUT", "--step"},
      {"render --at " + many_digits + ",7,500 --out OUT.png", "--at (latitude)"},
      {"bench cover --sizes 16," + many_digits, "--sizes"},
      {"noise --size 8 --channels rg --g cells=" + many_digits + " --out OUT.png", "--g cells"},
      {"generate --profile " + profile + " --out OUT", profile},
  };
  for (const auto& c : cases) {
    INFO(c.arguments.substr(0, 60));
    std::string arguments = c.arguments;
    if (const auto at = arguments.find("OUT"); at != std::string::npos)
      arguments.replace(at, 3, (out.path / "x").string());
    const Run r = run_without_gl(arguments);
    INFO(r.output.substr(0, 600));
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Catch::Contains("nephele: " + c.option));
    // The message quotes the value cut short, not all 30000 digits.
    CHECK(r.output.size() < 1000);
  }
  fs::remove(profile);
  CHECK_FALSE(fs::exists(out.path));
}

TEST_CASE("a value just past its range is quoted as typed, not as the double it rounds to", "[bad-input][numbers]") {
  const Run r = run_without_gl("generate --step 10.000000000000001 --out /nonexistent/x");
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.output, Catch::Contains("--step: '10.000000000000001' is out of range"));
}

TEST_CASE("noise channel settings take integers as the options of the same name do", "[bad-input][numbers][noise]") {
  for (const char* setting : {"cells=2.0", "cells=1e0", "octaves=3.", "worley-octaves=9", "cells=0"}) {
    INFO(setting);
    const Run r = run_without_gl(std::string("noise --size 8 --r ") + setting + " --out /nonexistent/x.png");
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Catch::StartsWith("nephele: --r "));
  }
  // The same texts through the options: the same verdicts.
  CHECK(run_without_gl("noise --size 8 --cells 2.0 --out /nonexistent/x.png").exit_code == 2);
  // worley-cells=0 means "as cells", as --worley-cells 0 does: accepted (exit 3: no GL here).
  CHECK(run_without_gl("noise --size 32 --type perlin-worley --r worley-cells=0 --out /tmp/x.png").exit_code == 3);
}

TEST_CASE("messages show control characters, invalid UTF-8 and NUL from inputs escaped", "[bad-input][messages]") {
  CHECK(core::printable("plain text, caf\xC3\xA9") == "plain text, caf\xC3\xA9");
  CHECK(core::printable("\x1B[31mred") == "\\x1B[31mred");
  CHECK(core::printable(std::string("a\0b", 3)) == "a\\x00b");
  CHECK(core::printable("\xFF\xC3") == "\\xFF\\xC3");           // a stray byte, a cut sequence
  CHECK(core::printable("\xC0\xAF") == "\\xC0\\xAF");           // an overlong '/'
  CHECK(core::printable("\xED\xA0\x80") == "\\xED\\xA0\\x80");  // a UTF-16 surrogate
  CHECK(core::printable("line\nnext", 200, true) == "line\nnext");
  CHECK(core::printable("line\nnext") == "line\\x0Anext");
  // Escaping its own output changes nothing: messages may pass twice.
  const std::string once = core::printable("\x1B]0;title\x07");
  CHECK(core::printable(once) == once);
  // Cut after the bound with a note of what was left out.
  const std::string cut = core::printable(std::string(1000, 'x'), 200);
  CHECK(cut == std::string(200, 'x') + "... (800 bytes more)");

  const core::InputError error("FILE: 'name'", std::string("a\0\x1B[2Jb", 7), "text");
  CHECK(std::string(error.what()) == "FILE: 'name': 'a\\x00\\x1B[2Jb' is not allowed (allowed: text)");

  const Run r = run_without_gl("generate --seed \"$(printf '1\\033[31mred\\377')\" --out /nonexistent/x");
  CHECK(r.exit_code == 2);
  CHECK(r.output.find('\x1B') == std::string::npos);
  CHECK_THAT(r.output, Catch::Contains("'1\\x1B[31mred\\xFF'"));
}

TEST_CASE("bench and report name --sizes when a size does not fit the driver", "[bad-input][cli]") {
  // llvmpipe cannot allocate 16384^2 RGBA32F cube maps; a GPU with room for them would run it.
  const Run r = test::run("bench cover --sizes 16384 --repeat 1");
  if (r.exit_code == 0)
    SUCCEED("this driver holds 16384 per face");
  else {
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Catch::StartsWith("nephele: --sizes: 16384"));
  }
}

TEST_CASE("stats checks parameters.size against the table before using it", "[bad-input][stats]") {
  TemporaryDirectory cover(true);
  for (const char* size : {"536870912", "1e300", "-3", "2.5", "\"8\""}) {
    INFO(size);
    std::ofstream(cover.path / "cover.json") << "{\"parameters\": {\"size\": " << size << "}}";
    const Run r = run_without_gl("stats " + cover.path.string());
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Catch::Contains("cover.json: parameters.size"));
    CHECK_THAT(r.output, Catch::Contains(params::cover::size.range_text()));
  }
}

// ---- Files: kinds, declared sizes, values, list lengths ------------------------------------

namespace {

// A cover of 8 texels per face (faces only), made once per test run.
const fs::path& small_cover() {
  static TemporaryDirectory directory;
  static const bool made = [] {
    const Run r = test::run("generate --size 8 --files faces --quiet --out " + directory.path.string());
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    return true;
  }();
  (void)made;
  return directory.path;
}

// A copy of the small cover with face +Z replaced by one of `value` at texel (3, 2): with channels 1
// a cover's face (Y, tau, cloud_top as generate writes them, the value in Y), else RGB.
void copy_cover_with_face(const fs::path& to, int channels, float value) {
  fs::create_directories(to);
  for (const auto& entry : fs::directory_iterator(small_cover()))
    fs::copy_file(entry.path(), to / entry.path().filename());
  const std::size_t stride = 3;
  core::ImageData face{8, 8, static_cast<int>(stride), std::vector<float>(64 * stride, 0.5f)};
  face.pixels[(2 * 8 + 3) * stride] = value;
  std::vector<std::string> names =
      channels == 1 ? std::vector<std::string>{"Y", "tau", "cloud_top"} : std::vector<std::string>{"R", "G", "B"};
  files::write_image(to / "cover_pz.exr", face, files::exr_encoding(names));
}

std::uint32_t crc32_of(const std::string& bytes) {  // PNG's CRC (ISO 3309), bit by bit
  std::uint32_t crc = 0xFFFFFFFFu;
  for (unsigned char c : bytes) {
    crc ^= c;
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

// A PNG whose IHDR declares width x height RGBA 8-bit and which holds no pixel data at all.
void write_png_header_only(const fs::path& path, std::uint32_t width, std::uint32_t height) {
  auto be32 = [](std::uint32_t v) { return std::string{char(v >> 24), char(v >> 16), char(v >> 8), char(v)}; };
  const std::string ihdr = "IHDR" + be32(width) + be32(height) + std::string{8, 6, 0, 0, 0};
  const std::string idat = "IDAT\x78\x9c";  // the start of a zlib stream, no more
  std::ofstream out(path, std::ios::binary);
  out << "\x89PNG\r\n\x1a\n"
      << be32(13) << ihdr << be32(crc32_of(ihdr)) << be32(2) << idat << be32(crc32_of(idat)) << be32(0) << "IEND"
      << be32(crc32_of("IEND"));
}

}  // namespace

TEST_CASE("cover faces holding NaN or values outside [0, 1] are refused by export, render and stats",
          "[bad-input][files]") {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (const float value : {nan, -5.0f, 1e30f}) {
    TemporaryDirectory cover, out;
    copy_cover_with_face(cover.path, 1, value);
    INFO("value " << value);
    const Run r = test::run("export " + cover.path.string() + " --preset gl-faces --out " + out.path.string());
    INFO(r.output);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Catch::Contains("cover_pz.exr") && Catch::Contains("at texel 3, 2") &&
                             Catch::Contains("coverage values in [0, 1]"));
    CHECK_FALSE(fs::exists(out.path));
    if (std::isnan(value)) {
      const Run render = test::run("render --view orbit --size 32x16 --cover " + cover.path.string() + " --out " +
                                   (out.path.string() + ".png"));
      CHECK(render.exit_code == 2);
      CHECK_THAT(render.output, Catch::Contains("cover_pz.exr"));
      CHECK_FALSE(fs::exists(out.path.string() + ".png"));
      const Run stats = run_without_gl("stats " + cover.path.string());
      CHECK(stats.exit_code == 2);
    }
  }
}

TEST_CASE("an RGB cover face is refused, not read through its red channel", "[bad-input][files]") {
  TemporaryDirectory cover, out;
  copy_cover_with_face(cover.path, 3, 0.25f);
  const Run r = run_without_gl("export " + cover.path.string() + " --preset gl-faces --out " + out.path.string());
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.output, Catch::Contains("cover_pz.exr") && Catch::Contains("has the channels R, G, B"));
  CHECK_FALSE(fs::exists(out.path));
}

TEST_CASE("export refuses --format and --name where its preset does not read them", "[bad-input][cli]") {
  TemporaryDirectory out;
  const std::string cover = small_cover().string();
  const Run format = run_without_gl("export " + cover + " --preset dds --format r32f --out " + out.path.string());
  CHECK(format.exit_code == 2);
  CHECK_THAT(format.output, Catch::StartsWith("nephele: --format: 'r32f' is not read by preset dds"));
  const Run name = run_without_gl("export " + cover + " --preset gl-faces --name clouds --out " + out.path.string());
  CHECK(name.exit_code == 2);
  CHECK_THAT(name.output, Catch::StartsWith("nephele: --name: 'clouds' is not read by preset gl-faces"));
  CHECK_FALSE(fs::exists(out.path));
}

TEST_CASE("a too-large export is refused from the faces' headers before their pixels are read", "[bad-input][files]") {
  // Faces of 4097 whose pixel data is cut off after the header: reading them would fail with a
  // read error, so the size refusal proves that only the headers were read.
  TemporaryDirectory cover(true), out;
  const fs::path whole = cover.path / "whole.exr";
  files::write_image(whole, core::ImageData{4097, 4097, 1, std::vector<float>(std::size_t(4097) * 4097, 0.0f)},
                     files::exr_encoding({"Y"}));
  std::string bytes = test::read_file(whole);
  bytes.resize(std::min<std::size_t>(bytes.size(), 4096));
  fs::remove(whole);
  for (const char* face : {"px", "nx", "py", "ny", "pz", "nz"})
    std::ofstream(cover.path / (std::string("cover_") + face + ".exr"), std::ios::binary) << bytes;
  const Run r = run_without_gl("export " + cover.path.string() + " --preset equirect --out " + out.path.string());
  INFO(r.output);
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.output, Catch::Contains("4097"));
  CHECK(r.output.find("cannot be read") == std::string::npos);
  CHECK_FALSE(fs::exists(out.path));
}

TEST_CASE("volume sidecars and raw files that are devices, FIFOs or too large are refused with code 2",
          "[bad-input][files]") {
  TemporaryDirectory directory(true), out;
  // A device as the sidecar: refused before reading (it was read until memory ran out).
  const Run zero = run_without_gl("export /dev/zero --preset atlas --out " + out.path.string());
  CHECK(zero.exit_code == 2);
  CHECK_THAT(zero.output, Catch::Contains("not a regular file"));
  // A FIFO as the sidecar and as the raw file: refused at once, not waited on.
  const fs::path fifo = directory.path / "pipe.json";
  REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
  const Run pipe = run_without_gl("timeout 20 " + std::string(NEPHELE_EXECUTABLE) + " export " + fifo.string() +
                                  " --preset atlas --out " + out.path.string());
  CHECK(pipe.exit_code == 2);
  const fs::path raw_fifo = directory.path / "data.raw";
  REQUIRE(mkfifo(raw_fifo.c_str(), 0600) == 0);
  const std::string sidecar = R"({"program": "nephele noise", "format": "raw-float32-little-endian", "width": 2, )"
                              R"("height": 2, "depth": 2, "channels": "r", "file": "data.raw"})";
  std::ofstream(directory.path / "noise.json") << sidecar;
  const Run raw =
      test::run_command("timeout 20 " + std::string(NEPHELE_EXECUTABLE) + " export " +
                        (directory.path / "noise.json").string() + " --preset atlas --out " + out.path.string());
  CHECK(raw.exit_code == 2);
  CHECK_THAT(raw.output, Catch::Contains("data.raw"));
  // Dimensions past the memory budget: refused from the sidecar, before the raw file is opened.
  std::string huge = sidecar;
  for (const char* axis : {"\"width\": 2", "\"height\": 2", "\"depth\": 2"})
    huge.replace(huge.find(axis), std::strlen(axis), std::string(axis).substr(0, std::strlen(axis) - 1) + "65536");
  std::ofstream(directory.path / "huge.json") << huge;
  const Run big = run_without_gl("export " + (directory.path / "huge.json").string() + " --preset atlas --out " +
                                 out.path.string());
  CHECK(big.exit_code == 2);
  CHECK_THAT(big.output, Catch::Contains("available memory"));
  CHECK_FALSE(fs::exists(out.path));
}

TEST_CASE("an image header declaring 100000 x 100000 pixels is refused naming the option before allocation",
          "[bad-input][files]") {
  TemporaryDirectory directory(true);
  const fs::path big = directory.path / "big.png";
  write_png_header_only(big, 100000, 100000);  // 160 GB as float RGBA
  const Run surface =
      run_without_gl("generate --size 8 --surface " + big.string() + " --out " + (directory.path / "c").string());
  INFO(surface.output);
  CHECK(surface.exit_code == 2);
  CHECK_THAT(surface.output, Catch::StartsWith("nephele: --surface: ") && Catch::Contains("available memory"));
  const Run earth = test::run("render --view orbit --size 32x16 --earth-texture " + big.string() + " --out " +
                              (directory.path / "o.png").string());
  INFO(earth.output);
  CHECK(earth.exit_code == 2);
  CHECK_THAT(earth.output, Catch::StartsWith("nephele: --earth-texture: ") && Catch::Contains("available memory"));
  CHECK_FALSE(fs::exists(directory.path / "o.png"));
}

TEST_CASE("a FIFO given as --surface is named as not a regular file, not as missing", "[bad-input][files]") {
  TemporaryDirectory directory(true);
  const fs::path fifo = directory.path / "mask.png";
  REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
  const Run r =
      run_without_gl("generate --size 8 --surface " + fifo.string() + " --out " + (directory.path / "c").string());
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.output, Catch::Contains("--surface") && Catch::Contains("not a regular file"));
}

TEST_CASE("lists are capped: 64 weather files a scene, 4096 primitives a model", "[bad-input][files]") {
  TemporaryDirectory directory(true);
  std::string weather = "[";
  for (std::size_t i = 0; i <= regional::max_weather_files; ++i) weather += (i ? ", " : "") + std::string("\"w.json\"");
  std::ofstream(directory.path / "scene.json") << R"({"view": "gurten", "weather": )" << weather << "]}";
  const Run scene = run_without_gl("render --scene " + (directory.path / "scene.json").string() + " --out " +
                                   (directory.path / "x.png").string());
  CHECK(scene.exit_code == 2);
  CHECK_THAT(scene.output, Catch::Contains("weather") && Catch::Contains("65 files (allowed: at most 64)"));

  std::string points = "[";
  for (std::size_t i = 0; i < model::max_primitives + 2; ++i)
    points += (i ? ", " : "") + std::string("[0.5, 0.5, 0.5]");
  std::ofstream(directory.path / "m.cloud.json")
      << R"({"primitives": [{"type": "polyline", "points": )" << points << R"(], "radius": 0.05}]})";
  const Run model = run_without_gl("model --scene " + (directory.path / "m.cloud.json").string() + " --size 8 --out " +
                                   (directory.path / "m").string());
  CHECK(model.exit_code == 2);
  CHECK_THAT(model.output, Catch::Contains("primitives") && Catch::Contains("at most 4096"));
  CHECK_FALSE(fs::exists(directory.path / "m"));
}

TEST_CASE("one rule everywhere: upper-case extensions, repeated list items, the option that was typed",
          "[bad-input][cli]") {
  TemporaryDirectory directory(true);
  // x.PNG is a PNG for render as for noise (render refused it, noise took it).
  const Run render = run_without_gl("render --view gurten --size 8x8 --out " + (directory.path / "x.PNG").string());
  CHECK(render.exit_code == 3);  // past every check: it needs GL
  const Run orbit = run_without_gl("render --view orbit --size 8x8 --out " + (directory.path / "x.EXR").string());
  CHECK(orbit.exit_code == 3);
  const Run noise = run_without_gl("noise --size 8 --out " + (directory.path / "a.PNG").string());
  CHECK(noise.exit_code == 3);
  // A preset named twice is refused as --files refuses faces,faces.
  const Run exports =
      run_without_gl("generate --size 8 --export equirect,equirect --out " + (directory.path / "c").string());
  CHECK(exports.exit_code == 2);
  CHECK_THAT(exports.output, Catch::StartsWith("nephele: --export: ") && Catch::Contains("twice"));
  // The viewer's --model names --model, not --scene.
  const Run view = run_without_gl("view --model " + (directory.path / "bogus").string());
  CHECK(view.exit_code == 2);
  CHECK_THAT(view.output, Catch::StartsWith("nephele: --model: "));
}
