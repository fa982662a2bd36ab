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

TEST_CASE("without its image codec module nephele says where it looked and writes no image", "[io][codecs]") {
  const test::TemporaryDirectory directory(true);
  const std::filesystem::path missing = directory.path / "elsewhere" / "nephele_image_codecs.so";
  const std::filesystem::path png = directory.path / "noise.png";
  // A fresh process (not the tests' command server, which has loaded the module already).
  const test::Run run = test::run_command("NEPHELE_IMAGE_CODECS=" + missing.string() + " " +
                                          std::string(NEPHELE_EXECUTABLE) + " noise --size 4 --out " + png.string());
  CHECK(run.exit_code == 1);
  INFO(run.output);
  CHECK(run.output.find(missing.string() + ": no such file") != std::string::npos);
  CHECK(run.output.find("NEPHELE_IMAGE_CODECS") != std::string::npos);
  CHECK(!std::filesystem::exists(png));
}

}  // namespace nephele
