#pragma once
// GPU texture containers for a one-channel cube map, written from their specifications:
// KTX 2.0 (Khronos, "KTX File Format Specification", version 2.0) and DDS (Microsoft,
// "DDS_HEADER structure", "DDS_PIXELFORMAT", "DDS_HEADER_DXT10"). docs/export.md explains
// which program reads which variant.
#include <cstdint>
#include <string>
#include <vector>

namespace nephele::files {

// Sample formats of the containers: 16-bit half float, 32-bit float, 8-bit unsigned normalised.
enum class TextureSample { r16f, r32f, r8 };
TextureSample parse_texture_sample(const std::string& word);  // "r16f", "r32f", "r8"
int sample_bytes(TextureSample sample);

// IEEE 754 binary16 of `value`, rounded to nearest even; overflow gives infinity.
std::uint16_t half_from_float(float value);

// Vulkan format codes (Vulkan specification, VkFormat): R8_UNORM 9, R16_SFLOAT 76, R32_SFLOAT 100.
std::uint32_t vk_format(TextureSample sample);

// A KTX2 cube map of one mip level: `texels` holds 6 faces of size x size in GL order +X, -X,
// +Y, -Y, +Z, -Z, rows from t = 0 (docs/conventions.md), values in [0, 1]. With the Data
// Format Descriptor (one sample, linear transfer, BT.709 primaries), the key/value data
// KTXorientation = "rd" and KTXwriter, no supercompression.
std::vector<unsigned char> encode_ktx2_cube(const std::vector<float>& texels, int size, TextureSample sample);

// A DDS cube map of one mip level, faces in the same order and orientation (Direct3D uses the
// same face addressing as OpenGL). rgba8: the legacy header, an uncompressed 32-bit RGBA pixel
// format with coverage in R, G, B and A (what KSP's and Unity's DDS loaders read); otherwise
// the DX10 extension header with DXGI_FORMAT_R16_FLOAT (54), R32_FLOAT (41) or R8_UNORM (61)
// (Direct3D 10+ engines, DirectXTex/texconv).
// rgba8_white: the legacy header with RGB white and coverage in alpha (a cloud colour map).
enum class DdsVariant { rgba8, rgba8_white, dx10_r16f, dx10_r32f, dx10_r8 };
std::vector<unsigned char> encode_dds_cube(const std::vector<float>& texels, int size, DdsVariant variant);
// A 2D DDS of width x height texels (rows top-down as stored; one mip level), same variants.
std::vector<unsigned char> encode_dds_2d(const std::vector<float>& texels, int width, int height, DdsVariant variant);

}  // namespace nephele::files
