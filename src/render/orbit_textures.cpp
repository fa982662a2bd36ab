#include "render/orbit_textures.hpp"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/half_float.hpp"
#include "core/mip_levels.hpp"
#include "core/parallel_rows.hpp"
#include "shader_math/shader_math.hpp"

namespace nephele::render {

namespace {

// `count` texels of `channels` floats as half floats of `out_channels` into `halves` (resized):
// the channels the source has are copied, a missing fourth is an alpha of 1 and other missing
// ones repeat the last (a grey map's value as RGB). Converted on every core.
void half_texels(const float* texels, std::size_t count, int channels, int out_channels,
                 std::vector<std::uint16_t>& halves) {
  halves.resize(count * std::size_t(out_channels));
  const std::uint16_t one = core::half_from_float(1.0f);
  constexpr std::size_t block = 4096;  // texels a share of the work
  core::parallel_rows(static_cast<int>((count + block - 1) / block), [&](int begin, int end) {
    for (std::size_t k = std::size_t(begin) * block, last = std::min(count, std::size_t(end) * block); k < last; ++k) {
      const float* in = texels + k * std::size_t(channels);
      std::uint16_t* out = halves.data() + k * std::size_t(out_channels);
      for (int c = 0; c < out_channels; ++c)
        out[c] = c < channels ? core::half_from_float(in[c]) : c == 3 ? one : core::half_from_float(in[channels - 1]);
    }
  });
}

// An equirect texture of `format` with every mip level, from `channels` floats a texel (level 0):
// `upload(id, level, width, height, texels)` fills a level; the levels are made on the CPU
// (core/mip_levels.hpp). It is filtered trilinearly, repeating in longitude and clamped in
// latitude.
template <class Upload>
GLuint equirect_texture_of(int width, int height, int channels, const std::vector<float>& level0, GLenum format,
                           Upload&& upload) {
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &id);
  const int levels = 1 + static_cast<int>(std::floor(std::log2(std::max(width, height))));
  glTextureStorage2D(id, levels, format, width, height);
  upload(id, 0, width, height, level0);
  const std::vector<std::vector<float>> chain = core::mip_levels(level0, width, height, channels, levels);
  for (int level = 1; level < levels; ++level)
    upload(id, level, std::max(1, width >> level), std::max(1, height >> level), chain[size_t(level - 1)]);
  glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return id;
}

// An equirect half-float texture of `out_channels` (GL_RG16F for 2, GL_RGB16F for 3, GL_RGBA16F for 4) from
// `channels` floats a texel. Each level goes up in bands of rows through one buffer: a buffer
// of the whole level would be fresh memory, and on a virtual machine each fresh page costs a
// fault of several microseconds (docs/orbit_view.md, "Cost").
GLuint half_equirect_texture(const core::ImageData& image, int out_channels) {
  const int channels = image.channels;
  const GLenum layout = out_channels == 2 ? GL_RG : out_channels == 3 ? GL_RGB : GL_RGBA;
  const GLenum format = out_channels == 2 ? GL_RG16F : out_channels == 3 ? GL_RGB16F : GL_RGBA16F;
  std::vector<std::uint16_t> halves;
  return equirect_texture_of(image.width, image.height, channels, image.pixels, format,
                             [&](GLuint id, int level, int width, int height, const std::vector<float>& texels) {
                               constexpr int band_texels = 1 << 18;
                               const int band_rows = std::max(1, band_texels / width);
                               glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
                               for (int row = 0; row < height; row += band_rows) {
                                 const int rows = std::min(band_rows, height - row);
                                 half_texels(texels.data() + std::size_t(row) * width * channels,
                                             std::size_t(rows) * width, channels, out_channels, halves);
                                 glTextureSubImage2D(id, level, 0, row, width, rows, layout, GL_HALF_FLOAT,
                                                     halves.data());
                               }
                               glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
                             });
}

}  // namespace

unsigned colour_map_texture(const core::ImageData& image) { return half_equirect_texture(image, 4); }

unsigned water_fraction_texture(const core::ImageData& image) {
  std::vector<float> fraction(static_cast<size_t>(image.width) * image.height);
  for (size_t k = 0; k < fraction.size(); ++k) fraction[k] = std::clamp(image.pixels[k * image.channels], 0.0f, 1.0f);
  return equirect_texture_of(image.width, image.height, 1, fraction, GL_R8,
                             [](GLuint id, int level, int width, int height, const std::vector<float>& texels) {
                               std::vector<unsigned char> bytes(texels.size());
                               for (size_t k = 0; k < bytes.size(); ++k)
                                 bytes[k] = static_cast<unsigned char>(std::lround(255.0f * texels[k]));
                               glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
                               glTextureSubImage2D(id, level, 0, 0, width, height, GL_RED, GL_UNSIGNED_BYTE,
                                                   bytes.data());
                               glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
                             });
}

unsigned slope_texture(const core::ImageData& image) {
  // (east, north) slopes, and with a third channel the roughness (an RG texture reads 0 there).
  return half_equirect_texture(image, image.channels >= 3 ? 3 : 2);
}

namespace {

// The texels as the orbit shader reads them: (cover, tau, cloud top km, 0). Clear texels take the
// unorganised cloud's top (TOP_BOUNDARY_LAYER_KM), so that the filtered tops at a cloud's edge blend
// towards a cloud's height and not towards the ground. Without the cover's own tau and tops the
// shader derives both from the filtered coverage (cloud_properties.glsl's fallbacks): derived
// per texel and then filtered, they would carry the texel grid into the image.
std::vector<float> cover_channels(const CoverCube& cover) {
  const size_t texels = cover.texels.size();
  const bool own = !cover.optical_thickness.empty();
  std::vector<float> rgba(4 * texels, 0.0f);
  for (size_t k = 0; k < texels; ++k) {
    const float c = cover.texels[k];
    rgba[4 * k] = c;
    if (own) {
      rgba[4 * k + 1] = cover.optical_thickness[k];
      rgba[4 * k + 2] = c > 0.0f ? cover.cloud_top[k] : glsl::TOP_BOUNDARY_LAYER_KM;
    }
  }
  return rgba;
}

}  // namespace

unsigned cover_texture(const CoverCube& cover) {
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_CUBE_MAP, 1, &id);
  const int levels = 1 + static_cast<int>(std::floor(std::log2(cover.size)));
  // Half floats: coverage, tau and heights in km need 3 digits, not float's 7 (half the upload
  // and memory of RGBA32F).
  glTextureStorage2D(id, levels, GL_RGBA16F, cover.size, cover.size);
  // Rows from t = 0 in file order: what glTexSubImage expects for a cube face (cubemaps/README.md).
  const std::vector<float> rgba = cover_channels(cover);
  std::vector<std::uint16_t> halves;
  half_texels(rgba.data(), rgba.size() / 4, 4, 4, halves);
  glTextureSubImage3D(id, 0, 0, 0, 0, cover.size, cover.size, 6, GL_RGBA, GL_HALF_FLOAT, halves.data());
  // The levels of each face on the CPU (core/mip_levels.hpp), as OpenGL makes them: per face.
  const size_t face_floats = 4 * static_cast<size_t>(cover.size) * cover.size;
  for (int face = 0; face < 6; ++face) {
    const std::vector<float> level0(rgba.begin() + static_cast<std::ptrdiff_t>(face * face_floats),
                                    rgba.begin() + static_cast<std::ptrdiff_t>((face + 1) * face_floats));
    const std::vector<std::vector<float>> chain = core::mip_levels(level0, cover.size, cover.size, 4, levels);
    for (int level = 1; level < levels; ++level) {
      const int size = std::max(1, cover.size >> level);
      const std::vector<float>& texels = chain[size_t(level - 1)];
      half_texels(texels.data(), texels.size() / 4, 4, 4, halves);
      glTextureSubImage3D(id, level, 0, 0, face, size, size, 1, GL_RGBA, GL_HALF_FLOAT, halves.data());
    }
  }
  glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return id;
}

}  // namespace nephele::render
