// nephele export: every preset's files, read back by readers written here from the formats'
// specifications (not the writers' code), with an asymmetric marker cover whose one bright dot
// must appear at the pixel each target's convention puts it.
#include <OpenImageIO/imageio.h>

#include <catch2/catch.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "case_tags.hpp"
#include "cli_support.hpp"
#include "files/atomic_output.hpp"
#include "io/cube_frames.hpp"
#include "io/export_writers.hpp"
#include "io/export_presets.hpp"
#include "files/image_files.hpp"
#include "io/model_files.hpp"
#include "files/texture_containers.hpp"
#include "io/volume_export.hpp"
#include "core/error.hpp"
#include "cover/equirect.hpp"
#include "gl_support.hpp"
#include "io/cover_files.hpp"
#include "shader_math/shader_math.hpp"
#include "params/table.hpp"
#include "texture_readers.hpp"

namespace nephele {
namespace {

constexpr int kSize = 32;
// The marker: geocentric latitude 30 N, longitude 60 E. It lies on the +Y face, away from its
// edges, and no mirror or rotation of a face or of the map maps it onto itself.
constexpr double kLat = 30.0, kLon = 60.0;
constexpr double kRadius = 0.1;  // angular radius in radians: about 3 texels of a 32^2 face
constexpr double kPi = 3.14159265358979323846;

std::array<double, 3> marker_direction() {
  const double lat = kLat * kPi / 180, lon = kLon * kPi / 180;
  return {std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)};
}

// Writes a cover directory: 0.1 everywhere, 1 within kRadius of the marker, through the same
// image writer as `generate`. Texel directions come from io::gl_texel_direction; the checks
// below place the marker with formulas of their own (marker_on_face, gl_face_of), so an error
// there shows up as a misplaced marker.
void write_marker_cover(const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  const auto m = marker_direction();
  const char* const suffixes[6] = {"px", "nx", "py", "ny", "pz", "nz"};
  for (int f = 0; f < 6; ++f) {
    core::ImageData face{kSize, kSize, 1, std::vector<float>(kSize * kSize)};
    for (int j = 0; j < kSize; ++j)
      for (int i = 0; i < kSize; ++i) {
        const auto d = io::gl_texel_direction(f, i, j, kSize);
        const double angle = std::acos(std::min(1.0, d[0] * m[0] + d[1] * m[1] + d[2] * m[2]));
        face.pixels[j * kSize + i] = angle < kRadius ? 1.0f : 0.1f;
      }
    files::write_image(dir / (std::string("cover_") + suffixes[f] + ".exr"), face, files::exr_encoding({"Y"}));
  }
  files::write_text_file(dir / "cover.json", "{}\n");
}

struct Centroid {
  double x = 0, y = 0;
  int count = 0;
};
// Centroid of the pixels above 0.5 in channel c of the rectangle [x0, x0 + w) x [y0, y0 + h).
Centroid bright_centroid(const std::vector<float>& pixels, int width, int channels, int c, int x0, int y0, int w,
                         int h) {
  Centroid r;
  for (int y = y0; y < y0 + h; ++y)
    for (int x = x0; x < x0 + w; ++x)
      if (pixels[(std::size_t(y) * width + x) * channels + c] > 0.5f) r.x += x - x0, r.y += y - y0, ++r.count;
  if (r.count) r.x /= r.count, r.y /= r.count;
  return r;
}

// Where the marker's centre falls on the +Y face, in pixel coordinates (centres at i + 0.5).
std::array<double, 2> marker_on_face() {
  const auto m = marker_direction();
  const double s = (m[0] / m[1] + 1) / 2, t = (m[2] / m[1] + 1) / 2;
  return {s * kSize - 0.5, t * kSize - 0.5};
}

// The thresholded dot is about 6 texels across; its centroid moves by less than half a pixel
// with the texel grid, plus the bilinear resampling's blur of the edge: one pixel bounds both.
constexpr double kMarkerPixels = 1.0;

// The marker in face `face` of a cube map (kSize^2 texels of `channels`, starting at row `y0` of
// an image kSize wide): on +Y (face 2) where the GL face table puts it, nothing bright elsewhere.
void check_cube_face_marker(int face, const std::vector<float>& texels, int channels, int channel, int y0 = 0) {
  const auto centroid = bright_centroid(texels, kSize, channels, channel, 0, y0, kSize, kSize);
  INFO("face " << face << " channel " << channel);
  if (face != 2) {
    CHECK(centroid.count == 0);
    return;
  }
  REQUIRE(centroid.count > 0);
  CHECK(centroid.x == Approx(marker_on_face()[0]).epsilon(0).margin(kMarkerPixels));
  CHECK(centroid.y == Approx(marker_on_face()[1]).epsilon(0).margin(kMarkerPixels));
}

// Where it falls on a W x H equirect: -180 at the left edge, geodetic latitude down the rows.
std::array<double, 2> marker_on_equirect(int width, int height) {
  const double f = 1 / 298.257223563;
  const double geodetic = std::atan(std::tan(kLat * kPi / 180) / ((1 - f) * (1 - f))) * 180 / kPi;
  return {(kLon + 180) / 360 * width - 0.5, (90 - geodetic) / 180 * height - 0.5};
}

struct Exported {
  test::TemporaryDirectory cover{true}, out;
  test::Run run;
  explicit Exported(const std::string& preset, const std::string& extra = "") {
    write_marker_cover(cover.path);
    run = test::run("export " + cover.path.string() + " --preset " + preset + " --out " + out.path.string() + extra);
  }
};

// PNG chunk types in file order (PNG specification, section 5.3: length, type, data, CRC).
std::vector<std::string> png_chunks(const std::string& bytes) {
  std::vector<std::string> types;
  for (std::size_t at = 8; at + 8 <= bytes.size();) {
    const std::uint32_t length = (std::uint32_t((unsigned char)bytes[at]) << 24) |
                                 (std::uint32_t((unsigned char)bytes[at + 1]) << 16) |
                                 (std::uint32_t((unsigned char)bytes[at + 2]) << 8) | (unsigned char)bytes[at + 3];
    types.push_back(bytes.substr(at + 4, 4));
    at += 12 + length;
  }
  return types;
}

// Read as stored: PNG alpha is unassociated, and OpenImageIO would premultiply the colour.
core::ImageData read_png_as_stored(const std::filesystem::path& png) {
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(png.string(), &config);
  REQUIRE(in);
  core::ImageData image{in->spec().width, in->spec().height, in->spec().nchannels, {}};
  image.pixels.resize(std::size_t(image.width) * image.height * image.channels);
  REQUIRE(in->read_image(0, 0, 0, image.channels, OIIO::TypeDesc::FLOAT, image.pixels.data()));
  in->close();
  return image;
}

void check_equirect_marker(const core::ImageData& image, int channel = 0) {
  REQUIRE(image.width == 2 * image.height);
  const auto c = bright_centroid(image.pixels, image.width, image.channels, channel, 0, 0, image.width, image.height);
  const auto expected = marker_on_equirect(image.width, image.height);
  REQUIRE(c.count > 0);
  CHECK(c.x == Approx(expected[0]).epsilon(0).margin(kMarkerPixels));
  CHECK(c.y == Approx(expected[1]).epsilon(0).margin(kMarkerPixels));
}

// A 2D DDS of EVE's kind (legacy FourCC DXT5, every mip level; Microsoft's DDS_HEADER at its
// documented offsets): the base level as RGBA floats, after checking that it is not a cube and
// that the file holds exactly the full chain.
core::ImageData read_dds_2d_dxt5(const std::filesystem::path& path) {
  const std::string b = test::read_file(path);
  const test::DdsFile d = test::read_dds(b);
  CHECK(d.four_cc == "DXT5");
  CHECK(d.faces == 1);
  CHECK((d.caps & 0x400000u) != 0);  // DDSCAPS_MIPMAP: EVE's reader keeps the chain only with it
  int levels = 1;
  for (std::uint32_t edge = std::max(d.width, d.height); edge > 1; edge >>= 1) ++levels;
  CHECK(d.mip_count == std::uint32_t(levels));
  CHECK(b.size() == test::dds_image_offset(d, test::StoredFormat::bc3, 1, 0));
  const int width = int(d.width), height = int(d.height);
  const auto* data = reinterpret_cast<const unsigned char*>(b.data()) + d.data_offset;
  return {width, height, 4, test::decode_stored_image(test::StoredFormat::bc3, data, width, height)};
}

// KSP's ConfigNode text (GameData/*.cfg) as EVE's managers see it: nodes NAME { ... } holding
// `key = value` lines and child nodes, // comments. Written from the format's description on
// the KSP wiki and EVE's EveManager/IEVEManager.cs (Apply reads the child nodes of each
// top-level node), not from nephele's writer.
struct ConfigNode {
  std::string name;
  std::multimap<std::string, std::string> values;
  std::vector<ConfigNode> nodes;
  std::string value(const std::string& key) const {
    const auto it = values.find(key);
    return it == values.end() ? std::string() : it->second;
  }
  const ConfigNode* node(const std::string& child) const {
    for (const auto& n : nodes)
      if (n.name == child) return &n;
    return nullptr;
  }
};
std::string trimmed(std::string text) {
  const auto first = text.find_first_not_of(" \t\r"), last = text.find_last_not_of(" \t\r");
  return first == std::string::npos ? std::string() : text.substr(first, last - first + 1);
}
ConfigNode parse_config(const std::string& text) {
  ConfigNode root;
  std::vector<ConfigNode*> open{&root};
  std::string pending;  // a name waiting for its '{'
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    line = trimmed(line.substr(0, line.find("//")));
    if (line.empty()) continue;
    if (line == "{") {
      REQUIRE_FALSE(pending.empty());
      open.back()->nodes.push_back({pending, {}, {}});
      open.push_back(&open.back()->nodes.back());
      pending.clear();
    } else if (line == "}") {
      REQUIRE(open.size() > 1);
      open.pop_back();
    } else if (line.find('=') != std::string::npos) {
      open.back()->values.emplace(trimmed(line.substr(0, line.find('='))), trimmed(line.substr(line.find('=') + 1)));
    } else {
      pending = line;
    }
  }
  CHECK(open.size() == 1);  // every node closed
  return root;
}

}  // namespace

TEST_CASE("export's preset registry and the parameter table name the same presets", "[fast][export]") {
  std::string words;
  for (const auto& p : io::export_presets()) words += (words.empty() ? "" : "|") + p.name;
  CHECK(words == std::string(params::run::export_preset.allowed));
}

TEST_CASE("export refuses an unknown preset and a directory without cover faces with exit code 2", "[export][cli]") {
  test::TemporaryDirectory cover(true), out;
  write_marker_cover(cover.path);
  auto r = test::run("export " + cover.path.string() + " --preset blue --out " + out.path.string());
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.output, Catch::Contains("--preset") && Catch::Contains("blue") && Catch::Contains("equirect"));
  test::TemporaryDirectory empty(true);
  r = test::run("export " + empty.path.string() + " --preset gl-faces --out " + out.path.string());
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.output, Catch::Contains("COVER_DIR") && Catch::Contains("cover_px.exr"));
  r = test::run("export --preset gl-faces --out " + out.path.string());
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.output, Catch::Contains("COVER_DIR"));
  CHECK_FALSE(std::filesystem::exists(out.path / "README.txt"));
}

TEST_CASE("export equirect: the marker at its longitude and geodetic latitude in the EXR and both PNGs, no gamma chunk",
          "[export]") {
  Exported e("equirect");
  REQUIRE(e.run.exit_code == 0);
  CHECK(std::filesystem::exists(e.out.path / "README.txt"));
  for (const char* name : {"cover_equirect.exr", "cover_equirect_16.png", "cover_equirect_8.png"}) {
    INFO(name);
    const auto image = files::read_image(e.out.path / name);
    REQUIRE(image.width == 4 * kSize);
    REQUIRE(image.height == 2 * kSize);
    const auto c = bright_centroid(image.pixels, image.width, image.channels, 0, 0, 0, image.width, image.height);
    const auto expected = marker_on_equirect(image.width, image.height);
    REQUIRE(c.count > 0);
    CHECK(c.x == Approx(expected[0]).epsilon(0).margin(kMarkerPixels));
    CHECK(c.y == Approx(expected[1]).epsilon(0).margin(kMarkerPixels));
  }
  // Coverage is data: a gAMA, sRGB or iCCP chunk would make viewers and engines re-encode it.
  for (const char* name : {"cover_equirect_16.png", "cover_equirect_8.png"}) {
    const std::string bytes = test::read_file(e.out.path / name);
    INFO(name);
    REQUIRE(bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0);
    CHECK(bytes[24] == (std::string(name).find("16") != std::string::npos ? 16 : 8));  // IHDR bit depth
    for (const auto& type : png_chunks(bytes)) {
      CHECK(type != "gAMA");
      CHECK(type != "sRGB");
      CHECK(type != "iCCP");
    }
  }
}

TEST_CASE("export gl-faces: the marker on the +Y face only, at the texel of the GL face table", "[export]") {
  Exported e("gl-faces");
  REQUIRE(e.run.exit_code == 0);
  const char* const suffixes[6] = {"px", "nx", "py", "ny", "pz", "nz"};
  for (int f = 0; f < 6; ++f) {
    INFO(suffixes[f]);
    const auto face = files::read_image(e.out.path / (std::string("cover_") + suffixes[f] + ".exr"));
    REQUIRE(face.width == kSize);
    check_cube_face_marker(f, face.pixels, face.channels, 0);
  }
}

TEST_CASE(
    "export ktx2: an independent reader finds the spec's header, descriptor, orientation and mip chain, and the marker "
    "on +Y",
    "[export]") {
  const struct {
    const char* format;
    std::uint32_t vk_format, type_size;
    test::StoredFormat stored;
  } cases[] = {{"r16f", 76, 2, test::StoredFormat::r16f},
               {"r32f", 100, 4, test::StoredFormat::r32f},
               {"r8", 9, 1, test::StoredFormat::r8},
               {"bc4", 139, 1, test::StoredFormat::bc4}};
  for (const auto& c : cases) {
    INFO(c.format);
    Exported e("ktx2", std::string(" --format ") + c.format);
    REQUIRE(e.run.exit_code == 0);
    const std::string b = test::read_file(e.out.path / "cover_cube.ktx2");
    const test::Ktx2File k = test::read_ktx2(b);
    CHECK(k.vk_format == c.vk_format);
    CHECK(k.type_size == c.type_size);
    CHECK(k.width == std::uint32_t(kSize));
    CHECK(k.height == std::uint32_t(kSize));
    CHECK(k.depth == 0);
    CHECK(k.layers == 0);
    CHECK(k.faces == 6);
    CHECK(k.level_count == 6);  // 32 down to 1
    CHECK(k.supercompression == 0);
    CHECK(k.primaries == 1);  // BT.709
    CHECK(k.transfer == 1);   // linear: coverage is data
    CHECK(k.orientation == "rd");
    // Faces in GL order, rows without padding: the marker on face 2 of the base level.
    const std::size_t face_bytes = test::stored_image_bytes(c.stored, kSize, kSize);
    REQUIRE(k.levels[0].length == 6 * face_bytes);
    REQUIRE(k.levels[0].offset + k.levels[0].length <= b.size());
    for (int f = 0; f < 6; ++f) {
      const auto* data = reinterpret_cast<const unsigned char*>(b.data()) + k.levels[0].offset + f * face_bytes;
      check_cube_face_marker(f, test::decode_stored_image(c.stored, data, kSize, kSize), 1, 0);
    }
  }
}

TEST_CASE("export refuses a ktx2 format outside r16f, r32f, r8, bc4", "[export][cli]") {
  Exported e("ktx2", " --format bc7");
  CHECK(e.run.exit_code == 2);
  CHECK_THAT(e.run.output, Catch::Contains("--format") && Catch::Contains("bc7"));
}

// The fields of a DDS file that place its texels (Microsoft's "DDS_HEADER", "DDS_PIXELFORMAT"
// and "DDS_HEADER_DXT10" reference pages), read at their documented byte offsets.
TEST_CASE(
    "export dds: BC4, BC3, RGBA8 and DX10 float cubes with mip chains as documented, and OpenImageIO finds the marker "
    "in the RGBA8 cube",
    "[export]") {
  Exported e("dds");
  REQUIRE(e.run.exit_code == 0);
  const struct {
    const char* name;
    const char* four_cc;
    std::uint32_t dxgi;
    test::StoredFormat stored;
  } cases[] = {{"cover_cube_bc4.dds", "ATI1", 0, test::StoredFormat::bc4},
               {"cover_cube_bc3.dds", "DXT5", 0, test::StoredFormat::bc3},
               {"cover_cube_rgba8.dds", "", 0, test::StoredFormat::rgba8},
               {"cover_cube_r16f.dds", "DX10", 54, test::StoredFormat::r16f},
               {"cover_cube_r32f.dds", "DX10", 41, test::StoredFormat::r32f}};
  for (const auto& c : cases) {
    INFO(c.name);
    const std::string b = test::read_file(e.out.path / c.name);
    const test::DdsFile d = test::read_dds(b);
    CHECK(d.height == std::uint32_t(kSize));
    CHECK(d.width == std::uint32_t(kSize));
    CHECK(d.mip_count == 6);
    CHECK(d.four_cc == c.four_cc);
    CHECK(d.caps2 == 0xFE00u);  // CUBEMAP and all six faces
    if (c.stored == test::StoredFormat::rgba8) {
      CHECK(d.pixel_flags == 0x41u);  // DDPF_RGB | DDPF_ALPHAPIXELS
      CHECK(d.rgb_bits == 32);
      CHECK(d.masks[0] == 0x000000ffu);
      CHECK(d.masks[3] == 0xff000000u);
    }
    if (c.dxgi != 0) {
      CHECK(d.dxgi == c.dxgi);
      CHECK(d.dx10_dimension == 3);  // D3D10_RESOURCE_DIMENSION_TEXTURE2D
      CHECK(d.dx10_misc == 0x4);     // DDS_RESOURCE_MISC_TEXTURECUBE
      CHECK(d.dx10_array_size == 1);
    }
    CHECK(b.size() == test::dds_image_offset(d, c.stored, 6, 0));
    // The marker on face 2 of the base level (alpha for the RGBA formats).
    for (int f = 0; f < 6; ++f) {
      const auto* data = reinterpret_cast<const unsigned char*>(b.data()) + test::dds_image_offset(d, c.stored, f, 0);
      const std::vector<float> texels = test::decode_stored_image(c.stored, data, kSize, kSize);
      const int channels = int(texels.size() / (kSize * kSize));
      check_cube_face_marker(f, texels, channels, channels - 1);
    }
  }
  // OpenImageIO 2.4 reads the legacy RGBA8 cube as an N x 6N image of the faces in order; the
  // marker must be on the third face (+Y), where the GL table puts it.
  const auto image = files::read_image(e.out.path / "cover_cube_rgba8.dds");
  REQUIRE(image.width == kSize);
  REQUIRE(image.height == 6 * kSize);
  REQUIRE(image.channels == 4);
  for (int channel = 0; channel < 4; ++channel)
    for (int f = 0; f < 6; ++f) check_cube_face_marker(f, image.pixels, 4, channel, f * kSize);
}

TEST_CASE(
    "export celestia: an add-on folder with a white RGBA map, coverage in alpha, prime meridian centred, and CloudMap",
    "[export]") {
  Exported e("celestia", " --name marker_test");
  REQUIRE(e.run.exit_code == 0);
  const auto folder = e.out.path / "extras" / "marker_test";
  const std::string ssc = test::read_file(folder / "marker_test.ssc");
  CHECK_THAT(ssc, Catch::Contains("Modify \"Earth\" \"Sol\"") && Catch::Contains("CloudMap \"marker_test.dds\"") &&
                      Catch::Contains("CloudShadowDepth 1") &&
                      Catch::Contains("CloudNormalMap \"marker_test_normal.png\""));
  // The normal map: the cloud map's size, flat (0.5, 0.5, 1) where the cover is flat.
  const auto normals = read_png_as_stored(folder / "textures" / "hires" / "marker_test_normal.png");
  REQUIRE(normals.channels == 3);
  CHECK(normals.width == 4 * kSize);
  CHECK(normals.height == 2 * kSize);
  CHECK(normals.pixels[0] == Approx(128 / 255.0).margin(1e-6));  // far from the marker: flat
  CHECK(normals.pixels[2] == 1.0f);
  // The DDS the .ssc names: DXT5 (Celestia's loader reads DXT1, DXT3, DXT5), every mip level,
  // RGB white and the marker in alpha where the PNG has it.
  const auto dds = read_dds_2d_dxt5(folder / "textures" / "hires" / "marker_test.dds");
  REQUIRE(dds.width == 4 * kSize);
  REQUIRE(dds.height == 2 * kSize);
  CHECK(dds.pixels[0] == 1.0f);
  check_equirect_marker(dds, 3);
  const auto png = folder / "textures" / "hires" / "marker_test.png";
  const auto image = read_png_as_stored(png);
  REQUIRE(image.channels == 4);
  REQUIRE(image.width == 4 * kSize);
  REQUIRE(image.height == 2 * kSize);
  for (std::size_t i = 0; i < image.pixels.size(); i += 4) {
    if (image.pixels[i] != 1.0f || image.pixels[i + 1] != 1.0f || image.pixels[i + 2] != 1.0f)
      FAIL("not white at " << i / 4);
  }
  // Celestia's cloud maps have longitude 0 at the centre column and -180 at the left edge.
  const auto c = bright_centroid(image.pixels, image.width, 4, 3, 0, 0, image.width, image.height);
  REQUIRE(c.count > 0);
  CHECK(c.x == Approx(marker_on_equirect(image.width, image.height)[0]).epsilon(0).margin(kMarkerPixels));
  CHECK(c.y == Approx(marker_on_equirect(image.width, image.height)[1]).epsilon(0).margin(kMarkerPixels));
  for (const auto& type : png_chunks(test::read_file(png))) CHECK(type != "gAMA");
  CHECK(std::filesystem::exists(e.out.path / "README.txt"));
  Exported bad("celestia", " --name ../x");
  CHECK(bad.run.exit_code == 2);
  CHECK_THAT(bad.run.output, Catch::Contains("--name"));
  CHECK_FALSE(std::filesystem::exists(bad.out.path / "README.txt"));  // the set appears whole or not at all
}

TEST_CASE("celestia's cloud normal map tilts red east and green south by the slope of the coverage's height",
          "[fast][export]") {
  // Celestia's tangent frame (shadermanager.cpp, the sphere's tangent (sin theta, 0, -cos theta)):
  // red east, green south (row 0 is north), blue up, each (1 + n)/2. A height rising east
  // tilts the surface west (red below 1/2), one rising south tilts it north (green below 1/2).
  const int w = 64, h = 32;
  const double relief = 1e6, pi = 3.14159265358979323846, radius = 6371000.0;
  core::ImageData east{w, h, 1, std::vector<float>(w * h)}, south{w, h, 1, std::vector<float>(w * h)};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      east.pixels[y * w + x] = 0.01f * float(x);   // coverage rising by 0.01 a column to the east
      south.pixels[y * w + x] = 0.02f * float(y);  // and by 0.02 a row to the south
    }
  const auto tilted_east = io::celestia_normal_map(east, relief);
  const auto tilted_south = io::celestia_normal_map(south, relief);
  for (int y : {4, 16, 27}) {
    const double latitude = pi / 2 - (y + 0.5) * pi / h;
    const double slope = relief * 0.01 / (radius * std::cos(latitude) * 2 * pi / w);  // dh/d(east), m/m
    const double length = std::sqrt(1 + slope * slope);
    for (int x : {1, 30, 62}) {  // away from the seam, where the ramp wraps
      INFO("row " << y << " column " << x);
      const float* n = &tilted_east.pixels[(std::size_t(y) * w + x) * 3];
      CHECK(n[0] == Approx(0.5 - 0.5 * slope / length).margin(1e-6));
      CHECK(n[1] == Approx(0.5).margin(1e-6));
      CHECK(n[2] == Approx(0.5 + 0.5 / length).margin(1e-6));
      const double north_slope = -relief * 0.02 / (radius * pi / h);  // falls to the north
      const double l2 = std::sqrt(1 + north_slope * north_slope);
      const float* m = &tilted_south.pixels[(std::size_t(y) * w + x) * 3];
      CHECK(m[0] == Approx(0.5).margin(1e-6));
      CHECK(m[1] == Approx(0.5 + 0.5 * north_slope / l2).margin(1e-6));
      CHECK(m[1] < 0.5f);
    }
  }
}

TEST_CASE("export celestia and eve refuse a bad --name with exit code 2 before creating --out", "[export][cli]") {
  for (const char* preset : {"celestia", "eve"}) {
    for (const char* name : {"../x", "a b", ""}) {
      INFO(preset << " --name '" << name << "'");
      Exported bad(preset, std::string(" --name '") + name + "'");
      CHECK(bad.run.exit_code == 2);
      CHECK_THAT(bad.run.output, Catch::Contains("--name"));
      CHECK_FALSE(std::filesystem::exists(bad.out.path));
    }
  }
}

// OpenEXR's CubeMap::pixelPosition inverted and CubeMap::direction (src/lib/OpenEXR/ImfEnvmap.cpp),
// transcribed: the direction of pixel (column c, row r) of `face` in an N x 6N strip. pif is the
// position in the face, 0 .. N - 1 on both axes, mapped to -1 .. 1 edge to edge.
std::array<double, 3> openexr_direction(int face, int c, int r, int n) {
  const double s = n - 1;
  double px = 0, py = 0;  // pif
  switch (face) {
    case 0: px = s - r, py = c; break;      // +X: pixel (min.x + pif.y, max.y - pif.x)
    case 1: px = s - r, py = s - c; break;  // -X: (max.x - pif.y, max.y - pif.x)
    case 2: px = c, py = s - r; break;      // +Y: (min.x + pif.x, max.y - pif.y)
    case 3: px = c, py = r; break;          // -Y: (min.x + pif.x, min.y + pif.y)
    case 4: px = s - c, py = s - r; break;  // +Z: (max.x - pif.x, max.y - pif.y)
    default: px = c, py = s - r; break;     // -Z: (min.x + pif.x, max.y - pif.y)
  }
  const double a = px / s * 2 - 1, b = py / s * 2 - 1;
  const std::array<double, 3> d = face == 0   ? std::array<double, 3>{1, a, b}
                                  : face == 1 ? std::array<double, 3>{-1, a, b}
                                  : face == 2 ? std::array<double, 3>{a, 1, b}
                                  : face == 3 ? std::array<double, 3>{a, -1, b}
                                  : face == 4 ? std::array<double, 3>{a, b, 1}
                                              : std::array<double, 3>{a, b, -1};
  const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  return {d[0] / length, d[1] / length, d[2] / length};
}

TEST_CASE(
    "export exr-cube: every pixel holds the cover in the direction OpenEXR's envmap gives it, edge pixels on the "
    "cube's edges",
    "[export]") {
  // A smooth cover, f(d) = 0.5 + A (x + y + z) with A = 0.45 / sqrt 3, on faces of n texels.
  const int n = 64;
  const double amplitude = 0.45 / std::sqrt(3.0);
  const auto f = [&](const std::array<double, 3>& d) { return 0.5 + amplitude * (d[0] + d[1] + d[2]); };
  test::TemporaryDirectory cover{true}, out;
  const char* const suffixes[6] = {"px", "nx", "py", "ny", "pz", "nz"};
  for (int face = 0; face < 6; ++face) {
    core::ImageData image{n, n, 1, std::vector<float>(n * n)};
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) image.pixels[j * n + i] = float(f(io::gl_texel_direction(face, i, j, n)));
    files::write_image(cover.path / (std::string("cover_") + suffixes[face] + ".exr"), image,
                       files::exr_encoding({"Y"}));
  }
  const test::Run run = test::run("export " + cover.path.string() + " --preset exr-cube --out " + out.path.string());
  REQUIRE(run.exit_code == 0);
  const auto path = out.path / "cover_envcube.exr";
  {
    auto in = OIIO::ImageInput::open(path.string());
    REQUIRE(in);
    // OpenImageIO reports the header's envmap = cube as this texture format.
    CHECK(in->spec().get_string_attribute("textureformat") == "CubeFace Environment");
  }
  const auto strip = files::read_image(path);
  REQUIRE(strip.width == n);
  REQUIRE(strip.height == 6 * n);
  // Bilinear interpolation of f in face coordinates (a, b), texel spacing h = 2/n, errs by at most
  // h^2/8 (|f_aa| + |f_bb|); each unit direction component has second derivatives of at most 1 in
  // a and b on a face, so |f_aa| + |f_bb| <= 6 A. That bounds every pixel off the face's edges.
  // An edge pixel mixes in texels of the next face (shaders/lib/cube_sampling.glsl), whose centres
  // lie up to h/2 along the edge from where the face's own grid continued (at a corner one more
  // stands in): with |grad f| <= sqrt 3 A per unit of a or b, at most sqrt 3 A h more.
  const double h = 2.0 / n, bound = h * h / 8 * 6 * amplitude, edge_bound = bound + std::sqrt(3.0) * amplitude * h;
  double worst = 0, worst_edge = 0, worst_gl_centres = 0;
  for (int face = 0; face < 6; ++face)
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c) {
        const double want = f(openexr_direction(face, c, r, n));
        const double error = std::abs(strip.pixels[(std::size_t(face) * n + r) * n + c] - want);
        const bool edge = c == 0 || r == 0 || c == n - 1 || r == n - 1;
        (edge ? worst_edge : worst) = std::max(edge ? worst_edge : worst, error);
        // What a mirrored copy of the GL texels (centres half a texel inside the face) puts there.
        const bool y_face = face == 2 || face == 3;
        const auto gl = io::gl_texel_direction(face, y_face ? c : n - 1 - c, y_face ? n - 1 - r : r, n);
        if (!edge) worst_gl_centres = std::max(worst_gl_centres, std::abs(f(gl) - want));
      }
  CHECK(worst <= bound);
  CHECK(worst_edge <= edge_bound);
  // The test tells the conventions apart: half a texel of shift errs by several bounds.
  CHECK(worst_gl_centres > 3 * bound);
  // The marker cover lands where OpenEXR's directions put it: on the third face of the strip.
  Exported e("exr-cube");
  REQUIRE(e.run.exit_code == 0);
  const auto marker = files::read_image(e.out.path / "cover_envcube.exr");
  for (int face = 0; face < 6; ++face) {
    INFO("face " << face);
    const auto centroid = bright_centroid(marker.pixels, kSize, 1, 0, 0, face * kSize, kSize, kSize);
    if (face != 2) {
      CHECK(centroid.count == 0);
      continue;
    }
    // Where OpenEXR's direction of a pixel is nearest the marker's.
    const auto m = marker_direction();
    double best = -2, bx = 0, by = 0;
    for (int r = 0; r < kSize; ++r)
      for (int c = 0; c < kSize; ++c) {
        const auto d = openexr_direction(face, c, r, kSize);
        const double dot = d[0] * m[0] + d[1] * m[1] + d[2] * m[2];
        if (dot > best) best = dot, bx = c, by = r;
      }
    CHECK(centroid.x == Approx(bx).epsilon(0).margin(kMarkerPixels + 0.5));
    CHECK(centroid.y == Approx(by).epsilon(0).margin(kMarkerPixels + 0.5));
  }
}

TEST_CASE("bench export prints each texel format's error within the bound of its format", "[export][cli]") {
  test::TemporaryDirectory cover{true};
  write_marker_cover(cover.path);
  const test::Run r = test::run("bench export " + cover.path.string());
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  // format -> {rms, max}, from the rows "format bits MB ms rms max written-by".
  std::map<std::string, std::pair<double, double>> errors;
  std::istringstream lines(r.output);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string first, second;
    words >> first >> second;
    if (second == "alpha" || second == "grey")
      first += " " + second;
    else
      words.seekg(0), words >> first;
    double bits = 0, megabytes = 0, ms = 0, rms = -1, max = -1;
    if (words >> bits >> megabytes >> ms >> rms >> max) errors[first] = {rms, max};
  }
  REQUIRE(errors.size() == 7);
  CHECK(errors["r32f"].second == 0.0);
  CHECK(errors["r16f"].second <= std::ldexp(1.0, -12));  // half an ulp of binary16 below 1
  CHECK(errors["r8"].second <= 0.5 / 255 + 1e-6);
  // The marker cover's blocks span at most 0.9: BC4 and BC3's alpha within a palette step of it
  // (0.9 / 7) plus rounding, the 4-entry colour blocks within 0.9 / 3 plus the 5-bit step.
  CHECK(errors["bc4"].second <= 0.9 / 7 + 1.5 / 255);
  CHECK(errors["bc3 alpha"].second <= 0.9 / 7 + 1.5 / 255);
  CHECK(errors["bc3 grey"].second <= 0.9 / 3 + 8.0 / 255);
  CHECK(errors["bc1 grey"].second <= 0.9 / 3 + 8.0 / 255);
  for (const auto& [format, error] : errors) CHECK(error.first <= error.second);
}

TEST_CASE("every cover export preset writes a README.txt naming the preset beside its files", "[export]") {
  for (const auto& preset : io::export_presets()) {
    if (preset.volume) continue;  // atlas and openvdb read volumes: their own tests read their README
    INFO(preset.name);
    Exported e(preset.name);
    REQUIRE(e.run.exit_code == 0);
    const std::string readme = test::read_file(e.out.path / "README.txt");
    CHECK_THAT(readme, Catch::Contains("preset " + preset.name) && Catch::Contains("linear"));
    // The command prints each file it wrote; every one exists. (The output holds stderr too, where
    // an export that runs past a second, as on a loaded machine, reports its progress.)
    std::istringstream lines(e.run.output);
    int files = 0;
    for (std::string line; std::getline(lines, line);) {
      if (line.rfind("export " + preset.name + ": ", 0) == 0) continue;
      CHECK(std::filesystem::is_regular_file(line));
      ++files;
    }
    CHECK(files >= 2);
  }
}

namespace {

// Face and (s, t) of direction d by the GL table (OpenGL 4.6, table 8.19), for the engines'
// face layouts; written here from the table, not from the writer's code.
struct FaceHit {
  int face;
  double s, t;
};
FaceHit gl_face_of(const std::array<double, 3>& d) {
  const double ax = std::abs(d[0]), ay = std::abs(d[1]), az = std::abs(d[2]);
  if (ax >= ay && ax >= az)
    return d[0] > 0 ? FaceHit{0, (-d[2] / ax + 1) / 2, (-d[1] / ax + 1) / 2}
                    : FaceHit{1, (d[2] / ax + 1) / 2, (-d[1] / ax + 1) / 2};
  if (ay >= az)
    return d[1] > 0 ? FaceHit{2, (d[0] / ay + 1) / 2, (d[2] / ay + 1) / 2}
                    : FaceHit{3, (d[0] / ay + 1) / 2, (-d[2] / ay + 1) / 2};
  return d[2] > 0 ? FaceHit{4, (d[0] / az + 1) / 2, (-d[1] / az + 1) / 2}
                  : FaceHit{5, (-d[0] / az + 1) / 2, (-d[1] / az + 1) / 2};
}

// Checks the marker in face `hit.face` of a layout `columns` faces wide, and nothing bright in
// the other faces.
void check_marker_in_layout(const core::ImageData& image, int columns, const FaceHit& hit) {
  REQUIRE(image.width == columns * kSize);
  REQUIRE(image.height == 6 / columns * kSize);
  for (int f = 0; f < 6; ++f) {
    INFO("face " << f);
    const auto c = bright_centroid(image.pixels, image.width, image.channels, 0, f % columns * kSize,
                                   f / columns * kSize, kSize, kSize);
    if (f != hit.face) {
      CHECK(c.count == 0);
      continue;
    }
    REQUIRE(c.count > 0);
    CHECK(c.x == Approx(hit.s * kSize - 0.5).epsilon(0).margin(kMarkerPixels));
    CHECK(c.y == Approx(hit.t * kSize - 0.5).epsilon(0).margin(kMarkerPixels));
  }
}

void check_no_gamma_chunk(const std::filesystem::path& png) {
  INFO(png.string());
  const std::string bytes = test::read_file(png);
  REQUIRE(bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0);
  for (const auto& type : png_chunks(bytes)) {
    CHECK(type != "gAMA");
    CHECK(type != "sRGB");
    CHECK(type != "iCCP");
  }
}

}  // namespace

TEST_CASE("export flightgear: eight bordered tiles whose inner 126/128 reassemble to the map with the marker in N3",
          "[export]") {
  Exported e("flightgear");
  REQUIRE(e.run.exit_code == 0);
  const int tile = io::flightgear_tile_size(kSize), border = tile / 128, content = tile - 2 * border;
  REQUIRE(tile == 128);
  core::ImageData mosaic{4 * content, 2 * content, 1, std::vector<float>(std::size_t(8) * content * content)};
  for (int h = 0; h < 2; ++h)
    for (int q = 0; q < 4; ++q) {
      const std::string name = std::string("clouds_") + (h ? "S" : "N") + std::to_string(q + 1) + ".png";
      INFO(name);
      check_no_gamma_chunk(e.out.path / name);
      const auto image = read_png_as_stored(e.out.path / name);
      REQUIRE(image.width == tile);
      REQUIRE(image.height == tile);
      REQUIRE(image.channels == 2);  // grey + alpha, as the shipped tiles
      const auto at = [&](int x, int y, int c) { return image.pixels[(std::size_t(y) * tile + x) * 2 + c]; };
      for (int y = 0; y < tile; ++y)
        for (int x = 0; x < tile; ++x) {
          if (at(x, y, 0) != 1.0f) FAIL("grey is not white at " << x << ", " << y);
          // The border repeats the nearest content pixel.
          const int cx = std::clamp(x, border, tile - 1 - border), cy = std::clamp(y, border, tile - 1 - border);
          if (at(x, y, 1) != at(cx, cy, 1)) FAIL("border pixel " << x << ", " << y << " is not its edge pixel");
        }
      for (int y = 0; y < content; ++y)
        for (int x = 0; x < content; ++x)
          mosaic.pixels[std::size_t(h * content + y) * mosaic.width + q * content + x] = at(x + border, y + border, 1);
    }
  check_equirect_marker(mosaic);
}

TEST_CASE(
    "export eve: DXT5 textures with mip chains, the marker where EVE's equirect and GetCubeCubeUV rules look, and "
    "configs EVE's node structure reads",
    "[export]") {
  Exported e("eve");
  REQUIRE(e.run.exit_code == 0);
  const auto dir = e.out.path / "GameData" / "nephele_clouds";
  // The marker in EVE's body frame: +Z longitude 0, +X 90 E, +Y north.
  const auto m = marker_direction();
  const std::array<double, 3> v{m[1], m[2], m[0]};
  {
    const auto image = read_dds_2d_dxt5(dir / "clouds_equirect.dds");
    REQUIRE(image.width == 4 * kSize);
    const double u = 0.5 + std::atan2(v[0], v[2]) / (2 * kPi), vv = std::acos(v[1]) / kPi;
    const auto c = bright_centroid(image.pixels, image.width, 4, 3, 0, 0, image.width, image.height);
    REQUIRE(c.count > 0);
    CHECK(c.x == Approx(u * image.width - 0.5).epsilon(0).margin(kMarkerPixels));
    CHECK(c.y == Approx(vv * image.height - 0.5).epsilon(0).margin(kMarkerPixels));  // v = 0 is the first row
    CHECK(image.pixels[0] == 1.0f);                                                  // RGB white
  }
  // GetCubeCubeUV (cubeMap.cginc), transcribed: the face and its uv.
  const double ax = std::abs(v[0]), ay = std::abs(v[1]), az = std::abs(v[2]);
  const bool zx = az >= ax, ny = ay <= std::max(ax, az);
  const double s = (ny ? (zx ? v[2] : v[0]) : v[1]) > 0 ? 1 : -1;
  std::array<double, 3> dc = !ny  ? std::array<double, 3>{v[1], v[0], s * v[2]}
                             : zx ? std::array<double, 3>{v[2], s * v[0], -v[1]}
                                  : std::array<double, 3>{v[0], -s * v[2], -v[1]};
  const double u = 0.5 * dc[1] / std::abs(dc[0]) + 0.5, vv = 0.5 * dc[2] / std::abs(dc[0]) + 0.5;
  const std::string hit = std::string(ny ? (zx ? "z" : "x") : "y") + (s > 0 ? "p" : "n");
  // EVE's TextureConfig manager reads each child node of EVE_TEXTURE_CONFIG; a TEX_CUBE_6 object
  // names its six faces by GameData paths without extension.
  const ConfigNode textures = parse_config(test::read_file(dir / "nephele_clouds_textures.cfg"));
  const ConfigNode* texture_config = textures.node("EVE_TEXTURE_CONFIG");
  REQUIRE(texture_config != nullptr);
  REQUIRE(texture_config->nodes.size() == 1);
  const ConfigNode& cube = texture_config->nodes[0];
  CHECK(cube.value("type") == "TEX_CUBE_6");
  CHECK(texture_config->values.empty());  // keys outside an object are never read
  for (const char* key : {"xn", "xp", "yn", "yp", "zn", "zp"}) {
    INFO(key);
    const std::string path = cube.value(std::string("tex") + char(std::toupper(key[0])) + key[1]);
    REQUIRE_FALSE(path.empty());
    const auto image = read_dds_2d_dxt5(e.out.path / "GameData" / (path + ".dds"));
    REQUIRE(image.width == kSize);
    const auto c = bright_centroid(image.pixels, kSize, 4, 3, 0, 0, kSize, kSize);
    if (hit != key) {
      CHECK(c.count == 0);
      continue;
    }
    REQUIRE(c.count > 0);
    CHECK(c.x == Approx(u * kSize - 0.5).epsilon(0).margin(kMarkerPixels));
    CHECK(c.y == Approx(vv * kSize - 0.5).epsilon(0).margin(kMarkerPixels));
  }
  CHECK(hit == "xp");  // 30 N 60 E: EVE's +X (90 E) face
  // The cloud layer: an object of EVE_CLOUDS whose _MainTex is the cube by name, type CubeMap
  // (TextureWrapper.isValid looks a CubeMap value up among the texture configs' names).
  const ConfigNode clouds = parse_config(test::read_file(dir / "nephele_clouds_clouds.cfg"));
  REQUIRE(clouds.node("EVE_CLOUDS") != nullptr);
  REQUIRE(clouds.node("EVE_CLOUDS")->nodes.size() == 1);
  const ConfigNode& layer = clouds.node("EVE_CLOUDS")->nodes[0];
  CHECK(layer.value("body") == "Kerbin");
  CHECK_FALSE(layer.value("altitude").empty());
  REQUIRE(layer.node("settings") != nullptr);
  const ConfigNode* main_texture = layer.node("settings")->node("_MainTex");
  REQUIRE(main_texture != nullptr);
  CHECK(main_texture->value("value") == cube.value("name"));
  CHECK(main_texture->value("type") == "CubeMap");
  CHECK(layer.node("layer2D") != nullptr);
  // The detail texture the layer names: it tiles (the step across its wrap is no larger than
  // between neighbours inside) and has the statistics of EVE's shipped detail (grey 0.85, sd 0.05).
  const std::string detail_path = layer.node("settings")->value("_DetailTex");
  REQUIRE_FALSE(detail_path.empty());
  const auto detail = read_dds_2d_dxt5(e.out.path / "GameData" / (detail_path + ".dds"));
  const int n = detail.width;
  REQUIRE(detail.height == n);
  double sum = 0, squares = 0, inner_step = 0, wrap_step = 0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const double g = detail.pixels[(std::size_t(y) * n + x) * 4 + 1];
      sum += g, squares += g * g;
      const double right = detail.pixels[(std::size_t(y) * n + (x + 1) % n) * 4 + 1];
      (x == n - 1 ? wrap_step : inner_step) += std::abs(right - g);
    }
  const double mean = sum / (double(n) * n);
  CHECK(mean == Approx(0.85).margin(0.01));
  CHECK(std::sqrt(squares / (double(n) * n) - mean * mean) == Approx(0.05).margin(0.01));
  CHECK(wrap_step / n <= 2.0 * inner_step / (double(n) * (n - 1)));
}

TEST_CASE("export unity: the lat-long maps carry the marker, HDRP's in red, and the 6x1 strip is the reflected cube",
          "[export]") {
  Exported e("unity");
  REQUIRE(e.run.exit_code == 0);
  check_equirect_marker(files::read_image(e.out.path / "cover_latlong.exr"));
  check_equirect_marker(files::read_image(e.out.path / "cover_latlong_16.png"));
  const auto hdrp = files::read_image(e.out.path / "cover_latlong_hdrp.png");
  REQUIRE(hdrp.channels == 3);
  check_equirect_marker(hdrp, 0);
  CHECK(bright_centroid(hdrp.pixels, hdrp.width, 3, 1, 0, 0, hdrp.width, hdrp.height).count == 0);
  for (const char* png : {"cover_latlong_16.png", "cover_latlong_hdrp.png", "cover_cube_6x1.png"})
    check_no_gamma_chunk(e.out.path / png);
  // Unity's frame: +X longitude 0, +Y north, +Z 90 E (left-handed); its sampler uses the GL table.
  const auto m = marker_direction();
  const auto hit = gl_face_of({m[0], m[2], m[1]});
  CHECK(hit.face == 4);                                          // Unity +Z: 90 E is nearest to 60 E
  CHECK(io::AxisMap{{0, 2, 1}, {1, 1, 1}}.determinant() == -1);  // the writer's Unity axes: a reflection
  check_marker_in_layout(files::read_image(e.out.path / "cover_cube_6x1.png"), 6, hit);
}

TEST_CASE("export godot: 2x3 and 6x1 cubes rotated into Godot's Y-up frame and a panorama with the marker",
          "[export]") {
  Exported e("godot");
  REQUIRE(e.run.exit_code == 0);
  // Godot's frame: +Z longitude 0, +X 90 E, +Y north (right-handed, a rotation of nephele's).
  const auto m = marker_direction();
  const auto hit = gl_face_of({m[1], m[2], m[0]});
  CHECK(hit.face == 0);                                         // Godot +X
  CHECK(io::AxisMap{{2, 0, 1}, {1, 1, 1}}.determinant() == 1);  // the writer's Godot axes: a rotation
  check_marker_in_layout(files::read_image(e.out.path / "cover_cube_2x3.png"), 2, hit);
  check_marker_in_layout(files::read_image(e.out.path / "cover_cube_6x1.png"), 6, hit);
  check_equirect_marker(files::read_image(e.out.path / "cover_panorama.exr"));
  for (const char* png : {"cover_cube_2x3.png", "cover_cube_6x1.png", "cover_panorama_16.png"})
    check_no_gamma_chunk(e.out.path / png);
}

TEST_CASE("export unreal: linear EXR and 16-bit PNG maps with the marker where the README's UV formula looks",
          "[export]") {
  Exported e("unreal");
  REQUIRE(e.run.exit_code == 0);
  for (const char* name : {"cover_equirect.exr", "cover_equirect_16.png"}) {
    INFO(name);
    const auto image = files::read_image(e.out.path / name);
    check_equirect_marker(image);
    // The README's formula in Unreal's axes (X forward, Y right, Z up): Y = -(nephele Y).
    const auto m = marker_direction();
    const double u = 0.5 + std::atan2(-(-m[1]), m[0]) / (2 * kPi);
    const auto c = bright_centroid(image.pixels, image.width, image.channels, 0, 0, 0, image.width, image.height);
    CHECK(c.x == Approx(u * image.width - 0.5).epsilon(0).margin(kMarkerPixels));
  }
  check_no_gamma_chunk(e.out.path / "cover_equirect_16.png");
  const std::string readme = test::read_file(e.out.path / "README.txt");
  CHECK_THAT(readme, Catch::Contains("u = 0.5 + atan2(-y, x)/(2 pi)"));
}

TEST_CASE("export blender: the equirect with the marker and a World script whose Mapping scales Y by -1", "[export]") {
  Exported e("blender");
  REQUIRE(e.run.exit_code == 0);
  check_equirect_marker(files::read_image(e.out.path / "cover_equirect.exr"));
  const std::string script = test::read_file(e.out.path / "nephele_world.py");
  CHECK_THAT(script, Catch::Contains("(1.0, -1.0, 1.0)") && Catch::Contains("Non-Color"));
}

TEST_CASE("export refuses up front a preset whose image would exceed 16384 pixels, naming the largest face size",
          "[fast][export]") {
  const auto& equirect = io::find_export_preset("equirect");
  CHECK_NOTHROW(io::check_texture_limit(equirect, 4096));
  try {
    io::check_texture_limit(equirect, 4097);
    FAIL("no error for a 16388-pixel equirect");
  } catch (const core::InputError& error) {
    CHECK_THAT(error.what(), Catch::Contains("COVER_DIR") && Catch::Contains("4096") && Catch::Contains("16384"));
  }
  CHECK_NOTHROW(io::check_texture_limit(io::find_export_preset("unity"), 2730));
  CHECK_THROWS_AS(io::check_texture_limit(io::find_export_preset("unity"), 2731), core::InputError);
  CHECK_THROWS_AS(io::check_texture_limit(io::find_export_preset("godot"), 2731), core::InputError);
  // Tiles and cube faces stay within the limit for every face size generate makes.
  CHECK(io::flightgear_tile_size(16384) == 16384);
  CHECK_NOTHROW(io::check_texture_limit(io::find_export_preset("flightgear"), 16384));
  CHECK_NOTHROW(io::check_texture_limit(io::find_export_preset("ktx2"), 16384));
}

// A real client: Blender renders the World that the preset's own script sets up, looking at the
// marker and at its mirror images (scripts/blender_probe.py). Blender is not a CI package (see
// docs/export.md, "blender"): without it on PATH the test says so and passes.
TEST_CASE(
    "export blender: Blender renders the marker at 30 N 60 E through the preset's World, and at 60 W without Y = -1",
    "[optional][export][blender]") {
  if (std::system("command -v blender > /dev/null 2>&1") != 0) {
    test::skip_case("blender is not installed (apt-get install --no-install-recommends blender)");
    return;
  }
  Exported e("blender");
  REQUIRE(e.run.exit_code == 0);
  const auto run = test::run_command("blender -b --factory-startup --python-exit-code 1 --python " +
                                     std::string(NEPHELE_SOURCE_DIR) + "/scripts/blender_probe.py -- " +
                                     (e.out.path / "nephele_world.py").string() + " " +
                                     (e.out.path / "cover_equirect.exr").string() + " 30 60 30 -60 -30 60 -30 -60");
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  std::istringstream lines(run.output);
  std::map<std::string, double> probes;  // "scale lat lon" -> value
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("PROBE ", 0) != 0) continue;
    std::istringstream fields(line.substr(6));
    std::string scale, lat, lon;
    double value;
    fields >> scale >> lat >> lon >> value;
    probes[scale + " " + lat + " " + lon] = value;
  }
  REQUIRE(probes.size() == 8);
  // The cover is 1 inside the marker and 0.1 elsewhere; a 1-degree view inside the 5.7-degree
  // marker sees 1 up to the bilinear blur, outside it 0.1: 0.5 separates them.
  CHECK(probes["-1 30 60"] > 0.5);
  CHECK(probes["-1 30 -60"] < 0.5);
  CHECK(probes["-1 -30 60"] < 0.5);
  CHECK(probes["-1 -30 -60"] < 0.5);
  // Without the reflection Blender shows the map mirrored: the marker at 60 W.
  CHECK(probes["1 30 60"] < 0.5);
  CHECK(probes["1 30 -60"] > 0.5);
}

TEST_CASE("generate --export runs the presets into export/NAME of the same set, and refuses an unknown one before work",
          "[export][cli]") {
  test::TemporaryDirectory out;
  const auto r =
      test::run("generate --size 16 --iterations 5 --files faces --export flightgear,godot --out " + out.path.string());
  REQUIRE(r.exit_code == 0);
  CHECK(std::filesystem::is_regular_file(out.path / "cover_px.exr"));
  for (const char* file :
       {"export/flightgear/clouds_N1.png", "export/flightgear/clouds_S4.png", "export/flightgear/README.txt",
        "export/godot/cover_cube_2x3.png", "export/godot/README.txt"})
    CHECK(std::filesystem::is_regular_file(out.path / file));
  const auto strip = files::read_image(out.path / "export/godot/cover_cube_6x1.png");
  CHECK(strip.width == 6 * 16);  // made from the generated 16^2 faces
  test::TemporaryDirectory bad;
  const auto refused = test::run("generate --size 16 --iterations 5 --export godot,blue --out " + bad.path.string());
  CHECK(refused.exit_code == 2);
  CHECK_THAT(refused.output, Catch::Contains("--export") && Catch::Contains("blue"));
  CHECK_FALSE(std::filesystem::exists(bad.path / "cover.json"));
  const auto too_wide = test::run("generate --size 4097 --export equirect --out " + bad.path.string());
  CHECK(too_wide.exit_code == 2);
  CHECK_THAT(too_wide.output, Catch::Contains("16384"));
}

// FlightGear's shipped cloud tiles (Debian flightgear-data-models, optional): the grey channel
// multiplies the light when Earthview's overlay is off (Shaders/planet-cloudlayer.frag), so the
// exported tiles must carry the grey the shipped ones carry for a given alpha, or our clouds come
// out brighter or darker than FlightGear's. Mean grey per alpha bin of width 0.1 over the eight
// shipped tiles, compared bin by bin with the export of the marker cover (alpha 0.1 and 1).
TEST_CASE("export flightgear: the tiles' grey follows the shipped tiles' grey for each alpha",
          "[optional][export][flightgear]") {
  const std::filesystem::path textures = "/usr/share/games/flightgear/Models/Astro/Textures";
  if (!std::filesystem::exists(textures / "clouds_N1.png")) {
    test::skip_case("FlightGear's models are not installed (apt-get install flightgear-data-models)");
    return;
  }
  const auto grey_by_alpha = [](const std::filesystem::path& folder) {
    std::array<double, 10> sum{}, count{};
    for (const char* tile : {"N1", "N2", "N3", "N4", "S1", "S2", "S3", "S4"}) {
      const auto image = read_png_as_stored(folder / (std::string("clouds_") + tile + ".png"));
      REQUIRE(image.channels == 2);  // grey + alpha
      for (std::size_t i = 0; i < image.pixels.size(); i += 2) {
        const float alpha = image.pixels[i + 1];
        if (alpha <= 0.0f) continue;  // invisible: its grey is arbitrary in the shipped tiles
        const int bin = std::min(9, int(alpha * 10));
        sum[bin] += image.pixels[i], count[bin] += 1;
      }
    }
    std::array<double, 10> mean{};
    for (int b = 0; b < 10; ++b) mean[b] = count[b] > 0 ? sum[b] / count[b] : -1;
    return mean;
  };
  const auto shipped = grey_by_alpha(textures);
  Exported e("flightgear");
  REQUIRE(e.run.exit_code == 0);
  const auto ours = grey_by_alpha(e.out.path);
  int compared = 0;
  for (int b = 0; b < 10; ++b) {
    if (shipped[b] < 0 || ours[b] < 0) continue;
    INFO("alpha in [" << b / 10.0 << ", " << (b + 1) / 10.0 << ")");
    CHECK(ours[b] == Approx(shipped[b]).margin(0.05));
    ++compared;
  }
  CHECK(compared >= 2);  // the marker cover's two levels
}

// FlightGear's own models (Debian flightgear-data-models, optional): every vertex of the
// shipped clouds_*.ac samples the exported tile at its UV. The models' frame (AC3D, y up):
// latitude asin(y), longitude atan2(-x, -z); u = 1/128 + (126/128) lon/90 from the tile's west
// edge, and v (0 at the bottom row) runs from 1/128 at the equator of N tiles (127/128 for S)
// at 88.61 degrees per unit: the meshes' last ring is at 87.2 degrees before the pole fan, so
// FlightGear draws every Earthview texture, the shipped ones included, with latitudes scaled
// by 87.23/90. The bright vertices must sit at 60 E and 30 N times that scale.
TEST_CASE("export flightgear: through the UVs of FlightGear's shipped cloud models the marker lands at 60 E, 30 N",
          "[optional][export][flightgear]") {
  const std::filesystem::path astro = "/usr/share/games/flightgear/Models/Astro";
  if (!std::filesystem::exists(astro / "clouds_N1.ac")) {
    test::skip_case("FlightGear's models are not installed (apt-get install flightgear-data-models)");
    return;
  }
  Exported e("flightgear");
  REQUIRE(e.run.exit_code == 0);
  double lat_sum = 0, lon_sum = 0;
  int bright = 0, vertices = 0;
  for (const char* hemisphere : {"N", "S"})
    for (int q = 1; q <= 4; ++q) {
      const std::string name = std::string("clouds_") + hemisphere + std::to_string(q);
      const auto tile = read_png_as_stored(e.out.path / (name + ".png"));
      std::istringstream ac(test::read_file(astro / (name + ".ac")));
      // AC3D: the object named `name` lists numvert positions, then surfaces whose refs lines
      // are "vertex u v".
      std::vector<std::array<double, 3>> points;
      bool ours = false;
      for (std::string line; std::getline(ac, line);) {
        std::istringstream words(line);
        std::string word;
        words >> word;
        if (word == "name") ours = line == "name \"" + name + "\"";
        if (!ours) continue;
        if (word == "numvert") {
          int n;
          words >> n;
          points.resize(n);
          for (auto& p : points) ac >> p[0] >> p[1] >> p[2];
        } else if (word == "refs") {
          int n;
          words >> n;
          for (int k = 0; k < n; ++k) {
            int index;
            double u, v;
            ac >> index >> u >> v;
            const auto& p = points.at(index);
            const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
            const double lat = std::asin(p[1] / r) * 180 / kPi, lon = std::atan2(-p[0], -p[2]) * 180 / kPi;
            const int x = std::clamp(int(u * tile.width), 0, tile.width - 1);
            const int y = std::clamp(int((1 - v) * tile.height), 0, tile.height - 1);
            ++vertices;
            if (tile.pixels[(std::size_t(y) * tile.width + x) * 2 + 1] > 0.5f) lat_sum += lat, lon_sum += lon, ++bright;
          }
        }
      }
    }
  CHECK(vertices == 8 * 4356);
  REQUIRE(bright > 0);
  // The mesh's vertices are 2.8 degrees apart: the centroid of the references inside the
  // 5.7-degree marker (a vertex once per surface using it) is within about half a spacing of
  // its centre; a mirrored or misplaced tile puts it 60 or more degrees away.
  CHECK(lon_sum / bright == Approx(kLon).epsilon(0).margin(1.5));
  CHECK(lat_sum / bright == Approx(kLat * 87.23 / 90).epsilon(0).margin(1.5));
}

// The other Blender check: `nephele model`'s density.vdb imported as a Volume object. Blender
// must find the grid `density` as floats, and its bounds (of OpenVDB's active 8^3 leaf nodes,
// voxel centre to centre) must be the raw volume's nonzero voxels rounded out to leaves on each
// axis: the towering example is taller than wide, so a swapped axis (z up) or a wrong voxel
// size fails.
TEST_CASE("model's density.vdb opens in Blender as a Volume with the grid density where the raw volume has density",
          "[optional][export][blender]") {
  if (std::system("command -v blender > /dev/null 2>&1") != 0) {
    test::skip_case("blender is not installed (apt-get install --no-install-recommends blender)");
    return;
  }
  if (!io::vdb_available()) {
    test::skip_case("nephele was built without OpenVDB (libopenvdb-dev)");
    return;
  }
  test::TemporaryDirectory out;
  constexpr int n = 32;
  constexpr double extent = 6000, s = extent / n;
  REQUIRE(test::run("model --example towering --size 32 --extent 6000 --no-preview --quiet --out " + out.path.string())
              .exit_code == 0);
  const std::string raw = test::read_file(out.path / "density.raw");
  REQUIRE(raw.size() == std::size_t(4) * n * n * n);
  std::array<int, 3> low{n, n, n}, high{-1, -1, -1};
  for (int i = 0; i < n * n * n; ++i) {
    float v;
    std::memcpy(&v, raw.data() + 4 * std::size_t(i), 4);
    if (!(v > 0)) continue;
    const int c[3] = {i % n, i / n % n, i / (n * n)};
    for (int k = 0; k < 3; ++k) low[k] = std::min(low[k], c[k]), high[k] = std::max(high[k], c[k]);
  }
  REQUIRE(high[0] >= 0);
  const auto run = test::run_command("blender -b --factory-startup --python-exit-code 1 --python " +
                                     std::string(NEPHELE_SOURCE_DIR) + "/scripts/blender_volume_probe.py -- " +
                                     (out.path / "density.vdb").string());
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  CHECK_THAT(run.output, Catch::Contains("GRID density FLOAT 1"));
  const auto at = run.output.find("BOUNDS ");
  REQUIRE(at != std::string::npos);
  std::istringstream bounds(run.output.substr(at + 7));
  double b[6];
  for (double& x : b) bounds >> x;
  // The nonzero voxels' range rounded out to whole leaves, voxel centre to centre: what
  // Blender 3.4 reports (observed), exact up to printing.
  for (int k = 0; k < 3; ++k) {
    INFO("axis " << k);
    CHECK(b[k] == Approx(s * (low[k] / 8 * 8 + 0.5)).epsilon(0).margin(1e-3));
    CHECK(b[3 + k] == Approx(s * (high[k] / 8 * 8 + 7 + 0.5)).epsilon(0).margin(1e-3));
  }
}

TEST_CASE("export atlas: a noise volume's slices in rows and columns, every texel where the layout says", "[export]") {
  test::TemporaryDirectory dir(true);
  REQUIRE(test::run("noise --width 16 --height 16 --depth 10 --cells 8 --channels rg --quiet --out " +
                    (dir.path / "n.raw").string())
              .exit_code == 0);
  test::TemporaryDirectory out;
  const auto r = test::run("export " + (dir.path / "n.json").string() + " --preset atlas --out " + out.path.string());
  REQUIRE(r.exit_code == 0);
  const std::string raw = test::read_file(dir.path / "n.raw");
  REQUIRE(raw.size() == 4u * 16 * 16 * 10 * 2);
  const auto atlas = files::read_image(out.path / "volume_atlas.exr");
  const auto png = read_png_as_stored(out.path / "volume_atlas_16.png");
  check_no_gamma_chunk(out.path / "volume_atlas_16.png");
  REQUIRE(atlas.width == 4 * 16);   // ceil(sqrt(10)) = 4 columns
  REQUIRE(atlas.height == 3 * 16);  // 3 rows
  REQUIRE(atlas.channels == 2);
  REQUIRE(png.channels == 2);
  int wrong = 0;
  for (int z = 0; z < 10; ++z)
    for (int y = 0; y < 16; ++y)
      for (int x = 0; x < 16; ++x)
        for (int c = 0; c < 2; ++c) {
          float v;
          std::memcpy(&v, raw.data() + 4 * ((((std::size_t(z) * 16 + y) * 16 + x) * 2) + c), 4);
          const std::size_t at = ((std::size_t(z / 4) * 16 + y) * atlas.width + std::size_t(z % 4) * 16 + x) * 2 + c;
          // The 16-bit PNG quantises to 1/65535: half a step.
          if (atlas.pixels[at] != v || std::abs(png.pixels[at] - v) > 0.5f / 65535 + 1e-7f) ++wrong;
        }
  CHECK(wrong == 0);
  CHECK_THAT(test::read_file(out.path / "README.txt"),
             Catch::Contains("preset atlas") && Catch::Contains("Columns 4, Rows 3") && Catch::Contains("data"));
}

TEST_CASE("export atlas keeps every side within 16384 pixels: 160^3 in 13 x 13, and refuses what cannot fit",
          "[fast][export]") {
  const auto g = io::atlas_grid(160, 160, 160);
  CHECK(g.columns == 13);
  CHECK(g.rows == 13);
  CHECK(g.columns * 160 <= io::max_texture_edge);
  const auto wide = io::atlas_grid(4096, 64, 64);  // only 4 slices fit across
  CHECK(wide.columns == 4);
  CHECK(wide.rows == 16);
  CHECK_THROWS_AS(io::atlas_grid(16384, 16384, 2), core::InputError);
}

TEST_CASE("export openvdb: a model's density.json becomes a FOG grid density with its voxel size and every voxel",
          "[export]") {
  if (!io::vdb_available()) {
    test::skip_case("nephele was built without OpenVDB (libopenvdb-dev)");
    return;
  }
  test::TemporaryDirectory model, out;
  REQUIRE(test::run("model --example fair-weather --size 16 --extent 3200 --no-preview --quiet --out " +
                    model.path.string())
              .exit_code == 0);
  const auto r =
      test::run("export " + (model.path / "density.json").string() + " --preset openvdb --out " + out.path.string());
  REQUIRE(r.exit_code == 0);
  const auto vdb = io::read_vdb((out.path / "volume.vdb").string());
  CHECK(vdb.grids == std::vector<std::string>{"density"});
  CHECK(vdb.fog_volume);
  CHECK(vdb.background == 0.0f);
  CHECK(vdb.voxel_size == Approx(200.0).epsilon(0).margin(1e-9));
  CHECK(vdb.origin[0] == Approx(100.0).epsilon(0).margin(1e-9));  // voxel (0, 0, 0) centred at s/2
  const std::string raw = test::read_file(model.path / "density.raw");
  long nonzero = 0;
  for (std::size_t i = 0; i + 4 <= raw.size(); i += 4) {
    float v;
    std::memcpy(&v, raw.data() + i, 4);
    nonzero += v > 0;
  }
  CHECK(vdb.active == nonzero);
  int wrong = 0;
  for (const auto& voxel : vdb.values) {
    float v;
    std::memcpy(&v, raw.data() + 4 * ((std::size_t(voxel.z) * 16 + voxel.y) * 16 + voxel.x), 4);
    wrong += v != voxel.value;
  }
  CHECK(wrong == 0);
  CHECK_THAT(test::read_file(out.path / "README.txt"), Catch::Contains("preset openvdb") && Catch::Contains("density"));
  test::TemporaryDirectory bad;
  const auto refused = test::run("export " + (model.path / "model.cloud.json").string() + " --preset openvdb --out " +
                                 bad.path.string());
  CHECK(refused.exit_code == 2);
  CHECK_THAT(refused.output, Catch::Contains("VOLUME"));
}

}  // namespace nephele

namespace nephele {

TEST_CASE("celestia beyond one texture: a virtual texture whose level K holds 2^(K+1) x 2^K tiles of the map",
          "[export]") {
  test::test_context();
  // A smooth cover with a bright cap north of 60 degrees, so that a tile's place shows.
  const int n = 64, tile = 64;
  io::CoverFaces faces{n, std::vector<float>(6 * static_cast<size_t>(n) * n)};
  for (int f = 0; f < 6; ++f)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const glm::vec3 d = glm::normalize(glsl::texel_direction(f, i, j, n));
        faces.texels[(static_cast<size_t>(f) * n + j) * n + i] = d.z > 0.866f ? 1.0f : 0.25f + 0.2f * d.x;
      }
  test::TemporaryDirectory out(true);
  files::OutputSet set(out.path, files::OutputSet::Scope::directory);
  io::ExportOptions options;
  options.name = "vt";
  options.celestia_tile = tile;
  options.resample_equirect = cover::equirect_from_faces;
  io::write_export(set, io::find_export_preset("celestia"), faces, options);
  set.commit();
  const std::filesystem::path hires = out.path / "extras/vt/textures/hires";
  const std::string ctx = test::read_file(hires / "vt.ctx");
  CHECK_THAT(ctx, Catch::Contains("VirtualTexture") && Catch::Contains("ImageDirectory \"vt\"") &&
                      Catch::Contains("BaseSplit 0") && Catch::Contains("TileSize 64") &&
                      Catch::Contains("TileType \"dds\""));
  CHECK_THAT(test::read_file(out.path / "extras/vt/vt.ssc"), Catch::Contains("CloudMap \"vt.ctx\""));
  // 4 n = 256 texels wide: level 0 is 128 wide (2 x 1 tiles), level 1 256 (4 x 2), no level 2.
  CHECK_FALSE(std::filesystem::exists(hires / "vt/level2"));
  for (int level = 0; level < 2; ++level) {
    const int width = tile << (level + 1), height = width / 2, face = width / 4;
    // The level's map: the cube box-filtered to a quarter of its width per face, resampled.
    const std::vector<float> expected =
        cover::equirect_from_faces(face, io::reduced_faces(n, faces.texels, face), width, height);
    int count = 0;
    double worst = 0.0;
    for (const auto& entry : std::filesystem::directory_iterator(hires / ("vt/level" + std::to_string(level)))) {
      ++count;
      int u = -1, v = -1;
      REQUIRE(std::sscanf(entry.path().filename().c_str(), "tx_%d_%d.dds", &u, &v) == 2);
      REQUIRE(u < (2 << level));
      REQUIRE(v < (1 << level));
      const std::string bytes = test::read_file(entry.path());
      const test::DdsFile dds = test::read_dds(bytes);
      CHECK(dds.four_cc == "DXT5");
      CHECK(dds.width == static_cast<unsigned>(tile));
      CHECK(dds.mip_count == 7);  // 64 down to 1
      const std::vector<float> rgba = test::decode_stored_image(
          test::StoredFormat::bc3, reinterpret_cast<const unsigned char*>(bytes.data()) + dds.data_offset, tile, tile);
      for (int y = 0; y < tile; ++y)
        for (int x = 0; x < tile; ++x) {
          const float want = expected[static_cast<size_t>(v * tile + y) * width + u * tile + x];
          worst = std::max(worst, double(std::abs(rgba[(static_cast<size_t>(y) * tile + x) * 4 + 3] - want)));
        }
    }
    INFO("level " << level);
    CHECK(count == (2 << level) * (1 << level));
    // BC3's alpha: 8 levels between a block's extremes, 1/14 of their span at most, plus the
    // 8-bit rounding and the CPU twin's float rounding; the cap's edge spans 0 to 1 in a block.
    CHECK(worst <= 1.0 / 14.0 + 1.0 / 255.0 + 1e-4);
  }
}

TEST_CASE("export flightgear beyond the GPU's faces: tiles sampled on the CPU equal the GPU pass's to an 8-bit step",
          "[export]") {
  test::test_context();
  const int n = 64;
  io::CoverFaces faces{n, std::vector<float>(6 * static_cast<size_t>(n) * n)};
  for (int f = 0; f < 6; ++f)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const glm::vec3 d = glm::normalize(glsl::texel_direction(f, i, j, n));
        faces.texels[(static_cast<size_t>(f) * n + j) * n + i] = 0.5f + 0.45f * std::sin(5.0f * d.x + 3.0f * d.z);
      }
  io::ExportOptions options;
  options.resample_equirect = cover::equirect_from_faces;
  const auto export_tiles = [&](int gpu_faces) {
    options.gpu_equirect_faces = gpu_faces;
    auto out = std::make_unique<test::TemporaryDirectory>(true);
    files::OutputSet set(out->path, files::OutputSet::Scope::directory);
    io::write_export(set, io::find_export_preset("flightgear"), faces, options);
    set.commit();
    return out;
  };
  const auto gpu = export_tiles(4096), cpu = export_tiles(0);
  // The CPU twin rounds its own way (5.6e-6 at 256, docs/scale.md): a value that close to an
  // 8-bit rounding boundary may land one step off, about 2 x 5.6e-6 x 255 = 0.3 % of the pixels.
  std::size_t differing = 0, pixels = 0;
  float worst = 0.0f;
  for (const char* name : {"clouds_N1.png", "clouds_N3.png", "clouds_S2.png", "clouds_S4.png"}) {
    INFO(name);
    const core::ImageData a = read_png_as_stored(gpu->path / name), b = read_png_as_stored(cpu->path / name);
    REQUIRE(a.width == b.width);
    REQUIRE(a.pixels.size() == b.pixels.size());
    for (std::size_t k = 0; k < a.pixels.size(); ++k) {
      worst = std::max(worst, std::abs(a.pixels[k] - b.pixels[k]));
      differing += a.pixels[k] != b.pixels[k];
    }
    pixels += a.pixels.size();
  }
  CHECK(worst <= 1.0f / 255.0f + 1e-6f);
  CHECK(double(differing) <= 0.01 * double(pixels));
}

}  // namespace nephele
