// files::encode_image's PNG options, checked by a reader written here from the PNG and zlib
// specifications (W3C PNG 2nd edition, RFC 1950/1951): at zlib level 0 the deflate stream is
// made of stored blocks, so each row's filter-type byte can be read without inflating.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "files/image_files.hpp"

namespace nephele {
namespace {

std::uint32_t big_endian32(const unsigned char* p) {
  return (std::uint32_t(p[0]) << 24) | (std::uint32_t(p[1]) << 16) | (std::uint32_t(p[2]) << 8) | p[3];
}

// The concatenated IDAT payloads of a PNG file (the zlib stream).
std::vector<unsigned char> idat_stream(const std::vector<unsigned char>& png) {
  const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  REQUIRE(png.size() > 8);
  REQUIRE(std::equal(signature, signature + 8, png.begin()));
  std::vector<unsigned char> stream;
  for (size_t at = 8; at + 12 <= png.size();) {
    const std::uint32_t length = big_endian32(&png[at]);
    const std::string type(png.begin() + static_cast<std::ptrdiff_t>(at + 4),
                           png.begin() + static_cast<std::ptrdiff_t>(at + 8));
    REQUIRE(at + 12 + length <= png.size());
    if (type == "IDAT")
      stream.insert(stream.end(), png.begin() + static_cast<std::ptrdiff_t>(at + 8),
                    png.begin() + static_cast<std::ptrdiff_t>(at + 8 + length));
    at += 12 + length;
  }
  return stream;
}

// The filtered rows of a zlib stream of stored blocks only (BTYPE 00), as one byte string.
std::vector<unsigned char> stored_payload(const std::vector<unsigned char>& zlib) {
  REQUIRE(zlib.size() > 2);
  REQUIRE((zlib[0] & 0x0F) == 8);  // CM = deflate
  std::vector<unsigned char> data;
  size_t at = 2;
  bool final_block = false;
  while (!final_block) {
    REQUIRE(at + 5 <= zlib.size());
    final_block = (zlib[at] & 1) != 0;
    REQUIRE(((zlib[at] >> 1) & 3) == 0);  // stored: the header's other bits pad to the byte
    const unsigned length = zlib[at + 1] | (unsigned(zlib[at + 2]) << 8);
    const unsigned complement = zlib[at + 3] | (unsigned(zlib[at + 4]) << 8);
    REQUIRE((length ^ complement) == 0xFFFFu);
    REQUIRE(at + 5 + length <= zlib.size());
    data.insert(data.end(), zlib.begin() + static_cast<std::ptrdiff_t>(at + 5),
                zlib.begin() + static_cast<std::ptrdiff_t>(at + 5 + length));
    at += 5 + length;
  }
  return data;
}

// A one-channel image whose rows differ, so that libpng's own choice is not always one filter.
core::ImageData test_image(int width, int height) {
  core::ImageData image{width, height, 1, std::vector<float>(static_cast<size_t>(width) * height)};
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i)
      image.pixels[static_cast<size_t>(j) * width + i] =
          j % 3 == 0 ? 0.5f : static_cast<float>((i * 37 + j * 11) % 256) / 255.0f;
  return image;
}

}  // namespace

TEST_CASE("a PNG with png_filters set filters every row with that one filter and keeps the pixels", "[fast][io][png]") {
  const int width = 64, height = 24;
  const core::ImageData image = test_image(width, height);
  files::ImageEncoding encoding = files::png_encoding(8);
  encoding.png_compression_level = 0;  // stored blocks: the filtered rows lie in the file as they are
  encoding.png_filters = files::png_filter_average;
  const std::vector<unsigned char> rows =
      stored_payload(idat_stream(files::encode_image(image, encoding, "average.png")));
  // Each row: its filter-type byte, then one byte per pixel. Type 3 is Average (PNG 9.2).
  REQUIRE(rows.size() == static_cast<size_t>(height) * (width + 1));
  for (int j = 0; j < height; ++j) {
    INFO("row " << j);
    CHECK(rows[static_cast<size_t>(j) * (width + 1)] == 3);
  }

  // libpng's default tries every filter per row and picks different ones here.
  encoding.png_filters = 0;
  const std::vector<unsigned char> adaptive =
      stored_payload(idat_stream(files::encode_image(image, encoding, "adaptive.png")));
  REQUIRE(adaptive.size() == rows.size());
  bool other_filter = false;
  for (int j = 0; j < height; ++j) other_filter = other_filter || adaptive[static_cast<size_t>(j) * (width + 1)] != 3;
  CHECK(other_filter);

  // Decoded, both hold round(255 v) of every pixel.
  const test::TemporaryDirectory directory(true);
  for (const int filters : {0, files::png_filter_average}) {
    files::ImageEncoding compressed = files::png_encoding(8);
    compressed.png_compression_level = 1;
    compressed.png_filters = filters;
    const std::filesystem::path path = directory.path / ("filters_" + std::to_string(filters) + ".png");
    files::write_image(path, image, compressed);
    const core::ImageData back = files::read_image(path);
    REQUIRE(back.pixels.size() == image.pixels.size());
    for (size_t k = 0; k < image.pixels.size(); ++k)
      REQUIRE(back.pixels[k] * 255.0f == Approx(std::round(image.pixels[k] * 255.0f)).margin(1e-3));
  }
}

TEST_CASE("PNG samples are round((2^bits - 1) v) of v clamped to [0, 1], NaN as 0, and big-endian at 16 bits",
          "[fast][io][png]") {
  const float nan = std::nanf("");
  const std::vector<float> values = {0.0f, 1.0f, -0.5f, 2.0f, nan, 0.5f, 1.0f / 3.0f, 0.999f};
  const core::ImageData image{8, 1, 1, values};
  const test::TemporaryDirectory directory(true);
  for (const int bits : {8, 16}) {
    const double top = bits == 16 ? 65535.0 : 255.0;
    const std::filesystem::path path = directory.path / ("samples_" + std::to_string(bits) + ".png");
    files::write_image(path, image, files::png_encoding(bits));
    const core::ImageData back = files::read_image(path);
    REQUIRE(back.pixels.size() == values.size());
    for (size_t k = 0; k < values.size(); ++k) {
      const double v = std::isnan(values[k]) ? 0.0 : std::clamp(double(values[k]), 0.0, 1.0);
      INFO("bits " << bits << " value " << values[k]);
      // The decoder divides the stored integer by 2^bits - 1 in float: half an ulp of 1.
      CHECK(back.pixels[k] * top == Approx(std::floor(v * top + 0.5)).margin(1e-3 * top / 255.0));
    }
    // Zero, one and the 16-bit sample's high byte first: IDAT of level 0 holds the row raw.
    if (bits == 16) {
      files::ImageEncoding raw = files::png_encoding(16);
      raw.png_compression_level = 0;
      raw.png_filters = 8;  // PNG_FILTER_NONE
      const std::vector<unsigned char> stream = idat_stream(files::encode_image(image, raw, "raw.png"));
      // zlib header (2 bytes), stored block header (5 bytes), the row's filter byte, then samples.
      REQUIRE(stream.size() >= 8 + 2 * values.size());
      const unsigned char* samples = stream.data() + 8;
      CHECK(samples[0] == 0x00);
      CHECK(samples[1] == 0x00);
      CHECK(samples[2] == 0xFF);
      CHECK(samples[3] == 0xFF);
      CHECK(samples[10] == 0x80);  // 0.5: round(32767.5) = 32768
      CHECK(samples[11] == 0x00);
    }
  }
}

TEST_CASE("an RGBA PNG stores colour given with premultiplied alpha divided by it, and as given when unassociated",
          "[fast][io][png]") {
  // Pixel 0: colour 0.25 at alpha 0.5 (premultiplied: 0.5 unpremultiplied); pixel 1: alpha 0.
  const core::ImageData image{2, 1, 4, {0.25f, 0.25f, 0.25f, 0.5f, 0.3f, 0.3f, 0.3f, 0.0f}};
  files::ImageEncoding associated = files::png_encoding(16);
  associated.png_compression_level = 0;
  associated.png_filters = 8;  // PNG_FILTER_NONE
  files::ImageEncoding unassociated = associated;
  unassociated.unassociated_alpha = true;
  const auto sample = [](const std::vector<unsigned char>& stream, int k) {
    return (int(stream[8 + 2 * k]) << 8) | stream[8 + 2 * k + 1];
  };
  const std::vector<unsigned char> divided = idat_stream(files::encode_image(image, associated, "a.png"));
  const std::vector<unsigned char> as_given = idat_stream(files::encode_image(image, unassociated, "u.png"));
  CHECK(sample(divided, 0) == 32768);   // 0.25 / 0.5 = 0.5
  CHECK(sample(divided, 3) == 32768);   // alpha 0.5
  CHECK(sample(divided, 4) == 19661);   // alpha 0: the colour as given, round(0.3 x 65535)
  CHECK(sample(as_given, 0) == 16384);  // round(0.25 x 65535)
  CHECK(sample(as_given, 4) == 19661);
}

// OpenImageIO's 250-odd libraries took 0.4 s of every start: they come in a module
// (files/image_codecs.hpp) that the first image read or write loads.
TEST_CASE("nephele starts without OpenImageIO, which its image codec module brings", "[io][codecs]") {
  const test::Run executable = test::run_command("ldd " + std::string(NEPHELE_EXECUTABLE));
  REQUIRE(executable.exit_code == 0);
  CHECK(executable.output.find("libOpenImageIO") == std::string::npos);
  const std::filesystem::path module =
      std::filesystem::path(NEPHELE_EXECUTABLE).parent_path() / "nephele_image_codecs.so";
  const test::Run codecs = test::run_command("ldd " + module.string());
  REQUIRE(codecs.exit_code == 0);
  CHECK(codecs.output.find("libOpenImageIO.so") != std::string::npos);
  CHECK(codecs.output.find("not found") == std::string::npos);
}

TEST_CASE("PNGs need no image codec module, and without it an EXR is refused naming where it was looked for",
          "[io][codecs]") {
  const test::TemporaryDirectory directory(true);
  const std::filesystem::path missing = directory.path / "elsewhere" / "nephele_image_codecs.so";
  const std::string without_module = "NEPHELE_IMAGE_CODECS=" + missing.string() + " " + NEPHELE_EXECUTABLE;
  // Fresh processes (not the tests' command server, which has loaded the module already).
  const std::filesystem::path png = directory.path / "noise.png";
  const test::Run png_run = test::run_command(without_module + " noise --size 4 --out " + png.string());
  INFO(png_run.output);
  CHECK(png_run.exit_code == 0);
  CHECK(std::filesystem::is_regular_file(png));
  const std::filesystem::path exr = directory.path / "noise.exr";
  const test::Run exr_run = test::run_command(without_module + " noise --size 4 --out " + exr.string());
  INFO(exr_run.output);
  CHECK(exr_run.exit_code == 1);
  CHECK(exr_run.output.find(missing.string() + ": no such file") != std::string::npos);
  CHECK(exr_run.output.find("NEPHELE_IMAGE_CODECS") != std::string::npos);
  CHECK(!std::filesystem::exists(exr));
}

}  // namespace nephele
