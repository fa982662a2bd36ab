#pragma once
// GPU texture containers with full mip chains, written from their specifications: KTX 2.0
// (Khronos, "KTX File Format Specification", version 2.0, with the Khronos Data Format
// Specification 1.3) and DDS (Microsoft, "DDS_HEADER structure", "DDS_PIXELFORMAT",
// "DDS_HEADER_DXT10", "Programming Guide for DDS"). docs/export.md says which program reads
// which variant.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/file_descriptor.hpp"

#include "files/mip_chain.hpp"

namespace nephele::files {

// How a texel is stored. r8, r16f, r32f: one channel (8-bit unsigned normalised, binary16,
// binary32); rgba8: four 8-bit channels; bc1, bc3, bc4: the block formats of
// files/block_compression.hpp (bc1 opaque RGB from RGBA texels, bc3 RGBA, bc4 one channel).
enum class TexelFormat { r8, r16f, r32f, rgba8, bc1, bc3, bc4 };
bool is_block_compressed(TexelFormat format);
// The channels a chain must have for `format`: 1 for r8, r16f, r32f and bc4, 4 (RGBA) otherwise.
int format_channels(TexelFormat format);
// ktx2's --format words: "r16f", "r32f", "r8", "bc4" (core::InputError naming --format otherwise).
TexelFormat parse_ktx2_format(const std::string& word);
// "VK_FORMAT_R16_SFLOAT (76)" and so on, for READMEs.
std::string vk_format_name(TexelFormat format);
// Vulkan format codes (Vulkan specification, VkFormat): R8_UNORM 9, R8G8B8A8_UNORM 37,
// R16_SFLOAT 76, R32_SFLOAT 100, BC1_RGB_UNORM_BLOCK 131, BC3_UNORM_BLOCK 137,
// BC4_UNORM_BLOCK 139.
std::uint32_t vk_format(TexelFormat format);

// A one-channel chain's texels in a four-channel format: the value in R, G, B and A (grey), or
// RGB white with the value in alpha (a cloud colour map, alpha unassociated).
enum class GreyLayout { grey, white_alpha };

// Where a container file's images lie: the bytes before them (header and indices) and the byte
// offset of image `layer` of each level; the file is file_bytes long, zeros where nothing is
// written (the padding between KTX2 levels). Known from the sizes alone, so that a file can be
// written face by face (ContainerWriter) without holding every face.
struct ContainerLayout {
  std::vector<unsigned char> header;
  std::vector<std::vector<std::uint64_t>> offsets;  // [level][layer]
  std::uint64_t file_bytes = 0;
};

// A KTX2 file of `levels` levels of `layers` images width x height (6 layers: a cube map,
// faceCount 6; otherwise one 2D image): the Data Format Descriptor of the format (linear
// transfer, BT.709 primaries), the key/value data KTXorientation = "rd" and KTXwriter, no
// supercompression, levels stored smallest first as section 3.9 wants, each face's rows (or
// rows of blocks) without padding.
ContainerLayout ktx2_layout(int width, int height, int layers, int levels, TexelFormat format);
// A DDS file of the same (6 layers: a cube map with all six face bits; otherwise 2D), each
// face's levels together (DDS's order), rows top-down. rgba8, bc1, bc3 and bc4 use the legacy
// header that every DDS loader reads (rgba8 as RGB + alpha masks, the block formats by the
// FourCC "DXT1", "DXT5" and "ATI1"); r8, r16f and r32f the DX10 extension header
// (DXGI_FORMAT_R8_UNORM 61, R16_FLOAT 54, R32_FLOAT 41; Direct3D 10+ engines, DirectXTex).
ContainerLayout dds_layout(int width, int height, int layers, int levels, TexelFormat format);

// The bytes of a width x height image in `format`.
std::uint64_t image_bytes(int width, int height, TexelFormat format);
// The bytes of `rows` rows of an image `width` wide in `format` from texels of `channels`
// floats (format_channels(format), or 1 spread into RGBA by `layout`). Block formats encode
// whole rows of blocks, so an image encoded in bands of a multiple of 4 rows gives the bytes of
// the whole image.
std::vector<unsigned char> encode_rows(const float* texels, int width, int rows, int channels, TexelFormat format,
                                       GreyLayout layout = GreyLayout::grey);

// The KTX2 or DDS file of every level of `chain` in memory. `chain` has format_channels(format)
// channels, or 1 with `layout` saying how to fill RGBA.
std::vector<unsigned char> encode_ktx2(const MipChain& chain, TexelFormat format, GreyLayout layout = GreyLayout::grey);
std::vector<unsigned char> encode_dds(const MipChain& chain, TexelFormat format, GreyLayout layout = GreyLayout::grey);

// A container file written layer by layer at its layout's places, for cube maps too large to
// hold with their mip chains (a 16384 cover's chain is 8.6 GB of floats): the caller makes one
// face's chain at a time. The bytes are encode_ktx2's or encode_dds's for the whole chain.
// Every write is checked (std::runtime_error naming the path).
class ContainerWriter {
 public:
  // Creates `path` (it must not exist) at its full length. Each level is encoded in bands of
  // band_rows rows (a multiple of 4; 0: about 4 M texels a band).
  ContainerWriter(std::filesystem::path path, ContainerLayout layout, TexelFormat format,
                  GreyLayout grey = GreyLayout::grey, int band_rows = 0);
  // Every level of image `layer` from `chain` (one layer, the layout's sizes).
  void write_layer(int layer, const MipChain& chain);
  // Checks that every layer came and fsyncs the file.
  void close();

 private:
  std::filesystem::path path_;
  ContainerLayout layout_;
  TexelFormat format_;
  GreyLayout grey_;
  int band_rows_;
  core::FileDescriptor fd_;
  std::vector<bool> written_;
};

}  // namespace nephele::files
