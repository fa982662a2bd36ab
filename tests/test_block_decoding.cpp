// The test suite's decoder of BC1, BC3 and BC4 blocks (block_decoding.hpp) against values worked
// out by hand from the Khronos Data Format Specification 1.3 ("S3TC Compressed Texture Image
// Formats", "RGTC Compressed Texture Image Formats"). Blocks are written byte by byte: endpoints
// little-endian, then the indices, texel i = 4 * y + x at bit 2 * i (BC1, 32 bits from byte 4) or
// 3 * i (BC4 and BC3 alpha, 48 bits from byte 2), both little-endian.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "block_decoding.hpp"

using namespace nephele::test;

namespace {

// Where the spec gives a value exactly (an endpoint, the 0 and 1 of BC4's 6-value mode,
// transparent black) the check is exact. Where it gives a weighted mean in real arithmetic and
// lets implementations round it as they do (BC1's thirds and half, BC4's sevenths and fifths in
// 8 bits), the check allows 1 in 8 bits: rounding to nearest is within 0.5, truncation within 1.
constexpr double kInterpolated8 = 1.0;
// The float BC4 values are the real value rounded to float: within 2^-24 relative of it (about
// 6e-8 below 1); the check allows 1e-6 and nothing for the exact 0 and 1.
constexpr double kFloatRounding = 1e-6;

void check_near(int actual, double real, double tolerance) {
  INFO("decoded " << actual << ", spec value " << real);
  CHECK(std::abs(double(actual) - real) <= tolerance);
}

// The 48 index bits of a BC4 block whose texels 0..7 use codes 0, 1, ..., 7 and texels 8..15 codes
// 7, 6, ..., 0: 3-bit fields from the low bit, 000 001 010 011 100 101 110 111 (texels 0..7) give
// the 24 bits 0xFAC688, and 111 110 101 100 011 010 001 000 (texels 8..15) give 0x053977; low
// byte first: 88 C6 FA 77 39 05.
constexpr std::array<int, 16> kRampCodes = {0, 1, 2, 3, 4, 5, 6, 7, 7, 6, 5, 4, 3, 2, 1, 0};

// BC1 index pattern, rows (0 1 2 3) (3 2 1 0) (0 0 1 1) (2 2 3 3): 2-bit fields from the low bit,
// row 0 = 0b11'10'01'00 = 0xE4, row 1 = 0b00'01'10'11 = 0x1B, row 2 = 0b01'01'00'00 = 0x50,
// row 3 = 0b11'11'10'10 = 0xFA.
constexpr std::array<int, 16> kColourCodes = {0, 1, 2, 3, 3, 2, 1, 0, 0, 0, 1, 1, 2, 2, 3, 3};

}  // namespace

TEST_CASE("BC4 with red0 greater than red1 interpolates eight values in sevenths", "[fast][block_decoding]") {
  // red0 = 255, red1 = 0 (red0 > red1: 8 values), then the ramp indices.
  const std::array<std::uint8_t, 8> block = {0xFF, 0x00, 0x88, 0xC6, 0xFA, 0x77, 0x39, 0x05};
  // Code c in 8-bit units: 0 -> 255, 1 -> 0, c = 2..7 -> ((8 - c) * 255 + (c - 1) * 0) / 7:
  // 6*255/7 = 218.571, 5*255/7 = 182.143, 4*255/7 = 145.714, 3*255/7 = 109.286,
  // 2*255/7 = 72.857, 1*255/7 = 36.429.
  const std::array<double, 8> spec = {255.0,         0.0,           6 * 255.0 / 7, 5 * 255.0 / 7,
                                      4 * 255.0 / 7, 3 * 255.0 / 7, 2 * 255.0 / 7, 1 * 255.0 / 7};
  const std::array<std::uint8_t, 16> bytes = decode_bc4_block(block.data());
  const std::array<float, 16> reals = decode_bc4_block_float(block.data());
  for (int i = 0; i < 16; ++i) {
    const int code = kRampCodes[i];
    INFO("texel " << i << ", code " << code);
    check_near(bytes[i], spec[code], code < 2 ? 0.0 : kInterpolated8);
    // The real value is spec / 255: 1, 0, 6/7, 5/7, ..., 1/7.
    CHECK(std::abs(double(reals[i]) - spec[code] / 255.0) <= (code < 2 ? 0.0 : kFloatRounding));
  }
  CHECK(reals[0] == 1.0f);
  CHECK(reals[1] == 0.0f);
}

TEST_CASE("BC4 with red0 not greater than red1 gives six values and exact 0 and 1", "[fast][block_decoding]") {
  // red0 = 50 (0x32) <= red1 = 201 (0xC9): 6 values, then the ramp indices.
  const std::array<std::uint8_t, 8> block = {0x32, 0xC9, 0x88, 0xC6, 0xFA, 0x77, 0x39, 0x05};
  // Code c: 0 -> 50, 1 -> 201, c = 2..5 -> ((6 - c) * 50 + (c - 1) * 201) / 5:
  // (200 + 201)/5 = 80.2, (150 + 402)/5 = 110.4, (100 + 603)/5 = 140.6, (50 + 804)/5 = 170.8;
  // 6 -> 0 and 7 -> 255 (1.0) exactly.
  const std::array<double, 8> spec = {50.0, 201.0, 80.2, 110.4, 140.6, 170.8, 0.0, 255.0};
  const std::array<std::uint8_t, 16> bytes = decode_bc4_block(block.data());
  const std::array<float, 16> reals = decode_bc4_block_float(block.data());
  for (int i = 0; i < 16; ++i) {
    const int code = kRampCodes[i];
    INFO("texel " << i << ", code " << code);
    const bool exact = code < 2 || code > 5;
    check_near(bytes[i], spec[code], exact ? 0.0 : kInterpolated8);
    CHECK(std::abs(double(reals[i]) - spec[code] / 255.0) <= kFloatRounding);
  }
  // Texels 6 and 9 use code 6, texels 7 and 8 code 7: exactly 0 and 1.
  CHECK(bytes[6] == 0);
  CHECK(bytes[9] == 0);
  CHECK(bytes[7] == 255);
  CHECK(bytes[8] == 255);
  CHECK(reals[6] == 0.0f);
  CHECK(reals[9] == 0.0f);
  CHECK(reals[7] == 1.0f);
  CHECK(reals[8] == 1.0f);
  // The endpoints are red0 / 255 and red1 / 255 as floats.
  CHECK(reals[0] == static_cast<float>(50.0 / 255.0));
  CHECK(reals[1] == static_cast<float>(201.0 / 255.0));
}

TEST_CASE("BC4 with equal endpoints is in the six value mode", "[fast][block_decoding]") {
  // red0 = red1 = 128 (0x80): red0 > red1 is false, so 6 values; codes 0..5 all give
  // ((6 - c) * 128 + (c - 1) * 128) / 5 = 128 exactly, code 6 gives 0 and code 7 gives 255.
  const std::array<std::uint8_t, 8> block = {0x80, 0x80, 0x88, 0xC6, 0xFA, 0x77, 0x39, 0x05};
  const std::array<std::uint8_t, 16> bytes = decode_bc4_block(block.data());
  for (int i = 0; i < 16; ++i) {
    const int code = kRampCodes[i];
    INFO("texel " << i << ", code " << code);
    CHECK(int(bytes[i]) == (code == 6 ? 0 : code == 7 ? 255 : 128));
  }
}

TEST_CASE("BC1 with colour0 greater than colour1 gives four opaque colours", "[fast][block_decoding]") {
  // colour0 = R 31, G 20, B 10 = (31 << 11) | (20 << 5) | 10 = 0xFA8A, bytes 8A FA.
  // colour1 = R 3, G 60, B 31 = (3 << 11) | (60 << 5) | 31 = 0x1F9F, bytes 9F 1F.
  // 0xFA8A > 0x1F9F: 4-colour mode. Indices: the kColourCodes pattern, E4 1B 50 FA.
  const std::array<std::uint8_t, 8> block = {0x8A, 0xFA, 0x9F, 0x1F, 0xE4, 0x1B, 0x50, 0xFA};
  // Bit replication: R 31 -> (31 << 3) | (31 >> 2) = 255, G 20 -> 80 | 1 = 81, B 10 -> 80 | 2 = 82;
  // R 3 -> 24 | 0 = 24, G 60 -> 240 | 3 = 243, B 31 -> 255.
  // Code 2 = (2 c0 + c1) / 3 = ((510 + 24) / 3, (162 + 243) / 3, (164 + 255) / 3) = (178, 135, 139.667).
  // Code 3 = (c0 + 2 c1) / 3 = ((255 + 48) / 3, (81 + 486) / 3, (82 + 510) / 3) = (101, 189, 197.333).
  const std::array<std::array<double, 3>, 4> spec = {
      {{255, 81, 82}, {24, 243, 255}, {178, 135, 419.0 / 3}, {101, 189, 592.0 / 3}}};
  const Rgba8Block texels = decode_bc1_block(block.data());
  for (int i = 0; i < 16; ++i) {
    const int code = kColourCodes[i];
    INFO("texel " << i << ", code " << code);
    for (int ch = 0; ch < 3; ++ch) check_near(texels[i][ch], spec[code][ch], code < 2 ? 0.0 : kInterpolated8);
    CHECK(int(texels[i][3]) == 255);
  }
}

TEST_CASE("BC1 with colour0 not greater than colour1 gives three colours and transparent black",
          "[fast][block_decoding]") {
  // The endpoints of the 4-colour case swapped: colour0 = 0x1F9F (9F 1F) <= colour1 = 0xFA8A
  // (8A FA): 3-colour mode. Same indices, E4 1B 50 FA.
  const std::array<std::uint8_t, 8> block = {0x9F, 0x1F, 0x8A, 0xFA, 0xE4, 0x1B, 0x50, 0xFA};
  // c0 = (24, 243, 255), c1 = (255, 81, 82); code 2 = (c0 + c1) / 2 = (139.5, 162, 168.5);
  // code 3 = transparent black (0, 0, 0, 0).
  const std::array<std::array<double, 3>, 3> spec = {{{24, 243, 255}, {255, 81, 82}, {139.5, 162, 168.5}}};
  const Rgba8Block texels = decode_bc1_block(block.data());
  for (int i = 0; i < 16; ++i) {
    const int code = kColourCodes[i];
    INFO("texel " << i << ", code " << code);
    if (code == 3) {
      CHECK(texels[i] == Rgba8{0, 0, 0, 0});
      continue;
    }
    for (int ch = 0; ch < 3; ++ch) check_near(texels[i][ch], spec[code][ch], code < 2 ? 0.0 : kInterpolated8);
    CHECK(int(texels[i][3]) == 255);
  }
}

TEST_CASE("BC1 with equal endpoints is in the three colour mode", "[fast][block_decoding]") {
  // colour0 = colour1 = 0x07E0 (pure green, bytes E0 07): colour0 > colour1 is false. Indices
  // i % 4 in every row: 0b11'10'01'00 = E4. Codes 0, 1 and 2 ((c0 + c1) / 2) give (0, 255, 0)
  // exactly, code 3 transparent black.
  const std::array<std::uint8_t, 8> block = {0xE0, 0x07, 0xE0, 0x07, 0xE4, 0xE4, 0xE4, 0xE4};
  const Rgba8Block texels = decode_bc1_block(block.data());
  for (int i = 0; i < 16; ++i) {
    INFO("texel " << i);
    CHECK(texels[i] == (i % 4 == 3 ? Rgba8{0, 0, 0, 0} : Rgba8{0, 255, 0, 255}));
  }
}

TEST_CASE("BC3 takes alpha from its first half and always decodes four colours", "[fast][block_decoding]") {
  // Alpha: alpha0 = 200 (C8) > alpha1 = 10 (0A): 8 values; texel i uses code i % 8, the 24 bits
  // 0xFAC688 twice: 88 C6 FA 88 C6 FA.
  // Colour: colour0 = 0x001F (blue, 1F 00) <= colour1 = 0xF800 (red, 00 F8), which BC1 would
  // decode in the 3-colour mode; texel i uses code i % 4 (E4 in every row).
  const std::array<std::uint8_t, 16> block = {0xC8, 0x0A, 0x88, 0xC6, 0xFA, 0x88, 0xC6, 0xFA,
                                              0x1F, 0x00, 0x00, 0xF8, 0xE4, 0xE4, 0xE4, 0xE4};
  // Alpha code c: 0 -> 200, 1 -> 10, c = 2..7 -> ((8 - c) * 200 + (c - 1) * 10) / 7:
  // 1210/7 = 172.857, 1020/7 = 145.714, 830/7 = 118.571, 640/7 = 91.429, 450/7 = 64.286,
  // 260/7 = 37.143.
  const std::array<double, 8> alpha = {200, 10, 1210.0 / 7, 1020.0 / 7, 830.0 / 7, 640.0 / 7, 450.0 / 7, 260.0 / 7};
  // Colours, 4-colour mode always: c0 = (0, 0, 255), c1 = (255, 0, 0),
  // code 2 = (2 c0 + c1) / 3 = (85, 0, 170), code 3 = (c0 + 2 c1) / 3 = (170, 0, 85).
  const std::array<std::array<double, 3>, 4> colour = {{{0, 0, 255}, {255, 0, 0}, {85, 0, 170}, {170, 0, 85}}};
  const Rgba8Block texels = decode_bc3_block(block.data());
  for (int i = 0; i < 16; ++i) {
    const int a = i % 8, c = i % 4;
    INFO("texel " << i << ", alpha code " << a << ", colour code " << c);
    for (int ch = 0; ch < 3; ++ch) check_near(texels[i][ch], colour[c][ch], c < 2 ? 0.0 : kInterpolated8);
    check_near(texels[i][3], alpha[a], a < 2 ? 0.0 : kInterpolated8);
  }
  // The same colour half read as BC1 is in the 3-colour mode: code 3 is transparent black there.
  const Rgba8Block as_bc1 = decode_bc1_block(block.data() + 8);
  CHECK(as_bc1[3] == Rgba8{0, 0, 0, 0});
  CHECK(int(texels[3][3]) == 146);  // round(1020 / 7 = 145.714); not transparent
}

TEST_CASE("the decoder rounds interpolated values to nearest as its header documents", "[fast][block_decoding]") {
  // Pins this decoder's own choice (round to nearest, the 3-colour half rounded up) on the blocks
  // above, so that a test using it with a tolerance of 1 knows what it compares against.
  const std::array<std::uint8_t, 8> bc4_eight = {0xFF, 0x00, 0x88, 0xC6, 0xFA, 0x77, 0x39, 0x05};
  // 218.571 -> 219, 182.143 -> 182, 145.714 -> 146, 109.286 -> 109, 72.857 -> 73, 36.429 -> 36.
  const std::array<std::uint8_t, 16> eight = decode_bc4_block(bc4_eight.data());
  CHECK(std::array<int, 6>{eight[2], eight[3], eight[4], eight[5], eight[6], eight[7]} ==
        std::array<int, 6>{219, 182, 146, 109, 73, 36});
  const std::array<std::uint8_t, 8> bc4_six = {0x32, 0xC9, 0x88, 0xC6, 0xFA, 0x77, 0x39, 0x05};
  // 80.2 -> 80, 110.4 -> 110, 140.6 -> 141, 170.8 -> 171.
  const std::array<std::uint8_t, 16> six = decode_bc4_block(bc4_six.data());
  CHECK(std::array<int, 4>{six[2], six[3], six[4], six[5]} == std::array<int, 4>{80, 110, 141, 171});
  // BC1 4-colour: code 2 (178, 135, 139.667 -> 140) at texel 2, code 3 (101, 189, 197.333 -> 197) at texel 3.
  const std::array<std::uint8_t, 8> bc1_four = {0x8A, 0xFA, 0x9F, 0x1F, 0xE4, 0x1B, 0x50, 0xFA};
  const Rgba8Block four = decode_bc1_block(bc1_four.data());
  CHECK(four[2] == Rgba8{178, 135, 140, 255});
  CHECK(four[3] == Rgba8{101, 189, 197, 255});
  // BC1 3-colour: code 2 (139.5 -> 140, 162, 168.5 -> 169) at texel 2.
  const std::array<std::uint8_t, 8> bc1_three = {0x9F, 0x1F, 0x8A, 0xFA, 0xE4, 0x1B, 0x50, 0xFA};
  CHECK(decode_bc1_block(bc1_three.data())[2] == Rgba8{140, 162, 169, 255});
}

TEST_CASE("the image byte size counts partial blocks as whole ones", "[fast][block_decoding]") {
  CHECK(bc_image_bytes(6, 5, 8) == 2 * 2 * 8);
  CHECK(bc_image_bytes(4, 4, 8) == 8);
  CHECK(bc_image_bytes(1, 1, 16) == 16);
  CHECK(bc_image_bytes(5, 9, 16) == 2 * 3 * 16);
  CHECK(bc_image_bytes(8, 1, 16) == 2 * 16);
  CHECK(bc_image_bytes(0, 7, 8) == 0);
  CHECK_THROWS_AS(bc_image_bytes(-1, 4, 8), std::invalid_argument);
  CHECK(decode_bc4_image(nullptr, 0, 0).empty());
}

TEST_CASE("a 6x5 BC4 image is decoded from 2x2 blocks and cropped at the edges", "[fast][block_decoding]") {
  // Block b (row-major: b = 2 * block_y + block_x) has red0 = 10 * (b + 1) <= red1 = 255 (6-value
  // mode) and code 0 (red0) everywhere except texel 5 (x 1, y 1): code 1 (255), bits 15..17 =
  // 001 -> byte 1 = 0x80; and texel 15 (x 3, y 3): code 6 (0), bits 45..47 = 110 -> byte 5 = 0xC0.
  std::vector<std::uint8_t> data;
  for (int b = 0; b < 4; ++b) {
    const std::array<std::uint8_t, 8> block = {std::uint8_t(10 * (b + 1)), 0xFF, 0x00, 0x80, 0x00, 0x00, 0x00, 0xC0};
    data.insert(data.end(), block.begin(), block.end());
  }
  REQUIRE(data.size() == bc_image_bytes(6, 5, 8));
  // The image in units of 1/255: block 0 (x 0..3, y 0..3) whole, with 255 at (1, 1) and 0 at
  // (3, 3); block 1 only x 4..5 (its 255 at local (1, 1) lands at (5, 1); its (3, 3) is cut);
  // blocks 2 and 3 only their row y = 4 (local row 0).
  const std::array<std::array<int, 6>, 5> expected = {{{10, 10, 10, 10, 20, 20},
                                                       {10, 255, 10, 10, 20, 255},
                                                       {10, 10, 10, 10, 20, 20},
                                                       {10, 10, 10, 0, 20, 20},
                                                       {30, 30, 30, 30, 40, 40}}};
  const std::vector<float> image = decode_bc4_image(data.data(), 6, 5);
  REQUIRE(image.size() == 30u);
  for (int y = 0; y < 5; ++y) {
    for (int x = 0; x < 6; ++x) {
      INFO("texel (" << x << ", " << y << ")");
      // Endpoints and the 6-value mode's 0 and 1: exact up to float rounding.
      CHECK(std::abs(double(image[std::size_t(y * 6 + x)]) - expected[y][x] / 255.0) <= kFloatRounding);
    }
  }
}

TEST_CASE("a 6x5 BC1 image is decoded from 2x2 blocks and cropped at the edges", "[fast][block_decoding]") {
  // Blocks red 0xF800 (00 F8), green 0x07E0 (E0 07), blue 0x001F (1F 00), white 0xFFFF (FF FF),
  // colour0 = colour1 (3-colour mode); code 0 everywhere except texel 5 (x 1, y 1), code 3
  // (transparent black): bits 10..11 = 11 -> byte 1 = 0x0C.
  const std::array<std::array<std::uint8_t, 2>, 4> colours = {{{0x00, 0xF8}, {0xE0, 0x07}, {0x1F, 0x00}, {0xFF, 0xFF}}};
  const std::array<Rgba8, 4> rgba = {{{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}, {255, 255, 255, 255}}};
  std::vector<std::uint8_t> data;
  for (const auto& c : colours) {
    const std::array<std::uint8_t, 8> block = {c[0], c[1], c[0], c[1], 0x00, 0x0C, 0x00, 0x00};
    data.insert(data.end(), block.begin(), block.end());
  }
  REQUIRE(data.size() == bc_image_bytes(6, 5, 8));
  const std::vector<std::uint8_t> image = decode_bc1_image(data.data(), 6, 5);
  REQUIRE(image.size() == 6u * 5u * 4u);
  for (int y = 0; y < 5; ++y) {
    for (int x = 0; x < 6; ++x) {
      INFO("texel (" << x << ", " << y << ")");
      // Transparent at local (1, 1): image (1, 1) in block 0 and (5, 1) in block 1; blocks 2 and 3
      // show only their local row 0.
      const bool hole = x % 4 == 1 && y % 4 == 1;
      const Rgba8 want = hole ? Rgba8{0, 0, 0, 0} : rgba[std::size_t((y / 4) * 2 + x / 4)];
      const std::size_t at = std::size_t(y * 6 + x) * 4;
      CHECK(Rgba8{image[at], image[at + 1], image[at + 2], image[at + 3]} == want);
    }
  }
}

TEST_CASE("a 5x5 BC3 image is decoded from 2x2 blocks and cropped at the edges", "[fast][block_decoding]") {
  // Block b: alpha0 = alpha1 = 60 * b + 15 (6-value mode, code 0 everywhere: 15, 75, 135, 195
  // exactly), colour0 = colour1 = 0xF800 for b even, 0x001F for b odd (code 0 everywhere).
  std::vector<std::uint8_t> data;
  for (int b = 0; b < 4; ++b) {
    const auto a = std::uint8_t(60 * b + 15);
    const std::uint8_t lo = b % 2 == 0 ? 0x00 : 0x1F, hi = b % 2 == 0 ? 0xF8 : 0x00;
    const std::array<std::uint8_t, 16> block = {a, a, 0, 0, 0, 0, 0, 0, lo, hi, lo, hi, 0, 0, 0, 0};
    data.insert(data.end(), block.begin(), block.end());
  }
  REQUIRE(data.size() == bc_image_bytes(5, 5, 16));
  const std::vector<std::uint8_t> image = decode_bc3_image(data.data(), 5, 5);
  REQUIRE(image.size() == 5u * 5u * 4u);
  for (int y = 0; y < 5; ++y) {
    for (int x = 0; x < 5; ++x) {
      INFO("texel (" << x << ", " << y << ")");
      const int b = (y / 4) * 2 + x / 4;
      const Rgba8 want =
          b % 2 == 0 ? Rgba8{255, 0, 0, std::uint8_t(60 * b + 15)} : Rgba8{0, 0, 255, std::uint8_t(60 * b + 15)};
      const std::size_t at = std::size_t(y * 5 + x) * 4;
      CHECK(Rgba8{image[at], image[at + 1], image[at + 2], image[at + 3]} == want);
    }
  }
}
