// The texture containers' mip chains and block compression (src/files/mip_chain.hpp,
// block_compression.hpp, texture_containers.hpp), read back by the readers of
// tests/texture_readers.hpp and decoded by tests/block_decoding.hpp: both written from the
// specifications, neither sharing code with the writers.
#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <cmath>
#include <numeric>
#include <vector>

#include "files/block_compression.hpp"
#include "files/mip_chain.hpp"
#include "files/texture_containers.hpp"
#include "texture_readers.hpp"

namespace nephele {
namespace {

// A test cube of 6 faces of n^2 with smooth gradients, a sharp edge and fine texture on each
// face, values in [0, 1]: what a cover looks like to a compressor.
std::vector<float> test_cube(int n) {
  std::vector<float> texels(6u * n * n);
  for (int f = 0; f < 6; ++f)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double x = (i + 0.5) / n, y = (j + 0.5) / n;
        double v = 0.5 + 0.35 * std::sin(6.0 * x + f) * std::cos(5.0 * y - f) + 0.1 * std::sin(40.0 * x * y);
        if (x + 0.3 * y > 0.6 + 0.05 * f) v *= 0.3;  // an edge through every face
        texels[(std::size_t(f) * n + j) * n + i] = float(std::clamp(v, 0.0, 1.0));
      }
  return texels;
}

// The reference chain for power-of-two faces: each level the mean of 2 x 2 texels above it,
// computed here independently of files::build_mip_chain.
std::vector<std::vector<float>> reference_levels(const std::vector<float>& cube, int n) {
  std::vector<std::vector<float>> levels{cube};
  for (int size = n; size > 1; size /= 2) {
    const int half = size / 2;
    const std::vector<float>& above = levels.back();
    std::vector<float> next(6u * half * half);
    for (int f = 0; f < 6; ++f)
      for (int j = 0; j < half; ++j)
        for (int i = 0; i < half; ++i) {
          auto at = [&](int x, int y) { return above[(std::size_t(f) * size + y) * size + x]; };
          next[(std::size_t(f) * half + j) * half + i] =
              0.25f * (at(2 * i, 2 * j) + at(2 * i + 1, 2 * j) + at(2 * i, 2 * j + 1) + at(2 * i + 1, 2 * j + 1));
        }
    levels.push_back(next);
  }
  return levels;
}

// The largest error a BC4 block may have: the block's values are spread over the range of its
// 8-bit inputs; an encoder whose palette spans that range (8 values, 7 steps) with the nearest
// index is off by at most half a step. Endpoint searches trade the extremes for the mean error,
// so a full step is allowed, plus the input's rounding to 8 bits (half of 1/255) and the
// interpolation's rounding in the decoder (1/255).
double bc4_block_bound(const float* image, int width, int height, int bx, int by) {
  float lo = 1, hi = 0;
  for (int y = by; y < std::min(by + 4, height); ++y)
    for (int x = bx; x < std::min(bx + 4, width); ++x)
      lo = std::min(lo, image[y * width + x]), hi = std::max(hi, image[y * width + x]);
  return (hi - lo) / 7.0 + 1.5 / 255.0;
}

// Checks a decoded one-channel image against the reference, texel by texel, with the bound of
// `format`: exact for r32f, half a unit in the last place of binary16 for r16f (2^-12 relative
// for values in [0.5, 1], 2^-12 absolute bounds all below), half of 1/255 for r8 and the bound
// above for bc4.
void check_level(files::TexelFormat format, const std::vector<float>& decoded, const float* reference, int width,
                 int height) {
  REQUIRE(decoded.size() == std::size_t(width) * height);
  int failures = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const double want = reference[y * width + x], got = decoded[y * width + x];
      double bound = 0;
      switch (format) {
        case files::TexelFormat::r32f: bound = 1e-6 * std::max(1.0, want); break;
        case files::TexelFormat::r16f: bound = std::ldexp(1.0, -12); break;
        case files::TexelFormat::r8: bound = 0.5 / 255 + 1e-6; break;
        default: bound = bc4_block_bound(reference, width, height, x / 4 * 4, y / 4 * 4); break;
      }
      if (std::abs(got - want) > bound && ++failures <= 5)
        FAIL_CHECK("texel " << x << ", " << y << ": " << got << " against " << want << " (bound " << bound << ")");
    }
  CHECK(failures == 0);
}

test::StoredFormat stored(files::TexelFormat format) {
  switch (format) {
    case files::TexelFormat::r8: return test::StoredFormat::r8;
    case files::TexelFormat::r16f: return test::StoredFormat::r16f;
    case files::TexelFormat::r32f: return test::StoredFormat::r32f;
    case files::TexelFormat::rgba8: return test::StoredFormat::rgba8;
    case files::TexelFormat::bc1: return test::StoredFormat::bc1;
    case files::TexelFormat::bc3: return test::StoredFormat::bc3;
    case files::TexelFormat::bc4: return test::StoredFormat::bc4;
  }
  return test::StoredFormat::r8;
}

std::string as_string(const std::vector<unsigned char>& bytes) { return std::string(bytes.begin(), bytes.end()); }

}  // namespace

TEST_CASE("a mip chain halves every level down to 1 x 1 and keeps the mean of the level above, odd sizes included",
          "[fast][texture_containers]") {
  // 4 x 4 to 2 x 2: the means of 2 x 2 blocks, exactly.
  std::vector<float> base(16);
  std::iota(base.begin(), base.end(), 0.0f);
  const files::MipChain even = files::build_mip_chain(base, 4, 4, 1, 1);
  REQUIRE(even.count() == 3);
  CHECK(even.levels[1] == std::vector<float>{2.5f, 4.5f, 10.5f, 12.5f});
  CHECK(even.levels[2] == std::vector<float>{7.5f});
  // 5 x 3 (two channels, two layers): 2 x 1, then 1 x 1. Each output texel of the 5-wide row
  // covers 2.5 inputs: weights 1, 1, 0.5 over 2.5; every level keeps the image's mean.
  std::vector<float> odd(5 * 3 * 2 * 2);
  for (std::size_t i = 0; i < odd.size(); ++i) odd[i] = float((i * 7919) % 101) / 100.0f;
  const files::MipChain chain = files::build_mip_chain(odd, 5, 3, 2, 2);
  REQUIRE(chain.count() == 3);  // 1 + floor(log2 5)
  CHECK(chain.level_width(1) == 2);
  CHECK(chain.level_height(1) == 1);
  CHECK(chain.level_width(2) == 1);
  CHECK(chain.level_height(2) == 1);
  for (int layer = 0; layer < 2; ++layer)
    for (int channel = 0; channel < 2; ++channel) {
      double mean0 = 0;
      const float* image = chain.image(0, layer);
      for (int t = 0; t < 15; ++t) mean0 += image[2 * t + channel] / 15.0;
      // Row 0 of level 1, texel 0: rows 0..2 weigh 1/3 each (3 rows to 1), columns 0, 1, 2
      // weigh 1, 1, 0.5 over 2.5.
      double texel0 = 0;
      for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 3; ++x) texel0 += (x == 2 ? 0.5 : 1.0) / 2.5 / 3.0 * image[2 * (y * 5 + x) + channel];
      CHECK(chain.image(1, layer)[channel] == Approx(texel0).margin(1e-6));
      CHECK(chain.image(2, layer)[channel] == Approx(mean0).margin(1e-6));
    }
}

TEST_CASE("BC4 blocks from libnvtt decode, by a decoder written from the spec, within a palette step of every input",
          "[fast][texture_containers]") {
  const int n = 32;
  const std::vector<float> cube = test_cube(n);
  const std::vector<unsigned char> blocks = files::compress_image(cube.data(), n, n, files::BlockFormat::bc4);
  REQUIRE(blocks.size() == files::compressed_image_bytes(n, n, files::BlockFormat::bc4));
  check_level(files::TexelFormat::bc4, test::decode_stored_image(test::StoredFormat::bc4, blocks.data(), n, n),
              cube.data(), n, n);
  // BC3: the same bound for alpha (interpolated as BC4); the colour, 5:6:5 endpoints and 4
  // entries, within a full palette step (a third of the block's range) plus the 5-bit step of
  // red and blue (8/255).
  std::vector<float> rgba(4u * n * n);
  for (std::size_t i = 0; i < std::size_t(n) * n; ++i)
    rgba[4 * i] = rgba[4 * i + 1] = rgba[4 * i + 2] = rgba[4 * i + 3] = cube[i];
  const std::vector<unsigned char> bc3 = files::compress_image(rgba.data(), n, n, files::BlockFormat::bc3);
  const std::vector<float> decoded = test::decode_stored_image(test::StoredFormat::bc3, bc3.data(), n, n);
  std::vector<float> alpha, green;
  for (std::size_t i = 0; i < std::size_t(n) * n; ++i)
    alpha.push_back(decoded[4 * i + 3]), green.push_back(decoded[4 * i + 1]);
  check_level(files::TexelFormat::bc4, alpha, cube.data(), n, n);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const double bound =
          7.0 / 3.0 * (bc4_block_bound(cube.data(), n, n, x / 4 * 4, y / 4 * 4) - 1.5 / 255) + 8.0 / 255;
      if (std::abs(green[y * n + x] - cube[y * n + x]) > bound)
        FAIL_CHECK("colour at " << x << ", " << y << ": " << green[y * n + x] << " against " << cube[y * n + x]
                                << " bound " << bound);
    }
}

TEST_CASE(
    "a KTX2 cube stores every mip level smallest first, aligned, with each format's descriptor, and decodes to "
    "the area means",
    "[fast][texture_containers]") {
  const int n = 32;
  const std::vector<float> cube = test_cube(n);
  const auto reference = reference_levels(cube, n);
  const files::MipChain chain = files::build_mip_chain(cube, n, n, 6, 1);
  const struct {
    files::TexelFormat format;
    std::uint32_t vk_format, model, block, bytes_plane0, sample_bits, alignment;
  } cases[] = {{files::TexelFormat::r8, 9, 1, 1, 1, 8, 4},
               {files::TexelFormat::r16f, 76, 1, 1, 2, 16, 4},
               {files::TexelFormat::r32f, 100, 1, 1, 4, 32, 4},
               {files::TexelFormat::bc4, 139, 131, 4, 8, 64, 8}};
  for (const auto& c : cases) {
    INFO("vkFormat " << c.vk_format);
    const std::string b = as_string(files::encode_ktx2(chain, c.format));
    const test::Ktx2File k = test::read_ktx2(b);
    CHECK(k.vk_format == c.vk_format);
    CHECK(k.faces == 6);
    CHECK(k.layers == 0);
    REQUIRE(k.level_count == 6);  // 32, 16, 8, 4, 2, 1
    CHECK(k.color_model == c.model);
    CHECK(k.transfer == 1);  // linear
    CHECK(k.block_width == c.block);
    CHECK(k.block_height == c.block);
    CHECK(k.bytes_plane0 == c.bytes_plane0);
    REQUIRE(k.samples.size() == 1);
    CHECK(k.samples[0].bit_length == c.sample_bits);
    CHECK(k.orientation == "rd");
    for (std::uint32_t level = 0; level < k.level_count; ++level) {
      INFO("level " << level);
      const int size = test::mip_size(n, int(level));
      const test::Ktx2Level& l = k.levels[level];
      CHECK(l.offset % c.alignment == 0);
      const std::size_t face_bytes = test::stored_image_bytes(stored(c.format), size, size);
      REQUIRE(l.length == 6 * face_bytes);
      CHECK(l.uncompressed_length == l.length);
      REQUIRE(l.offset + l.length <= b.size());
      // Section 3.9: the smaller level lies before the larger one.
      if (level > 0) CHECK(l.offset + l.length <= k.levels[level - 1].offset);
      for (int f = 0; f < 6; ++f) {
        const auto* data = reinterpret_cast<const unsigned char*>(b.data()) + l.offset + f * face_bytes;
        check_level(c.format, test::decode_stored_image(stored(c.format), data, size, size),
                    reference[level].data() + std::size_t(f) * size * size, size, size);
      }
    }
  }
}

TEST_CASE("a KTX2 of RGBA formats describes RGBA8 by four samples and BC3 by its alpha and colour blocks",
          "[fast][texture_containers]") {
  // Khronos Data Format Specification 1.3: RGBA8 in the RGBSDA model, channels R, G, B and
  // alpha (15) at bit offsets 0, 8, 16, 24; BC3 in KHR_DF_MODEL_BC3 (130) with the alpha block
  // (channel 15) in the first 64 bits and the colour block (0) in the second, 4 x 4 texels in 16
  // bytes. A one-channel chain is spread into RGBA as grey; its alpha decodes to the chain.
  const int n = 8;
  const std::vector<float> cube = test_cube(n);
  const files::MipChain chain = files::build_mip_chain(cube, n, n, 6, 1);
  const auto reference = reference_levels(cube, n);
  const std::string rgba = as_string(files::encode_ktx2(chain, files::TexelFormat::rgba8));
  const test::Ktx2File a = test::read_ktx2(rgba);
  CHECK(a.vk_format == 37);
  CHECK(a.color_model == 1);
  REQUIRE(a.samples.size() == 4);
  for (std::uint32_t k = 0; k < 4; ++k) {
    CHECK(a.samples[k].bit_offset == 8 * k);
    CHECK(a.samples[k].bit_length == 8);
    CHECK(a.samples[k].channel == (k < 3 ? k : 15u));
  }
  const std::string bc3 = as_string(files::encode_ktx2(chain, files::TexelFormat::bc3));
  const test::Ktx2File b = test::read_ktx2(bc3);
  CHECK(b.vk_format == 137);
  CHECK(b.color_model == 130);
  CHECK(b.block_width == 4);
  CHECK(b.bytes_plane0 == 16);
  REQUIRE(b.samples.size() == 2);
  CHECK(b.samples[0].channel == 15);
  CHECK(b.samples[0].bit_offset == 0);
  CHECK(b.samples[1].channel == 0);
  CHECK(b.samples[1].bit_offset == 64);
  // Level 0, face 3: the alpha within the BC4 bound of the float texels, and RGBA8's alpha
  // within half of 1/255.
  const std::size_t face = 3;
  const auto* rgba_data = reinterpret_cast<const unsigned char*>(rgba.data()) + a.levels[0].offset + face * n * n * 4;
  const auto* bc3_data = reinterpret_cast<const unsigned char*>(bc3.data()) + b.levels[0].offset + face * 4 * 16;
  const std::vector<float> rgba_values = test::decode_stored_image(test::StoredFormat::rgba8, rgba_data, n, n);
  const std::vector<float> bc3_values = test::decode_stored_image(test::StoredFormat::bc3, bc3_data, n, n);
  std::vector<float> rgba_alpha, bc3_alpha;
  for (int t = 0; t < n * n; ++t)
    rgba_alpha.push_back(rgba_values[4 * t + 3]), bc3_alpha.push_back(bc3_values[4 * t + 3]);
  check_level(files::TexelFormat::r8, rgba_alpha, reference[0].data() + face * n * n, n, n);
  check_level(files::TexelFormat::bc4, bc3_alpha, reference[0].data() + face * n * n, n, n);
}

TEST_CASE("a DDS cube holds each face's mip levels in turn, flagged as mipmapped, in legacy and DX10 headers",
          "[fast][texture_containers]") {
  const int n = 16;
  const std::vector<float> cube = test_cube(n);
  const auto reference = reference_levels(cube, n);
  const files::MipChain chain = files::build_mip_chain(cube, n, n, 6, 1);
  const struct {
    files::TexelFormat format;
    const char* four_cc;
    std::uint32_t dxgi;
  } cases[] = {{files::TexelFormat::bc4, "ATI1", 0},   {files::TexelFormat::bc3, "DXT5", 0},
               {files::TexelFormat::rgba8, "", 0},     {files::TexelFormat::r8, "DX10", 61},
               {files::TexelFormat::r16f, "DX10", 54}, {files::TexelFormat::r32f, "DX10", 41}};
  for (const auto& c : cases) {
    INFO("format " << int(c.format));
    const std::string b = as_string(files::encode_dds(chain, c.format));
    const test::DdsFile d = test::read_dds(b);
    CHECK(d.four_cc == c.four_cc);
    CHECK(d.dxgi == c.dxgi);
    CHECK(d.width == std::uint32_t(n));
    CHECK(d.height == std::uint32_t(n));
    CHECK(d.mip_count == 5);                   // 16, 8, 4, 2, 1
    CHECK((d.flags & 0x20000u) == 0x20000u);   // DDSD_MIPMAPCOUNT
    CHECK((d.caps & 0x401008u) == 0x401008u);  // TEXTURE | MIPMAP | COMPLEX
    CHECK(d.caps2 == 0xFE00u);                 // CUBEMAP and all six faces
    const bool block = c.format == files::TexelFormat::bc4 || c.format == files::TexelFormat::bc3;
    const test::StoredFormat format = stored(c.format);
    // Blocks give the base level's byte size (DDSD_LINEARSIZE), others the row pitch (DDSD_PITCH).
    CHECK((d.flags & (block ? 0x80000u : 0x8u)) != 0);
    CHECK(d.pitch_or_linear_size ==
          (block ? test::stored_image_bytes(format, n, n) : test::stored_image_bytes(format, n, 1)));
    REQUIRE(b.size() == test::dds_image_offset(d, format, 6, 0));  // nothing after the sixth face
    for (int f = 0; f < 6; ++f)
      for (int level = 0; level < 5; ++level) {
        INFO("face " << f << " level " << level);
        const int size = test::mip_size(n, level);
        const auto* data =
            reinterpret_cast<const unsigned char*>(b.data()) + test::dds_image_offset(d, format, f, level);
        std::vector<float> values = test::decode_stored_image(format, data, size, size);
        if (test::decode_stored_image(format, data, 1, 1).size() == 4) {  // RGBA: grey in every channel
          std::vector<float> alpha;
          for (std::size_t i = 3; i < values.size(); i += 4) alpha.push_back(values[i]);
          values = alpha;
        }
        check_level(block                                   ? files::TexelFormat::bc4
                    : c.format == files::TexelFormat::rgba8 ? files::TexelFormat::r8
                                                            : c.format,
                    values, reference[level].data() + std::size_t(f) * size * size, size, size);
      }
  }
}

TEST_CASE("OpenImageIO's DDS reader decodes the BC4 and BC3 cubes as the spec decoder does",
          "[fast][texture_containers]") {
  const int n = 16;
  const files::MipChain chain = files::build_mip_chain(test_cube(n), n, n, 6, 1);
  for (const auto format : {files::TexelFormat::bc4, files::TexelFormat::bc3}) {
    INFO("format " << int(format));
    const std::string b = as_string(files::encode_dds(chain, format));
    const std::filesystem::path path = std::filesystem::temp_directory_path() / "nephele_oiio_bc.dds";
    { std::ofstream(path, std::ios::binary) << b; }
    auto in = OIIO::ImageInput::open(path.string());
    REQUIRE(in);
    const int channels = in->spec().nchannels;
    // OpenImageIO 2.4 shows a DDS cube as an n x 6n image of the faces in order.
    REQUIRE(in->spec().width == n);
    REQUIRE(in->spec().height == 6 * n);
    std::vector<float> pixels(std::size_t(n) * 6 * n * channels);
    REQUIRE(in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels.data()));
    in->close();
    std::filesystem::remove(path);
    const test::DdsFile d = test::read_dds(b);
    for (int f = 0; f < 6; ++f) {
      const test::StoredFormat stored_format = stored(format);
      const auto* data =
          reinterpret_cast<const unsigned char*>(b.data()) + test::dds_image_offset(d, stored_format, f, 0);
      const std::vector<float> ours = test::decode_stored_image(stored_format, data, n, n);
      const int ours_channels = int(ours.size() / (std::size_t(n) * n));
      for (std::size_t t = 0; t < std::size_t(n) * n; ++t)
        for (int ch = 0; ch < std::min(channels, ours_channels); ++ch) {
          // Interpolated entries may round either way: one unit of 1/255.
          const float theirs = pixels[(std::size_t(f) * n * n + t) * channels + ch];
          if (std::abs(theirs - ours[t * ours_channels + ch]) > 1.0f / 255 + 1e-6f)
            FAIL_CHECK("face " << f << " texel " << t << " channel " << ch << ": " << theirs << " against "
                               << ours[t * ours_channels + ch]);
        }
    }
  }
}

TEST_CASE("a container written face by face in bands of rows holds the bytes of the whole chain's encoding",
          "[fast][texture_containers]") {
  // An odd size, so that levels have partial 4 x 4 blocks and the last band is short.
  const int n = 37, levels = files::full_mip_count(n, n);
  const std::vector<float> cube = test_cube(n);
  const files::MipChain whole = files::build_mip_chain(cube, n, n, 6, 1);
  const std::filesystem::path directory =
      std::filesystem::temp_directory_path() / ("nephele_container_writer_" + std::to_string(::getpid()));
  std::filesystem::remove_all(directory);
  std::filesystem::create_directories(directory);
  const struct {
    files::TexelFormat format;
    files::GreyLayout layout;
  } cases[] = {
      {files::TexelFormat::bc4, files::GreyLayout::grey},   {files::TexelFormat::bc3, files::GreyLayout::white_alpha},
      {files::TexelFormat::rgba8, files::GreyLayout::grey}, {files::TexelFormat::r8, files::GreyLayout::grey},
      {files::TexelFormat::r16f, files::GreyLayout::grey},  {files::TexelFormat::r32f, files::GreyLayout::grey}};
  int written = 0;
  for (const bool ktx2 : {true, false})
    for (const auto& c : cases)
      for (const int band : {4, 8, 0}) {
        INFO((ktx2 ? "ktx2" : "dds") << " format " << int(c.format) << " band " << band);
        const std::filesystem::path path = directory / ("file" + std::to_string(written++));
        files::ContainerWriter writer(
            path, ktx2 ? files::ktx2_layout(n, n, 6, levels, c.format) : files::dds_layout(n, n, 6, levels, c.format),
            c.format, c.layout, band);
        for (const int f : {3, 0, 5, 1, 4, 2}) {  // any order of faces
          const float* face = cube.data() + std::size_t(f) * n * n;
          writer.write_layer(f, files::build_mip_chain(std::vector<float>(face, face + n * n), n, n, 1, 1));
        }
        writer.close();
        std::ifstream in(path, std::ios::binary);
        const std::string file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        const std::vector<unsigned char> expected =
            ktx2 ? files::encode_ktx2(whole, c.format, c.layout) : files::encode_dds(whole, c.format, c.layout);
        REQUIRE(file.size() == expected.size());
        CHECK(file == std::string(expected.begin(), expected.end()));
      }
  // A face left out is an error, not a file with a hole of zeros.
  files::ContainerWriter partial(directory / "partial", files::dds_layout(n, n, 6, levels, files::TexelFormat::r8),
                                 files::TexelFormat::r8);
  partial.write_layer(0, files::build_mip_chain(std::vector<float>(cube.begin(), cube.begin() + n * n), n, n, 1, 1));
  CHECK_THROWS_AS(partial.close(), std::logic_error);
  std::filesystem::remove_all(directory);
}

}  // namespace nephele
