#include "files/texture_containers.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "core/error.hpp"

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

float clamp01(float v) { return std::isnan(v) ? 0.0f : std::clamp(v, 0.0f, 1.0f); }

// One sample in the container's format, appended little-endian.
void put_sample(std::vector<unsigned char>& out, float v, TextureSample sample) {
  switch (sample) {
    case TextureSample::r8: out.push_back((unsigned char)std::lround(255.0f * clamp01(v))); break;
    case TextureSample::r16f: {
      const std::uint16_t h = half_from_float(v);
      out.push_back((unsigned char)(h & 0xff));
      out.push_back((unsigned char)(h >> 8));
      break;
    }
    case TextureSample::r32f: {
      std::uint32_t bits;
      std::memcpy(&bits, &v, 4);
      put32(out, bits);
      break;
    }
  }
}

void check_texels(const std::vector<float>& texels, int size) {
  if (size < 1 || texels.size() != 6u * std::size_t(size) * std::size_t(size))
    throw std::invalid_argument("cube map texels do not match the face size");
}

}  // namespace

TextureSample parse_texture_sample(const std::string& word) {
  if (word == "r16f") return TextureSample::r16f;
  if (word == "r32f") return TextureSample::r32f;
  if (word == "r8") return TextureSample::r8;
  throw core::InputError("--format", word, "r16f, r32f, r8");
}

int sample_bytes(TextureSample sample) {
  return sample == TextureSample::r8 ? 1 : sample == TextureSample::r16f ? 2 : 4;
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

std::uint32_t vk_format(TextureSample sample) {
  return sample == TextureSample::r8 ? 9u : sample == TextureSample::r16f ? 76u : 100u;
}

std::vector<unsigned char> encode_ktx2_cube(const std::vector<float>& texels, int size, TextureSample sample) {
  check_texels(texels, size);
  const std::uint32_t bytes = std::uint32_t(sample_bytes(sample));
  std::vector<unsigned char> out;
  // Section 3.1: the file identifier «KTX 20»\r\n\x1A\n.
  const unsigned char identifier[12] = {0xAB, 0x4B, 0x54, 0x58, 0x20, 0x32, 0x30, 0xBB, 0x0D, 0x0A, 0x1A, 0x0A};
  out.insert(out.end(), identifier, identifier + 12);
  // Section 3.2, header: vkFormat, typeSize, pixelWidth, pixelHeight, pixelDepth, layerCount,
  // faceCount, levelCount, supercompressionScheme.
  for (std::uint32_t v : {vk_format(sample), bytes, std::uint32_t(size), std::uint32_t(size), 0u, 0u, 6u, 1u, 0u})
    put32(out, v);
  // Section 3.3, index: dfd offset and length, kvd offset and length, sgd offset and length (64-bit).
  const std::size_t index_at = out.size();
  put32(out, 0), put32(out, 0), put32(out, 0), put32(out, 0), put64(out, 0), put64(out, 0);
  // Section 3.4, level index: one level {byteOffset, byteLength, uncompressedByteLength}.
  const std::size_t level_index_at = out.size();
  put64(out, 0), put64(out, 0), put64(out, 0);

  // Section 3.5 and the Khronos Data Format Specification 1.3, section 5 (basic descriptor block).
  const std::size_t dfd_at = out.size();
  const std::uint32_t block_size = 24 + 16;  // header words + one sample
  put32(out, 4 + block_size);                // dfdTotalSize
  put32(out, 0);                             // vendorId 0 (Khronos), descriptorType 0 (basic)
  put32(out, 2u | (block_size << 16));       // versionNumber 2 (KDF 1.3), descriptorBlockSize
  // colorModel 1 (KHR_DF_MODEL_RGBSDA), colorPrimaries 1 (BT709), transferFunction 1 (LINEAR), flags 0.
  put32(out, 1u | (1u << 8) | (1u << 16));
  put32(out, 0);      // texelBlockDimension0..3 = 1 (stored as value - 1)
  put32(out, bytes);  // bytesPlane0
  put32(out, 0);      // bytesPlane4..7
  // Sample: bitOffset 0, bitLength - 1, channelType RED (0) with qualifiers FLOAT (0x80) and
  // SIGNED (0x40) for the float formats; samplePosition 0; sampleLower, sampleUpper.
  const bool floating = sample != TextureSample::r8;
  const std::uint32_t channel = floating ? 0xC0u : 0x00u;
  put32(out, 0u | ((8 * bytes - 1) << 16) | (channel << 24));
  put32(out, 0);
  put32(out, floating ? 0xBF800000u : 0u);    // -1.0f for float formats, 0 for UNORM
  put32(out, floating ? 0x3F800000u : 255u);  // 1.0f for float formats, 255 for UNORM
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

  // Section 3.9: mip level data aligned to lcm(texel block size, 4) = 4 here; a cube level is
  // its faces in order, each face its rows without padding.
  pad_to(out, 4);
  const std::size_t level_at = out.size();
  for (float v : texels) put_sample(out, v, sample);
  const std::size_t level_length = out.size() - level_at;

  set32(out, index_at + 0, std::uint32_t(dfd_at));
  set32(out, index_at + 4, std::uint32_t(dfd_length));
  set32(out, index_at + 8, std::uint32_t(kvd_at));
  set32(out, index_at + 12, std::uint32_t(kvd_length));
  set64(out, level_index_at + 0, level_at);
  set64(out, level_index_at + 8, level_length);
  set64(out, level_index_at + 16, level_length);
  return out;
}

namespace {

// The DDS of `layers` images of width x height (6: a cube, faces in order), one mip level.
std::vector<unsigned char> encode_dds(const std::vector<float>& texels, int width, int height, int layers,
                                      DdsVariant variant) {
  const bool legacy = variant == DdsVariant::rgba8 || variant == DdsVariant::rgba8_white;
  const bool cube = layers == 6;
  const TextureSample sample = variant == DdsVariant::dx10_r16f   ? TextureSample::r16f
                               : variant == DdsVariant::dx10_r32f ? TextureSample::r32f
                                                                  : TextureSample::r8;
  const std::uint32_t pixel_bytes = legacy ? 4u : std::uint32_t(sample_bytes(sample));
  std::vector<unsigned char> out;
  put32(out, 0x20534444u);  // "DDS "
  // DDS_HEADER (124 bytes).
  put32(out, 124);
  put32(out, 0x1u | 0x2u | 0x4u | 0x8u | 0x1000u);  // CAPS | HEIGHT | WIDTH | PITCH | PIXELFORMAT
  put32(out, std::uint32_t(height));                // dwHeight
  put32(out, std::uint32_t(width));                 // dwWidth
  put32(out, std::uint32_t(width) * pixel_bytes);   // dwPitchOrLinearSize: bytes per row
  put32(out, 0);                                    // dwDepth
  put32(out, 1);                                    // dwMipMapCount
  for (int i = 0; i < 11; ++i) put32(out, 0);       // dwReserved1
  // DDS_PIXELFORMAT (32 bytes).
  put32(out, 32);
  if (legacy) {
    put32(out, 0x40u | 0x1u);  // DDPF_RGB | DDPF_ALPHAPIXELS
    put32(out, 0);             // dwFourCC
    put32(out, 32);            // dwRGBBitCount
    put32(out, 0x000000ffu), put32(out, 0x0000ff00u), put32(out, 0x00ff0000u), put32(out, 0xff000000u);
  } else {
    put32(out, 0x4u);         // DDPF_FOURCC
    put32(out, 0x30315844u);  // "DX10"
    for (int i = 0; i < 5; ++i) put32(out, 0);
  }
  put32(out, cube ? 0x1000u | 0x8u : 0x1000u);  // dwCaps: DDSCAPS_TEXTURE (| DDSCAPS_COMPLEX for a cube)
  put32(out, cube ? 0x200u | 0xFC00u : 0u);     // dwCaps2: DDSCAPS2_CUBEMAP and all six face bits
  put32(out, 0), put32(out, 0), put32(out, 0);  // dwCaps3, dwCaps4, dwReserved2
  if (!legacy) {
    // DDS_HEADER_DXT10: dxgiFormat, resourceDimension (3: TEXTURE2D), miscFlag
    // (0x4: TEXTURECUBE), arraySize (1), miscFlags2 (0: alpha mode unknown).
    const std::uint32_t dxgi = sample == TextureSample::r16f ? 54u : sample == TextureSample::r32f ? 41u : 61u;
    put32(out, dxgi), put32(out, 3), put32(out, cube ? 0x4u : 0u), put32(out, 1), put32(out, 0);
  }
  for (float v : texels) {
    if (legacy) {
      const auto byte = (unsigned char)std::lround(255.0f * clamp01(v));
      if (variant == DdsVariant::rgba8_white)
        out.insert(out.end(), {255, 255, 255, byte});
      else
        out.insert(out.end(), {byte, byte, byte, byte});
    } else {
      put_sample(out, v, sample);
    }
  }
  return out;
}

}  // namespace

std::vector<unsigned char> encode_dds_cube(const std::vector<float>& texels, int size, DdsVariant variant) {
  check_texels(texels, size);
  return encode_dds(texels, size, size, 6, variant);
}

std::vector<unsigned char> encode_dds_2d(const std::vector<float>& texels, int width, int height, DdsVariant variant) {
  if (width < 1 || height < 1 || texels.size() != std::size_t(width) * std::size_t(height))
    throw std::invalid_argument("DDS texels do not match the image size");
  return encode_dds(texels, width, height, 1, variant);
}

}  // namespace nephele::files
