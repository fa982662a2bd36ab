#include "studies/compression_error.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <unistd.h>

#include "core/half_float.hpp"
#include "files/atomic_output.hpp"
#include "files/image_files.hpp"
#include "files/mip_chain.hpp"
#include "files/texture_containers.hpp"

namespace nephele::studies {
namespace {

struct Case {
  const char* name;
  const char* used_by;
  files::TexelFormat format;
  files::GreyLayout layout;
  int channel;  // of the decoded texel that holds the coverage
};

// The base level of face `face` as `format` decoded back: a 2D DDS through OpenImageIO for the
// block formats (its cube reader does not read the levels below the base), the definitions
// otherwise (round to 8 bits, to binary16).
std::vector<float> decoded_face(const files::MipChain& chain, int face, const Case& c) {
  const float* texels = chain.image(0, face);
  const std::size_t n = std::size_t(chain.width) * chain.height;
  std::vector<float> out(n);
  if (!files::is_block_compressed(c.format)) {
    for (std::size_t i = 0; i < n; ++i) {
      const float v = texels[i];
      if (c.format == files::TexelFormat::r16f) {
        out[i] = core::float_from_half(core::half_from_float(v));
      } else if (c.format == files::TexelFormat::r32f) {
        out[i] = v;
      } else {
        out[i] = std::round(255.0f * v) / 255.0f;  // r8
      }
    }
    return out;
  }
  const files::MipChain one =
      files::build_mip_chain(std::vector<float>(texels, texels + n), chain.width, chain.height, 1, 1, 1);
  const std::vector<unsigned char> bytes = files::encode_dds(one, c.format, c.layout);
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("nephele_compression_" + std::to_string(::getpid()) + ".dds");
  files::write_file(path, bytes.data(), bytes.size());
  files::ImageData image = files::read_image(path);
  std::filesystem::remove(path);
  for (std::size_t i = 0; i < n; ++i)
    out[i] = image.pixels[i * image.channels + std::min(c.channel, image.channels - 1)];
  return out;
}

}  // namespace

std::vector<CompressionRow> compression_errors(const io::CoverFaces& faces) {
  const Case cases[] = {
      {"r32f", "ktx2 --format r32f, dds", files::TexelFormat::r32f, files::GreyLayout::grey, 0},
      {"r16f", "ktx2 (default), dds", files::TexelFormat::r16f, files::GreyLayout::grey, 0},
      {"r8", "ktx2 --format r8, dds (rgba8), png", files::TexelFormat::r8, files::GreyLayout::grey, 0},
      {"bc4", "ktx2 --format bc4, dds", files::TexelFormat::bc4, files::GreyLayout::grey, 0},
      {"bc3 alpha", "dds, eve, celestia", files::TexelFormat::bc3, files::GreyLayout::white_alpha, 3},
      {"bc3 grey", "dds (RGB)", files::TexelFormat::bc3, files::GreyLayout::grey, 1},
      {"bc1 grey", "(not written)", files::TexelFormat::bc1, files::GreyLayout::grey, 1},
  };
  const files::MipChain chain = files::build_mip_chain(faces.texels, faces.size, faces.size, 6, 1);
  std::vector<CompressionRow> rows;
  for (const Case& c : cases) {
    CompressionRow row{c.name, c.used_by};
    const auto start = std::chrono::steady_clock::now();
    const std::vector<unsigned char> dds = files::encode_dds(chain, c.format, c.layout);
    row.encode_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    row.megabytes_chain = double(dds.size()) / (1024.0 * 1024.0);
    const double base_texels = 6.0 * faces.size * faces.size;
    // Bits of one base-level texel: the sample, or a 4 x 4 block's 64 or 128 bits over 16 texels.
    row.bits_per_texel = c.format == files::TexelFormat::r32f                                        ? 32
                         : c.format == files::TexelFormat::r16f                                      ? 16
                         : c.format == files::TexelFormat::bc3 || c.format == files::TexelFormat::r8 ? 8
                                                                                                     : 4;
    double sum = 0;
    for (int f = 0; f < 6; ++f) {
      const std::vector<float> decoded = decoded_face(chain, f, c);
      const float* reference = chain.image(0, f);
      for (std::size_t i = 0; i < decoded.size(); ++i) {
        const double e = std::abs(double(decoded[i]) - reference[i]);
        sum += e * e;
        row.max = std::max(row.max, e);
      }
    }
    row.rms = std::sqrt(sum / base_texels);
    rows.push_back(row);
  }
  return rows;
}

}  // namespace nephele::studies
