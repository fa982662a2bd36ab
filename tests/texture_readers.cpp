#include "texture_readers.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>

#include "block_decoding.hpp"

namespace nephele::test {

std::uint32_t le32(const std::string& b, std::size_t at) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | (unsigned char)b[at + i];
  return v;
}
std::uint64_t le64(const std::string& b, std::size_t at) {
  return le32(b, at) | (std::uint64_t(le32(b, at + 4)) << 32);
}

float float_from_half(std::uint16_t h) {
  const int exponent = (h >> 10) & 31, mantissa = h & 1023;
  const float magnitude =
      exponent == 0 ? std::ldexp(float(mantissa), -24) : std::ldexp(float(mantissa + 1024), exponent - 25);
  return (h & 0x8000) ? -magnitude : magnitude;
}

int mip_size(int size, int level) { return size >> level > 0 ? size >> level : 1; }

Ktx2File read_ktx2(const std::string& b) {
  const unsigned char identifier[12] = {0xAB, 'K', 'T', 'X', ' ', '2', '0', 0xBB, '\r', '\n', 0x1A, '\n'};
  REQUIRE(b.size() > 80);
  REQUIRE(std::memcmp(b.data(), identifier, 12) == 0);
  Ktx2File k;
  std::uint32_t* header[] = {&k.vk_format, &k.type_size, &k.width,       &k.height,          &k.depth,
                             &k.layers,    &k.faces,     &k.level_count, &k.supercompression};
  for (int i = 0; i < 9; ++i) *header[i] = le32(b, 12 + 4 * i);
  k.dfd_offset = le32(b, 48), k.dfd_length = le32(b, 52), k.kvd_offset = le32(b, 56), k.kvd_length = le32(b, 60);
  CHECK(le64(b, 64) == 0);  // no supercompression global data
  const std::uint32_t count = k.level_count == 0 ? 1 : k.level_count;
  for (std::uint32_t level = 0; level < count; ++level) {
    const std::size_t at = 80 + 24 * std::size_t(level);
    k.levels.push_back({le64(b, at), le64(b, at + 8), le64(b, at + 16)});
  }
  const std::size_t d = k.dfd_offset;
  REQUIRE(d + k.dfd_length <= b.size());
  CHECK(le32(b, d) == k.dfd_length);      // dfdTotalSize
  CHECK(le32(b, d + 4) == 0);             // Khronos vendor, basic descriptor type
  CHECK((le32(b, d + 8) & 0xffff) == 2);  // version 2 (KDF 1.3)
  const std::uint32_t block_size = le32(b, d + 8) >> 16;
  CHECK(block_size == k.dfd_length - 4);  // descriptorBlockSize: one block
  k.color_model = le32(b, d + 12) & 0xff, k.primaries = (le32(b, d + 12) >> 8) & 0xff;
  k.transfer = (le32(b, d + 12) >> 16) & 0xff;
  k.block_width = (le32(b, d + 16) & 0xff) + 1, k.block_height = ((le32(b, d + 16) >> 8) & 0xff) + 1;
  k.bytes_plane0 = le32(b, d + 20) & 0xff;
  // Samples of 16 bytes after the 24 bytes of the block's header words.
  REQUIRE((block_size - 24) % 16 == 0);
  for (std::size_t at = d + 4 + 24; at < d + 4 + block_size; at += 16) {
    const std::uint32_t word = le32(b, at);
    k.samples.push_back({word & 0xffff, ((word >> 16) & 0xff) + 1, word >> 24, le32(b, at + 8), le32(b, at + 12)});
  }
  // Key/value pairs: length, "key\0value", padded to 4 bytes.
  for (std::size_t at = k.kvd_offset; at < k.kvd_offset + k.kvd_length;) {
    const std::uint32_t length = le32(b, at);
    const std::string entry = b.substr(at + 4, length);
    const std::string key = entry.substr(0, entry.find('\0'));
    if (key == "KTXorientation") k.orientation = std::string(entry.c_str() + key.size() + 1);
    at += 4 + ((length + 3) / 4) * 4;
  }
  return k;
}

DdsFile read_dds(const std::string& b) {
  REQUIRE(b.size() >= 128);
  REQUIRE(b.compare(0, 4, "DDS ") == 0);
  CHECK(le32(b, 4) == 124);  // dwSize
  CHECK(le32(b, 76) == 32);  // ddspf.dwSize
  DdsFile d;
  d.flags = le32(b, 8), d.height = le32(b, 12), d.width = le32(b, 16), d.pitch_or_linear_size = le32(b, 20);
  d.mip_count = le32(b, 28);
  d.pixel_flags = le32(b, 80);
  if (d.pixel_flags & 0x4u) d.four_cc = b.substr(84, 4);
  d.rgb_bits = le32(b, 88);
  for (int i = 0; i < 4; ++i) d.masks[i] = le32(b, 92 + 4 * i);
  d.caps = le32(b, 108), d.caps2 = le32(b, 112);
  d.data_offset = 128;
  if (d.four_cc == "DX10") {
    REQUIRE(b.size() >= 148);
    d.dxgi = le32(b, 128), d.dx10_dimension = le32(b, 132), d.dx10_misc = le32(b, 136);
    d.dx10_array_size = le32(b, 140);
    d.data_offset = 148;
  }
  d.faces = (d.caps2 & 0x200u) ? 6 : 1;
  return d;
}

std::size_t stored_image_bytes(StoredFormat format, int width, int height) {
  switch (format) {
    case StoredFormat::r8: return std::size_t(width) * height;
    case StoredFormat::r16f: return std::size_t(width) * height * 2;
    case StoredFormat::r32f:
    case StoredFormat::rgba8: return std::size_t(width) * height * 4;
    case StoredFormat::bc3: return bc_image_bytes(width, height, 16);
    default: return bc_image_bytes(width, height, 8);  // bc1, bc4
  }
}

std::vector<float> decode_stored_image(StoredFormat format, const unsigned char* data, int width, int height) {
  const std::size_t texels = std::size_t(width) * height;
  std::vector<float> out;
  switch (format) {
    case StoredFormat::r8:
      for (std::size_t i = 0; i < texels; ++i) out.push_back(data[i] / 255.0f);
      break;
    case StoredFormat::r16f:
      for (std::size_t i = 0; i < texels; ++i)
        out.push_back(float_from_half(std::uint16_t(data[2 * i] | (data[2 * i + 1] << 8))));
      break;
    case StoredFormat::r32f:
      out.resize(texels);
      std::memcpy(out.data(), data, texels * 4);  // little-endian hosts, as the tests run on
      break;
    case StoredFormat::rgba8:
      for (std::size_t i = 0; i < 4 * texels; ++i) out.push_back(data[i] / 255.0f);
      break;
    case StoredFormat::bc4: out = decode_bc4_image(data, width, height); break;
    case StoredFormat::bc1:
    case StoredFormat::bc3: {
      const std::vector<std::uint8_t> rgba =
          format == StoredFormat::bc1 ? decode_bc1_image(data, width, height) : decode_bc3_image(data, width, height);
      for (std::uint8_t v : rgba) out.push_back(v / 255.0f);
      break;
    }
  }
  return out;
}

std::size_t dds_image_offset(const DdsFile& dds, StoredFormat format, int face, int level) {
  const int levels = dds.mip_count == 0 ? 1 : int(dds.mip_count);
  std::size_t face_bytes = 0;
  for (int k = 0; k < levels; ++k)
    face_bytes += stored_image_bytes(format, mip_size(int(dds.width), k), mip_size(int(dds.height), k));
  std::size_t at = dds.data_offset + face_bytes * std::size_t(face);
  for (int k = 0; k < level; ++k)
    at += stored_image_bytes(format, mip_size(int(dds.width), k), mip_size(int(dds.height), k));
  return at;
}

}  // namespace nephele::test
