#include "files/texture_containers.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>
#include <stdexcept>

#include "core/error.hpp"
#include "core/half_float.hpp"
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

void check_layers(int layers, const char* container) {
  if (layers != 1 && layers != 6) throw std::invalid_argument(std::string(container) + ": one image or a cube of six");
}

// A chain's images at their layout's places in one buffer.
std::vector<unsigned char> encode_in_memory(const ContainerLayout& layout, const MipChain& chain, TexelFormat format,
                                            GreyLayout grey) {
  std::vector<unsigned char> out(layout.file_bytes, 0);
  std::copy(layout.header.begin(), layout.header.end(), out.begin());
  for (int k = 0; k < chain.count(); ++k)
    for (int layer = 0; layer < chain.layers; ++layer) {
      const std::vector<unsigned char> bytes =
          encode_rows(chain.image(k, layer), chain.level_width(k), chain.level_height(k), chain.channels, format, grey);
      std::copy(bytes.begin(), bytes.end(), out.begin() + std::ptrdiff_t(layout.offsets[k][layer]));
    }
  return out;
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

std::uint64_t image_bytes(int width, int height, TexelFormat format) {
  if (is_block_compressed(format)) return compressed_image_bytes(width, height, block_format(format));
  return std::uint64_t(width) * std::uint64_t(height) * texel_block_bytes(format);
}

std::vector<unsigned char> encode_rows(const float* texels, int width, int rows, int channels, TexelFormat format,
                                       GreyLayout layout) {
  const std::size_t count = std::size_t(width) * std::size_t(rows);
  std::vector<float> spread;
  if (channels != format_channels(format)) {  // one channel into RGBA
    spread.resize(count * 4);
    for (std::size_t i = 0; i < count; ++i) {
      const float v = texels[i], colour = layout == GreyLayout::white_alpha ? 1.0f : v;
      spread[4 * i] = spread[4 * i + 1] = spread[4 * i + 2] = colour;
      spread[4 * i + 3] = v;
    }
    texels = spread.data();
  }
  if (is_block_compressed(format)) return compress_image(texels, width, rows, block_format(format));
  std::vector<unsigned char> out;
  out.reserve(std::size_t(image_bytes(width, rows, format)));
  const std::size_t values = count * std::size_t(format_channels(format));
  for (std::size_t i = 0; i < values; ++i) {
    const float v = texels[i];
    switch (format) {
      case TexelFormat::r16f: {
        const std::uint16_t h = core::half_from_float(v);
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
  return out;
}

ContainerLayout ktx2_layout(int width, int height, int layers, int levels, TexelFormat format) {
  check_layers(layers, "KTX2");
  const bool cube = layers == 6;
  const bool block = is_block_compressed(format);
  const std::uint32_t bytes = texel_block_bytes(format);
  ContainerLayout layout;
  std::vector<unsigned char>& out = layout.header;
  // Section 3.1: the file identifier «KTX 20»\r\n\x1A\n.
  const unsigned char identifier[12] = {0xAB, 0x4B, 0x54, 0x58, 0x20, 0x32, 0x30, 0xBB, 0x0D, 0x0A, 0x1A, 0x0A};
  for (unsigned char byte : identifier) out.push_back(byte);
  // Section 3.2, header: vkFormat, typeSize (1 for block formats and 8-bit data), pixelWidth,
  // pixelHeight, pixelDepth, layerCount, faceCount, levelCount, supercompressionScheme.
  const std::uint32_t type_size = block || format == TexelFormat::rgba8 ? 1u : bytes;
  for (std::uint32_t v : {vk_format(format), type_size, std::uint32_t(width), std::uint32_t(height), 0u, 0u,
                          cube ? 6u : 1u, std::uint32_t(levels), 0u})
    put32(out, v);
  // Section 3.3, index: dfd offset and length, kvd offset and length, sgd offset and length (64-bit).
  const std::size_t index_at = out.size();
  put32(out, 0), put32(out, 0), put32(out, 0), put32(out, 0), put64(out, 0), put64(out, 0);
  // Section 3.4, level index: {byteOffset, byteLength, uncompressedByteLength} for level 0 first.
  const std::size_t level_index_at = out.size();
  for (int k = 0; k < levels; ++k) put64(out, 0), put64(out, 0), put64(out, 0);

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
  const std::uint64_t alignment = std::lcm<std::uint64_t>(bytes, 4);
  layout.offsets.assign(std::size_t(levels), std::vector<std::uint64_t>(std::size_t(layers)));
  std::uint64_t at = out.size();
  for (int k = levels - 1; k >= 0; --k) {
    at = (at + alignment - 1) / alignment * alignment;
    const std::uint64_t image = image_bytes(std::max(1, width >> k), std::max(1, height >> k), format);
    for (int layer = 0; layer < layers; ++layer) layout.offsets[k][layer] = at + image * layer;
    set64(out, level_index_at + 24 * k + 0, at);
    set64(out, level_index_at + 24 * k + 8, image * layers);
    set64(out, level_index_at + 24 * k + 16, image * layers);
    at += image * layers;
  }
  layout.file_bytes = at;
  set32(out, index_at + 0, std::uint32_t(dfd_at));
  set32(out, index_at + 4, std::uint32_t(dfd_length));
  set32(out, index_at + 8, std::uint32_t(kvd_at));
  set32(out, index_at + 12, std::uint32_t(kvd_length));
  return layout;
}

ContainerLayout dds_layout(int width, int height, int layers, int levels, TexelFormat format) {
  check_layers(layers, "DDS");
  const bool cube = layers == 6;
  const bool block = is_block_compressed(format);
  const bool legacy = block || format == TexelFormat::rgba8;
  const std::uint32_t bytes = texel_block_bytes(format);
  ContainerLayout layout;
  std::vector<unsigned char>& out = layout.header;
  put32(out, 0x20534444u);  // "DDS "
  // DDS_HEADER (124 bytes). Flags: CAPS | HEIGHT | WIDTH | PIXELFORMAT | MIPMAPCOUNT, and PITCH
  // for uncompressed data or LINEARSIZE for blocks.
  put32(out, 124);
  put32(out, 0x1u | 0x2u | 0x4u | 0x1000u | 0x20000u | (block ? 0x80000u : 0x8u));
  put32(out, std::uint32_t(height));  // dwHeight
  put32(out, std::uint32_t(width));   // dwWidth
  // dwPitchOrLinearSize: bytes per row, or the base level's bytes for block formats.
  put32(out, block ? std::uint32_t(image_bytes(width, height, format)) : std::uint32_t(width) * bytes);
  put32(out, 0);                               // dwDepth
  put32(out, std::uint32_t(levels));           // dwMipMapCount
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
  const bool mips = levels > 1;
  put32(out, 0x1000u | (mips ? 0x400000u : 0u) | (mips || cube ? 0x8u : 0u));
  put32(out, cube ? 0x200u | 0xFC00u : 0u);
  put32(out, 0), put32(out, 0), put32(out, 0);  // dwCaps3, dwCaps4, dwReserved2
  if (!legacy) {
    // DDS_HEADER_DXT10: dxgiFormat, resourceDimension (3: TEXTURE2D), miscFlag
    // (0x4: TEXTURECUBE), arraySize (1), miscFlags2 (0: alpha mode unknown).
    const std::uint32_t dxgi = format == TexelFormat::r16f ? 54u : format == TexelFormat::r32f ? 41u : 61u;
    put32(out, dxgi), put32(out, 3), put32(out, cube ? 0x4u : 0u), put32(out, 1), put32(out, 0);
  }
  layout.offsets.assign(std::size_t(levels), std::vector<std::uint64_t>(std::size_t(layers)));
  std::uint64_t at = out.size();
  for (int layer = 0; layer < layers; ++layer)
    for (int k = 0; k < levels; ++k) {
      layout.offsets[k][layer] = at;
      at += image_bytes(std::max(1, width >> k), std::max(1, height >> k), format);
    }
  layout.file_bytes = at;
  return layout;
}

std::vector<unsigned char> encode_ktx2(const MipChain& chain, TexelFormat format, GreyLayout layout) {
  check_chain(chain, format);
  return encode_in_memory(ktx2_layout(chain.width, chain.height, chain.layers, chain.count(), format), chain, format,
                          layout);
}

std::vector<unsigned char> encode_dds(const MipChain& chain, TexelFormat format, GreyLayout layout) {
  check_chain(chain, format);
  return encode_in_memory(dds_layout(chain.width, chain.height, chain.layers, chain.count(), format), chain, format,
                          layout);
}

namespace {

std::runtime_error write_error(const std::filesystem::path& path, const std::string& what, int error) {
  return std::runtime_error("could not write " + path.string() + " (" + what + "): " + std::strerror(error));
}

}  // namespace

ContainerWriter::ContainerWriter(std::filesystem::path path, ContainerLayout layout, TexelFormat format,
                                 GreyLayout grey, int band_rows)
    : path_(std::move(path)), layout_(std::move(layout)), format_(format), grey_(grey), band_rows_(band_rows) {
  if (band_rows_ < 0 || band_rows_ % 4 != 0) throw std::invalid_argument("ContainerWriter: bands of 4 k rows");
  fd_.reset(::open(path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666));
  if (fd_.get() < 0) throw write_error(path_, "create", errno);
  // The full length first: the padding between levels reads as zeros, as encode_ktx2 writes it.
  if (::ftruncate(fd_.get(), off_t(layout_.file_bytes)) != 0) throw write_error(path_, "set its length", errno);
  if (!core::write_exactly_at(fd_.get(), layout_.header.data(), layout_.header.size(), 0))
    throw write_error(path_, "header", errno);
  written_.assign(layout_.offsets.empty() ? 0 : layout_.offsets[0].size(), false);
}

void ContainerWriter::write_layer(int layer, const MipChain& chain) {
  if (chain.layers != 1 || chain.count() != int(layout_.offsets.size()) || layer < 0 || layer >= int(written_.size()))
    throw std::invalid_argument("ContainerWriter: a layer's chain that does not match the layout");
  check_chain(chain, format_);
  for (int k = 0; k < chain.count(); ++k) {
    const int width = chain.level_width(k), height = chain.level_height(k);
    // Bands of whole block rows of about 4 M texels: the RGBA spread of a 16384 face's rows stays small.
    const int band = band_rows_ > 0 ? band_rows_ : std::max(4, ((1 << 22) / width) / 4 * 4);
    for (int row = 0; row < height; row += band) {
      const int rows = std::min(band, height - row);
      const std::vector<unsigned char> bytes = encode_rows(
          chain.image(k, 0) + std::size_t(row) * width * chain.channels, width, rows, chain.channels, format_, grey_);
      const std::uint64_t at = layout_.offsets[k][layer] + image_bytes(width, row, format_);
      if (!core::write_exactly_at(fd_.get(), bytes.data(), bytes.size(), off_t(at)))
        throw write_error(path_, "level " + std::to_string(k), errno);
    }
  }
  written_[layer] = true;
}

void ContainerWriter::close() {
  for (std::size_t layer = 0; layer < written_.size(); ++layer)
    if (!written_[layer])
      throw std::logic_error("ContainerWriter: layer " + std::to_string(layer) + " of " + path_.string() +
                             " was not written");
  if (::fsync(fd_.get()) != 0) throw write_error(path_, "fsync", errno);
  if (!fd_.close()) throw write_error(path_, "close", errno);
}

}  // namespace nephele::files
