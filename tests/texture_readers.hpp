#pragma once
// Readers of the KTX2 and DDS containers for the tests, written from the specifications (KTX
// File Format Specification 2.0 sections 3.1-3.9 with the Khronos Data Format Specification 1.3
// section 5; Microsoft's "DDS_HEADER", "DDS_PIXELFORMAT", "DDS_HEADER_DXT10" and the
// "Programming Guide for DDS"), sharing no code with the writers: what a loader needs to find
// every level of every face and turn its bytes into values.
#include <cstdint>
#include <string>
#include <vector>

namespace nephele::test {

std::uint32_t le32(const std::string& bytes, std::size_t at);
std::uint64_t le64(const std::string& bytes, std::size_t at);
// IEEE 754 binary16 to float.
float float_from_half(std::uint16_t h);

struct Ktx2Sample {
  std::uint32_t bit_offset, bit_length, channel, lower, upper;  // bit_length as stored + 1
};
struct Ktx2Level {
  std::uint64_t offset, length, uncompressed_length;
};
struct Ktx2File {
  std::uint32_t vk_format, type_size, width, height, depth, layers, faces, level_count, supercompression;
  std::uint32_t dfd_offset, dfd_length, kvd_offset, kvd_length;
  std::vector<Ktx2Level> levels;  // level 0 (the base) first, as the level index lists them
  std::uint32_t color_model, primaries, transfer, block_width, block_height, bytes_plane0;
  std::vector<Ktx2Sample> samples;
  std::string orientation;
};
// Checks the identifier and the descriptor's sizes (Catch2 REQUIRE/CHECK) and reads every field.
Ktx2File read_ktx2(const std::string& bytes);

struct DdsFile {
  std::uint32_t flags, height, width, pitch_or_linear_size, mip_count, pixel_flags, rgb_bits, caps, caps2;
  std::string four_cc;     // "" without DDPF_FOURCC
  std::uint32_t masks[4];  // R, G, B, A
  std::uint32_t dxgi = 0;  // 0 without the DX10 header
  std::uint32_t dx10_dimension = 0, dx10_misc = 0, dx10_array_size = 0;
  std::size_t data_offset = 0;
  int faces = 1;  // 6 with DDSCAPS2_CUBEMAP
};
DdsFile read_dds(const std::string& bytes);

// The stored formats the tests decode.
enum class StoredFormat { r8, r16f, r32f, rgba8, bc1, bc3, bc4 };
// Bytes of a width x height image in `format` (blocks of 4 x 4 for the BC formats).
std::size_t stored_image_bytes(StoredFormat format, int width, int height);
// Decodes a width x height image stored at `data`: one float per texel for r8, r16f, r32f and
// bc4; four (RGBA) for rgba8, bc1 and bc3. The block formats through tests/block_decoding.hpp.
std::vector<float> decode_stored_image(StoredFormat format, const unsigned char* data, int width, int height);
// Where image `face` of mip `level` starts in a DDS file: after the headers, each face holds all
// its levels in turn (DDS's order), each max(1, size >> level) on a side.
std::size_t dds_image_offset(const DdsFile& dds, StoredFormat format, int face, int level);

// Level sizes: max(1, size >> level).
int mip_size(int size, int level);

}  // namespace nephele::test
