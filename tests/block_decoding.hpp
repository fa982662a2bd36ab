#pragma once
// An independent decoder of block-compressed textures for the tests, written from the
// specifications only: Khronos Data Format Specification 1.3, "S3TC Compressed Texture Image
// Formats" (BC1/DXT1, BC3/DXT5) and "RGTC Compressed Texture Image Formats" (BC4 unsigned), with
// Microsoft's "Block Compression (Direct3D 10)" as a cross-check. It shares no code with the
// program, so a test can compare what the program (or the GPU) decodes or encodes against it.
//
// Layout (both specifications): a block covers 4x4 texels; multi-byte fields are little-endian;
// texel (x, y) of a block is number i = 4 * y + x, and its index is the bits starting at
// bit 2 * i (BC1 colour, 32 bits from byte 4) or 3 * i (BC4 / BC3 alpha, 48 bits from byte 2).
//
// Rounding, and the tolerance a test must allow:
// - BC1 endpoints: RGB565 is expanded to 8 bits by bit replication, (c5 << 3) | (c5 >> 2) and
//   (c6 << 2) | (c6 >> 4). This is an exact function of the bits; it is within 0.72 of the real
//   unorm value c * 255 / 31 (or / 63), so another decoder that rounds that value may differ by 1.
// - BC1 interpolated colours: the spec gives them in real arithmetic, (2 * c0 + c1) / 3,
//   (c0 + 2 * c1) / 3 and (c0 + c1) / 2, and lets implementations differ in how they round. This
//   decoder evaluates them on the 8-bit expanded endpoints and rounds to nearest (thirds never
//   tie; the half in 3-colour mode rounds up). A test comparing with the spec's value or with
//   another decoder allows +-1 per channel; texels that select an endpoint or transparent black
//   are exact.
// - BC4 (and BC3 alpha): the spec's values are red0, red1 (each / 255), the weighted means
//   ((8 - c) * red0 + (c - 1) * red1) / 7 or ((6 - c) * red0 + (c - 1) * red1) / 5, and exactly
//   0 and 1 for codes 6 and 7 of the 6-value mode. decode_bc4_block_float returns them as the
//   float nearest the real value (a test allows float rounding, 1e-6, and nothing else);
//   decode_bc4_block and BC3's alpha round the 8-bit value (a multiple of 1/7 or 1/5, never a
//   tie) to nearest: endpoints, 0 and 255 are exact, interpolated values +-1 against another
//   decoder.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace nephele::test {

using Rgba8 = std::array<std::uint8_t, 4>;
// 16 texels of one block, row-major: texel i is row i / 4, column i % 4.
using Rgba8Block = std::array<Rgba8, 16>;

// A BC1 (DXT1 with 1-bit alpha) block of 8 bytes: colour0 > colour1 (as 16-bit integers) is the
// 4-colour mode, otherwise the 3-colour mode, where code 3 is transparent black (0, 0, 0, 0).
Rgba8Block decode_bc1_block(const std::uint8_t* block8);

// A BC4 unsigned (RGTC1 red) block of 8 bytes: red0 > red1 gives 8 values, otherwise 6 values
// and 0 and 1. The 8-bit version rounds to nearest; the float version is the exact real value
// (rounded to float) in [0, 1].
std::array<std::uint8_t, 16> decode_bc4_block(const std::uint8_t* block8);
std::array<float, 16> decode_bc4_block_float(const std::uint8_t* block8);

// A BC3 (DXT5) block of 16 bytes: alpha from the first 8 bytes (interpolated as BC4), colour
// from the BC1 block in the last 8 bytes, always in the 4-colour mode whatever the endpoints'
// order.
Rgba8Block decode_bc3_block(const std::uint8_t* block16);

// Bytes of a width x height image of blocks of block_bytes each: ceil(w / 4) * ceil(h / 4) *
// block_bytes. Throws std::invalid_argument for a negative size.
std::size_t bc_image_bytes(int width, int height, int block_bytes);

// Whole images: blocks in row-major block order; the texels are returned row-major, width x
// height (the parts of the right and bottom blocks outside the image are dropped). The data holds
// bc_image_bytes(width, height, 8 or 16) bytes. Throws std::invalid_argument for a negative size.
std::vector<float> decode_bc4_image(const std::uint8_t* data, int width, int height);
// RGBA8, 4 bytes a texel.
std::vector<std::uint8_t> decode_bc1_image(const std::uint8_t* data, int width, int height);
std::vector<std::uint8_t> decode_bc3_image(const std::uint8_t* data, int width, int height);

}  // namespace nephele::test
