// The test suite's own decoder of BC1, BC3 and BC4 blocks (block_decoding.hpp), written from the
// Khronos Data Format Specification's formulas; the rounding choices are stated in the header.
#include "block_decoding.hpp"

#include <stdexcept>
#include <string>

namespace nephele::test {

namespace {

std::uint32_t read_u16(const std::uint8_t* p) { return std::uint32_t(p[0]) | (std::uint32_t(p[1]) << 8); }

std::uint32_t read_u32(const std::uint8_t* p) { return read_u16(p) | (read_u16(p + 2) << 16); }

// The 48 bits of 3-bit indices of a BC4 block (bytes 2..7), little-endian.
std::uint64_t read_u48(const std::uint8_t* p) {
  std::uint64_t bits = 0;
  for (int k = 0; k < 6; ++k) bits |= std::uint64_t(p[k]) << (8 * k);
  return bits;
}

// round(n / d) for n >= 0, d > 0, where n / d is never exactly halfway (thirds, fifths,
// sevenths): floor((2n + d) / 2d).
std::uint8_t round_ratio(int n, int d) { return static_cast<std::uint8_t>((2 * n + d) / (2 * d)); }

// The four colours of a BC1 colour block, RGBA8, after the spec: RGB565 expanded by bit
// replication; codes 2 and 3 interpolated (four_colour) or the mean and transparent black.
std::array<Rgba8, 4> bc1_palette(std::uint32_t colour0, std::uint32_t colour1, bool four_colour) {
  auto expand = [](std::uint32_t c) {
    const int r5 = int((c >> 11) & 31u), g6 = int((c >> 5) & 63u), b5 = int(c & 31u);
    return std::array<int, 3>{(r5 << 3) | (r5 >> 2), (g6 << 2) | (g6 >> 4), (b5 << 3) | (b5 >> 2)};
  };
  const std::array<int, 3> c0 = expand(colour0), c1 = expand(colour1);
  std::array<Rgba8, 4> palette{};
  for (int ch = 0; ch < 3; ++ch) {
    palette[0][ch] = std::uint8_t(c0[ch]);
    palette[1][ch] = std::uint8_t(c1[ch]);
    if (four_colour) {
      // (2 c0 + c1) / 3 and (c0 + 2 c1) / 3, rounded to nearest (a third never ties).
      palette[2][ch] = round_ratio(2 * c0[ch] + c1[ch], 3);
      palette[3][ch] = round_ratio(c0[ch] + 2 * c1[ch], 3);
    } else {
      // (c0 + c1) / 2, halves rounded up; code 3 stays transparent black.
      palette[2][ch] = std::uint8_t((c0[ch] + c1[ch] + 1) / 2);
      palette[3][ch] = 0;
    }
  }
  palette[0][3] = palette[1][3] = palette[2][3] = 255;
  palette[3][3] = four_colour ? 255 : 0;
  return palette;
}

Rgba8Block decode_colour_block(const std::uint8_t* block8, bool force_four_colour) {
  const std::uint32_t colour0 = read_u16(block8), colour1 = read_u16(block8 + 2);
  const std::array<Rgba8, 4> palette = bc1_palette(colour0, colour1, force_four_colour || colour0 > colour1);
  const std::uint32_t bits = read_u32(block8 + 4);
  Rgba8Block texels{};
  for (int i = 0; i < 16; ++i) texels[i] = palette[(bits >> (2 * i)) & 3u];
  return texels;
}

// The BC4 value of code c as a numerator over a denominator of 255 * denominator: the real value
// in [0, 1] is numerator / (255 * denominator).
struct Bc4Value {
  int numerator;
  int denominator;
};

Bc4Value bc4_value(int red0, int red1, int code) {
  if (code == 0) return {red0, 1};
  if (code == 1) return {red1, 1};
  if (red0 > red1) return {(8 - code) * red0 + (code - 1) * red1, 7};
  if (code == 6) return {0, 1};
  if (code == 7) return {255, 1};
  return {(6 - code) * red0 + (code - 1) * red1, 5};
}

template <typename Value, typename Convert>
std::array<Value, 16> decode_bc4_generic(const std::uint8_t* block8, Convert convert) {
  const int red0 = block8[0], red1 = block8[1];
  const std::uint64_t bits = read_u48(block8 + 2);
  std::array<Value, 16> values{};
  for (int i = 0; i < 16; ++i) values[i] = convert(bc4_value(red0, red1, int((bits >> (3 * i)) & 7u)));
  return values;
}

void check_size(int width, int height) {
  if (width < 0 || height < 0)
    throw std::invalid_argument("block image size " + std::to_string(width) + "x" + std::to_string(height));
}

// Calls texel(block, local_index, image_index) for each texel of a width x height image of blocks
// of block_bytes, dropping the parts of edge blocks outside the image.
template <typename Texel>
void for_each_texel(const std::uint8_t* data, int width, int height, int block_bytes, Texel texel) {
  check_size(width, height);
  const int blocks_x = (width + 3) / 4, blocks_y = (height + 3) / 4;
  for (int by = 0; by < blocks_y; ++by) {
    for (int bx = 0; bx < blocks_x; ++bx) {
      const std::uint8_t* block = data + std::size_t(by * blocks_x + bx) * std::size_t(block_bytes);
      for (int i = 0; i < 16; ++i) {
        const int x = 4 * bx + i % 4, y = 4 * by + i / 4;
        if (x < width && y < height) texel(block, i, std::size_t(y) * std::size_t(width) + std::size_t(x));
      }
    }
  }
}

template <typename DecodeBlock>
std::vector<std::uint8_t> decode_rgba_image(const std::uint8_t* data, int width, int height, int block_bytes,
                                            DecodeBlock decode_block) {
  check_size(width, height);
  std::vector<std::uint8_t> rgba(std::size_t(width) * std::size_t(height) * 4);
  const std::uint8_t* decoded_block = nullptr;
  Rgba8Block texels{};
  for_each_texel(data, width, height, block_bytes, [&](const std::uint8_t* block, int i, std::size_t at) {
    if (block != decoded_block) {
      texels = decode_block(block);
      decoded_block = block;
    }
    for (int ch = 0; ch < 4; ++ch) rgba[4 * at + std::size_t(ch)] = texels[i][ch];
  });
  return rgba;
}

}  // namespace

Rgba8Block decode_bc1_block(const std::uint8_t* block8) { return decode_colour_block(block8, false); }

std::array<std::uint8_t, 16> decode_bc4_block(const std::uint8_t* block8) {
  // The 8-bit value is numerator / denominator, rounded to nearest.
  return decode_bc4_generic<std::uint8_t>(block8, [](Bc4Value v) { return round_ratio(v.numerator, v.denominator); });
}

std::array<float, 16> decode_bc4_block_float(const std::uint8_t* block8) {
  return decode_bc4_generic<float>(
      block8, [](Bc4Value v) { return static_cast<float>(double(v.numerator) / (255.0 * double(v.denominator))); });
}

Rgba8Block decode_bc3_block(const std::uint8_t* block16) {
  Rgba8Block texels = decode_colour_block(block16 + 8, true);
  const std::array<std::uint8_t, 16> alpha = decode_bc4_block(block16);
  for (int i = 0; i < 16; ++i) texels[i][3] = alpha[i];
  return texels;
}

std::size_t bc_image_bytes(int width, int height, int block_bytes) {
  check_size(width, height);
  if (block_bytes < 0) throw std::invalid_argument("negative block size " + std::to_string(block_bytes));
  return std::size_t((width + 3) / 4) * std::size_t((height + 3) / 4) * std::size_t(block_bytes);
}

std::vector<float> decode_bc4_image(const std::uint8_t* data, int width, int height) {
  check_size(width, height);
  std::vector<float> values(std::size_t(width) * std::size_t(height));
  const std::uint8_t* decoded_block = nullptr;
  std::array<float, 16> block_values{};
  for_each_texel(data, width, height, 8, [&](const std::uint8_t* block, int i, std::size_t at) {
    if (block != decoded_block) {
      block_values = decode_bc4_block_float(block);
      decoded_block = block;
    }
    values[at] = block_values[i];
  });
  return values;
}

std::vector<std::uint8_t> decode_bc1_image(const std::uint8_t* data, int width, int height) {
  return decode_rgba_image(data, width, height, 8, decode_bc1_block);
}

std::vector<std::uint8_t> decode_bc3_image(const std::uint8_t* data, int width, int height) {
  return decode_rgba_image(data, width, height, 16, decode_bc3_block);
}

}  // namespace nephele::test
