#include "files/texture_containers.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>
#include <stdexcept>

#include "core/error.hpp"
#include "files/block_compression.hpp"

namespace nephele::files {
namespace {

// Little-endian writers (both formats are little-endian throughout).
void put32(std::vector<unsigned char>& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back((unsigned char)(v >> (8 * i)));
}
void put64(std::vector<unsigned char>& out, std::uint64_t v) {
  for (int i = 0; i < 8; ++i) out.push_back((unsigned char)(v >> (8 * i)));
}
void set32(std::vector<unsigned char>& out, std::size_t at, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out[at + i] = (unsigned char)(v >> (8 * i));
}
void set64(std::vector<unsigned char>& out, std::size_t at, std::uint64_t v) {
  for (int i = 0; i < 8; ++i) out[at + i] = (unsigned char)(v >> (8 * i));
}
void pad_to(std::vector<unsigned char>& out, std::size_t alignment) {
  while (out.size() % alignment != 0) out.push_back(0);
}

unsigned char unorm8(float v) {
  return (unsigned char)std::lround(255.0f * (std::isnan(v) ? 0.0f : std::clamp(v, 0.0f, 1.0f)));
}

BlockFormat block_format(TexelFormat format) {
  return format == TexelFormat::bc1   ? BlockFormat::bc1
         : format == TexelFormat::bc3 ? BlockFormat::bc3
                                      : BlockFormat::bc4;
}

// Bytes of one texel (uncompressed) or one 4x4 block.
std::uint32_t texel_block_bytes(TexelFormat format) {
  switch (format) {
    case TexelFormat::r8: return 1;
    case TexelFormat::r16f: return 2;
    case TexelFormat::r32f: return 4;
    case TexelFormat::rgba8: return 4;
    default: return std::uint32_t(block_bytes(block_format(format)));
  }
}

void check_chain(const MipChain& chain, TexelFormat format) {
  if (chain.count() < 1 || (chain.channels != format_channels(format) && chain.channels != 1))
    throw std::invalid_argument("texture container: the mip chain's channels do not match the format");
}

// Image `layer` of `level` with format_channels(format) channels: a one-channel chain is spread
// into RGBA by `layout`.
std::vector<float> image_in_channels(const MipChain& chain, int level, int layer, TexelFormat format,
                                     GreyLayout layout) {
  const float* image = chain.image(level, layer);
  const std::size_t floats = chain.image_floats(level);
  const int channels = format_channels(format);
  if (channels == chain.channels) return std::vector<float>(image, image + floats);
  std::vector<float> rgba(floats * 4);
  for (std::size_t i = 0; i < floats; ++i) {
    const float v = image[i], colour = layout == GreyLayout::white_alpha ? 1.0f : v;
    rgba[4 * i] = rgba[4 * i + 1] = rgba[4 * i + 2] = colour;
    rgba[4 * i + 3] = v;
  }
  return rgba;
}

// The bytes of image `layer` of `level` in `format`, appended.
void put_image(std::vector<unsigned char>& out, const MipChain& chain, int level, int layer, TexelFormat format,
               GreyLayout layout) {
  const std::vector<float> texels = image_in_channels(chain, level, layer, format, layout);
  const int width = chain.level_width(level), height = chain.level_height(level);
  if (is_block_compressed(format)) {
    const std::vector<unsigned char> blocks = compress_image(texels.data(), width, height, block_format(format));
    out.insert(out.end(), blocks.begin(), blocks.end());
    return;
  }
  for (float v : texels) {
    switch (format) {
      case TexelFormat::r16f: {
        const std::uint16_t h = half_from_float(v);
        out.push_back((unsigned char)(h & 0xff));
        out.push_back((unsigned char)(h >> 8));
        break;
      }
      case TexelFormat::r32f: {
        std::uint32_t bits;
        std::memcpy(&bits, &v, 4);
        put32(out, bits);
        break;
      }
      default: out.push_back(unorm8(v));  // r8, rgba8
    }
  }
}

// One sample of a Data Format Descriptor (Khronos Data Format Specification 1.3, section 5.15).
struct DfdSample {
  std::uint32_t offset, bits, channel, lower, upper;
};
// The samples of `format` and its colour model (KHR_DF_MODEL_RGBSDA 1 unless a block model), from
// the specification's sections on RGBSDA, S3TC (BC1, BC3) and RGTC (BC4).
std::vector<DfdSample> dfd_samples(TexelFormat format, std::uint32_t& model) {
  model = 1;
  switch (format) {
    case TexelFormat::r8: return {{0, 8, 0x00, 0, 255}};
    // Float and signed qualifiers (0x80 | 0x40) on the red channel; range -1..1 as floats.
    case TexelFormat::r16f: return {{0, 16, 0xC0, 0xBF800000u, 0x3F800000u}};
    case TexelFormat::r32f: return {{0, 32, 0xC0, 0xBF800000u, 0x3F800000u}};
    case TexelFormat::rgba8: return {{0, 8, 0, 0, 255}, {8, 8, 1, 0, 255}, {16, 8, 2, 0, 255}, {24, 8, 15, 0, 255}};
    // KHR_DF_MODEL_BC1A (128): one 64-bit sample, channel 0 (colour, opaque).
    case TexelFormat::bc1: model = 128; return {{0, 64, 0, 0, 0xFFFFFFFFu}};
    // KHR_DF_MODEL_BC3 (130): alpha (channel 15) in the first 64 bits, colour (0) in the second.
    case TexelFormat::bc3: model = 130; return {{0, 64, 15, 0, 0xFFFFFFFFu}, {64, 64, 0, 0, 0xFFFFFFFFu}};
    // KHR_DF_MODEL_BC4 (131): one 64-bit sample of channel 0 (data).
    case TexelFormat::bc4: model = 131; return {{0, 64, 0, 0, 0xFFFFFFFFu}};
  }
  return {};
}

}  // namespace

bool is_block_compressed(TexelFormat format) {
  return format == TexelFormat::bc1 || format == TexelFormat::bc3 || format == TexelFormat::bc4;
}

int format_channels(TexelFormat format) {
  return format == TexelFormat::rgba8 || format == TexelFormat::bc1 || format == TexelFormat::bc3 ? 4 : 1;
}

TexelFormat parse_ktx2_format(const std::string& word) {
  if (word == "r16f") return TexelFormat::r16f;
  if (word == "r32f") return TexelFormat::r32f;
  if (word == "r8") return TexelFormat::r8;
  if (word == "bc4") return TexelFormat::bc4;
  throw core::InputError("--format", word, "r16f, r32f, r8, bc4");
}

std::uint32_t vk_format(TexelFormat format) {
  switch (format) {
    case TexelFormat::r8: return 9;
    case TexelFormat::r16f: return 76;
    case TexelFormat::r32f: return 100;
    case TexelFormat::rgba8: return 37;
    case TexelFormat::bc1: return 131;
    case TexelFormat::bc3: return 137;
    case TexelFormat::bc4: return 139;
  }
  return 0;
}

std::string vk_format_name(TexelFormat format) {
  const char* name = "";
  switch (format) {
    case TexelFormat::r8: name = "VK_FORMAT_R8_UNORM"; break;
    case TexelFormat::r16f: name = "VK_FORMAT_R16_SFLOAT"; break;
    case TexelFormat::r32f: name = "VK_FORMAT_R32_SFLOAT"; break;
    case TexelFormat::rgba8: name = "VK_FORMAT_R8G8B8A8_UNORM"; break;
    case TexelFormat::bc1: name = "VK_FORMAT_BC1_RGB_UNORM_BLOCK"; break;
    case TexelFormat::bc3: name = "VK_FORMAT_BC3_UNORM_BLOCK"; break;
    case TexelFormat::bc4: name = "VK_FORMAT_BC4_UNORM_BLOCK"; break;
  }
  return std::string(name) + " (" + std::to_string(vk_format(format)) + ")";
}

std::uint16_t half_from_float(float value) {
  std::uint32_t f;
  std::memcpy(&f, &value, 4);
  const std::uint32_t sign = (f >> 16) & 0x8000u;
  const std::uint32_t exponent = (f >> 23) & 0xffu;
  std::uint32_t mantissa = f & 0x7fffffu;
  if (exponent == 0xff) return std::uint16_t(sign | 0x7c00u | (mantissa ? 0x200u : 0u));  // inf, NaN
  const int e = int(exponent) - 127 + 15;
  if (e >= 31) return std::uint16_t(sign | 0x7c00u);  // overflow
  if (e <= 0) {                                       // subnormal half or zero
    if (e < -10) return std::uint16_t(sign);
    mantissa |= 0x800000u;
    const int shift = 14 - e;
    std::uint32_t h = mantissa >> shift;
    const std::uint32_t rest = mantissa & ((1u << shift) - 1), halfway = 1u << (shift - 1);
    if (rest > halfway || (rest == halfway && (h & 1u))) ++h;
    return std::uint16_t(sign | h);
  }
  std::uint32_t h = (std::uint32_t(e) << 10) | (mantissa >> 13);
  const std::uint32_t rest = mantissa & 0x1fffu;
  if (rest > 0x1000u || (rest == 0x1000u && (h & 1u))) ++h;  // may carry into the exponent: correct
  return std::uint16_t(sign | h);
}

float float_from_half(std::uint16_t h) {
  const int exponent = (h >> 10) & 31, mantissa = h & 1023;
  const float magnitude =
      exponent == 0 ? std::ldexp(float(mantissa), -24) : std::ldexp(float(mantissa + 1024), exponent - 25);
  return (h & 0x8000) ? -magnitude : magnitude;
}

std::vector<unsigned char> encode_ktx2(const MipChain& chain, TexelFormat format, GreyLayout layout) {
  check_chain(chain, format);
  const bool cube = chain.layers == 6;
  if (!cube && chain.layers != 1) throw std::invalid_argument("KTX2: one image or a cube of six");
  const bool block = is_block_compressed(format);
  const std::uint32_t bytes = texel_block_bytes(format);
  const std::uint32_t levels = std::uint32_t(chain.count());
  std::vector<unsigned char> out;
  // Section 3.1: the file identifier «KTX 20»\r\n\x1A\n.
  const unsigned char identifier[12] = {0xAB, 0x4B, 0x54, 0x58, 0x20, 0x32, 0x30, 0xBB, 0x0D, 0x0A, 0x1A, 0x0A};
  for (unsigned char byte : identifier) out.push_back(byte);
  // Section 3.2, header: vkFormat, typeSize (1 for block formats and 8-bit data), pixelWidth,
  // pixelHeight, pixelDepth, layerCount, faceCount, levelCount, supercompressionScheme.
  const std::uint32_t type_size = block || format == TexelFormat::rgba8 ? 1u : bytes;
  for (std::uint32_t v : {vk_format(format), type_size, std::uint32_t(chain.width), std::uint32_t(chain.height), 0u, 0u,
                          cube ? 6u : 1u, levels, 0u})
    put32(out, v);
  // Section 3.3, index: dfd offset and length, kvd offset and length, sgd offset and length (64-bit).
  const std::size_t index_at = out.size();
  put32(out, 0), put32(out, 0), put32(out, 0), put32(out, 0), put64(out, 0), put64(out, 0);
  // Section 3.4, level index: {byteOffset, byteLength, uncompressedByteLength} for level 0 first.
  const std::size_t level_index_at = out.size();
  for (std::uint32_t k = 0; k < levels; ++k) put64(out, 0), put64(out, 0), put64(out, 0);

  // Section 3.5 and the Khronos Data Format Specification 1.3, section 5 (basic descriptor
  // block) and the chapters on S3TC and RGTC for the block formats' samples.
  std::uint32_t model = 1;
  const std::vector<DfdSample> samples = dfd_samples(format, model);
  const std::size_t dfd_at = out.size();
  const std::uint32_t block_size = 24 + 16 * std::uint32_t(samples.size());
  put32(out, 4 + block_size);           // dfdTotalSize
  put32(out, 0);                        // vendorId 0 (Khronos), descriptorType 0 (basic)
  put32(out, 2u | (block_size << 16));  // versionNumber 2 (KDF 1.3), descriptorBlockSize
  // colorModel, colorPrimaries 1 (BT709), transferFunction 1 (LINEAR: coverage is data), flags 0.
  put32(out, model | (1u << 8) | (1u << 16));
  put32(out, block ? 0x0303u : 0u);  // texelBlockDimension0..3, each stored as value - 1: 4 x 4 or 1 x 1
  put32(out, bytes);                 // bytesPlane0
  put32(out, 0);                     // bytesPlane4..7
  for (const DfdSample& s : samples) {
    put32(out, s.offset | ((s.bits - 1) << 16) | (s.channel << 24));  // bitOffset, bitLength - 1, channelType
    put32(out, 0);                                                    // samplePosition0..3
    put32(out, s.lower);
    put32(out, s.upper);
  }
  const std::size_t dfd_length = out.size() - dfd_at;

  // Section 3.6, key/value data: entries sorted by key, each {keyAndValueByteLength, key NUL
  // value, padding to 4}. KTXorientation "rd": s grows right, t grows down (row 0 is t = 0).
  const std::size_t kvd_at = out.size();
  const std::pair<std::string, std::string> entries[] = {{"KTXorientation", "rd"}, {"KTXwriter", "nephele"}};
  for (const auto& [key, value] : entries) {
    std::string text = key;
    text.push_back('\0');
    text += value;
    text.push_back('\0');
    put32(out, std::uint32_t(text.size()));
    out.insert(out.end(), text.begin(), text.end());
    pad_to(out, 4);
  }
  const std::size_t kvd_length = out.size() - kvd_at;

  // Section 3.9: levels from the smallest to the base, each aligned to lcm(texel block size, 4);
  // a cube level is its faces in order.
  const std::size_t alignment = std::lcm<std::size_t>(bytes, 4);
  for (int k = int(levels) - 1; k >= 0; --k) {
    pad_to(out, alignment);
    const std::size_t level_at = out.size();
    for (int layer = 0; layer < chain.layers; ++layer) put_image(out, chain, k, layer, format, layout);
    const std::size_t level_length = out.size() - level_at;
    set64(out, level_index_at + 24 * k + 0, level_at);
    set64(out, level_index_at + 24 * k + 8, level_length);
    set64(out, level_index_at + 24 * k + 16, level_length);
  }
  set32(out, index_at + 0, std::uint32_t(dfd_at));
  set32(out, index_at + 4, std::uint32_t(dfd_length));
  set32(out, index_at + 8, std::uint32_t(kvd_at));
  set32(out, index_at + 12, std::uint32_t(kvd_length));
  return out;
}

std::vector<unsigned char> encode_dds(const MipChain& chain, TexelFormat format, GreyLayout layout) {
  check_chain(chain, format);
  const bool cube = chain.layers == 6;
  if (!cube && chain.layers != 1) throw std::invalid_argument("DDS: one image or a cube of six");
  const bool block = is_block_compressed(format);
  const bool legacy = block || format == TexelFormat::rgba8;
  const std::uint32_t bytes = texel_block_bytes(format);
  std::vector<unsigned char> out;
  put32(out, 0x20534444u);  // "DDS "
  // DDS_HEADER (124 bytes). Flags: CAPS | HEIGHT | WIDTH | PIXELFORMAT | MIPMAPCOUNT, and PITCH
  // for uncompressed data or LINEARSIZE for blocks.
  put32(out, 124);
  put32(out, 0x1u | 0x2u | 0x4u | 0x1000u | 0x20000u | (block ? 0x80000u : 0x8u));
  put32(out, std::uint32_t(chain.height));  // dwHeight
  put32(out, std::uint32_t(chain.width));   // dwWidth
  // dwPitchOrLinearSize: bytes per row, or the base level's bytes for block formats.
  put32(out, block ? std::uint32_t(compressed_image_bytes(chain.width, chain.height, block_format(format)))
                   : std::uint32_t(chain.width) * bytes);
  put32(out, 0);                               // dwDepth
  put32(out, std::uint32_t(chain.count()));    // dwMipMapCount
  for (int i = 0; i < 11; ++i) put32(out, 0);  // dwReserved1
  // DDS_PIXELFORMAT (32 bytes).
  put32(out, 32);
  if (format == TexelFormat::rgba8) {
    put32(out, 0x40u | 0x1u);  // DDPF_RGB | DDPF_ALPHAPIXELS
    put32(out, 0);             // dwFourCC
    put32(out, 32);            // dwRGBBitCount
    put32(out, 0x000000ffu), put32(out, 0x0000ff00u), put32(out, 0x00ff0000u), put32(out, 0xff000000u);
  } else {
    put32(out, 0x4u);  // DDPF_FOURCC
    const char* four_cc = format == TexelFormat::bc1   ? "DXT1"
                          : format == TexelFormat::bc3 ? "DXT5"
                          : format == TexelFormat::bc4 ? "ATI1"
                                                       : "DX10";
    out.insert(out.end(), four_cc, four_cc + 4);
    for (int i = 0; i < 5; ++i) put32(out, 0);
  }
  // dwCaps: DDSCAPS_TEXTURE, DDSCAPS_MIPMAP and DDSCAPS_COMPLEX with more than one level, COMPLEX
  // for a cube; dwCaps2: DDSCAPS2_CUBEMAP and all six face bits.
  const bool mips = chain.count() > 1;
  put32(out, 0x1000u | (mips ? 0x400000u : 0u) | (mips || cube ? 0x8u : 0u));
  put32(out, cube ? 0x200u | 0xFC00u : 0u);
  put32(out, 0), put32(out, 0), put32(out, 0);  // dwCaps3, dwCaps4, dwReserved2
  if (!legacy) {
    // DDS_HEADER_DXT10: dxgiFormat, resourceDimension (3: TEXTURE2D), miscFlag
    // (0x4: TEXTURECUBE), arraySize (1), miscFlags2 (0: alpha mode unknown).
    const std::uint32_t dxgi = format == TexelFormat::r16f ? 54u : format == TexelFormat::r32f ? 41u : 61u;
    put32(out, dxgi), put32(out, 3), put32(out, cube ? 0x4u : 0u), put32(out, 1), put32(out, 0);
  }
  for (int layer = 0; layer < chain.layers; ++layer)
    for (int k = 0; k < chain.count(); ++k) put_image(out, chain, k, layer, format, layout);
  return out;
}

}  // namespace nephele::files
