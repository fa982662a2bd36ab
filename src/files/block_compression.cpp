#include "files/block_compression.hpp"

#include <nvtt/nvtt.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace nephele::files {
namespace {

// Collects the blocks libnvtt hands over (no DDS header: the containers write their own).
struct BlockCollector : nvtt::OutputHandler {
  std::vector<unsigned char> bytes;
  void beginImage(int, int, int, int, int, int) override {}
  bool writeData(const void* data, int size) override {
    const auto* begin = static_cast<const unsigned char*>(data);
    bytes.insert(bytes.end(), begin, begin + size);
    return true;
  }
};

unsigned char to_byte(float v) {
  return static_cast<unsigned char>(std::lround(255.0f * (std::isnan(v) ? 0.0f : std::clamp(v, 0.0f, 1.0f))));
}

}  // namespace

int block_bytes(BlockFormat format) { return format == BlockFormat::bc3 ? 16 : 8; }
int block_channels(BlockFormat format) { return format == BlockFormat::bc4 ? 1 : 4; }

std::size_t compressed_image_bytes(int width, int height, BlockFormat format) {
  return std::size_t((width + 3) / 4) * std::size_t((height + 3) / 4) * std::size_t(block_bytes(format));
}

std::vector<unsigned char> compress_image(const float* texels, int width, int height, BlockFormat format) {
  if (width < 1 || height < 1) throw std::invalid_argument("block compression: empty image");
  // libnvtt takes 8-bit BGRA; BC4 encodes its red channel.
  const int channels = block_channels(format);
  std::vector<unsigned char> bgra(std::size_t(width) * height * 4);
  for (std::size_t i = 0; i < std::size_t(width) * height; ++i) {
    const float* t = texels + i * channels;
    unsigned char* p = &bgra[i * 4];
    if (channels == 1) {
      p[0] = p[1] = p[2] = p[3] = to_byte(t[0]);
    } else {
      p[0] = to_byte(t[2]), p[1] = to_byte(t[1]), p[2] = to_byte(t[0]), p[3] = to_byte(t[3]);
    }
  }
  nvtt::InputOptions input;
  input.setTextureLayout(nvtt::TextureType_2D, width, height);
  input.setMipmapData(bgra.data(), width, height);
  input.setMipmapGeneration(false);  // the containers give every level (files/mip_chain.hpp)
  input.setGamma(1.0f, 1.0f);        // linear data: no gamma conversion
  input.setAlphaMode(nvtt::AlphaMode_None);
  nvtt::CompressionOptions compression;
  compression.setFormat(format == BlockFormat::bc1   ? nvtt::Format_BC1
                        : format == BlockFormat::bc3 ? nvtt::Format_BC3
                                                     : nvtt::Format_BC4);
  // BC4 at libnvtt's best search. For BC1 and BC3 colour, libnvtt 2.0.8's cluster fit (its
  // normal and higher qualities) picks wrong indices in some blocks (errors up to 0.49 of the
  // range, measured with tests/block_decoding.hpp); its fastest colour encoder is right, within
  // the bound tests/test_texture_containers.cpp states.
  compression.setQuality(format == BlockFormat::bc4 ? nvtt::Quality_Production : nvtt::Quality_Fastest);
  BlockCollector collector;
  nvtt::OutputOptions output;
  output.setOutputHandler(&collector);
  output.setOutputHeader(false);
  nvtt::Compressor compressor;
  if (!compressor.process(input, compression, output) ||
      collector.bytes.size() != compressed_image_bytes(width, height, format))
    throw std::runtime_error("block compression failed (libnvtt)");
  return std::move(collector.bytes);
}

}  // namespace nephele::files
