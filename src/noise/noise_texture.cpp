#include "noise/noise_texture.hpp"

#include <epoxy/gl.h>

#include <algorithm>
#include <stdexcept>

#include "gpu/pass_timer.hpp"
#include "gpu/shader_bindings.hpp"
#include "shader_math/uniforms.hpp"

namespace nephele::noise {
namespace {

// The linker drops uniforms a kind does not read (the Worley part outside perlin-worley).
void set_active(const gpu::ComputeProgram& program, const std::string& name, int v) {
  if (program.has_uniform(name)) program.set(name, v);
}
void set_active(const gpu::ComputeProgram& program, const std::string& name, glsl::ivec3 v) {
  if (program.has_uniform(name)) program.set(name, v);
}

void set_channel(const gpu::ComputeProgram& program, const glsl::NoiseChannel& channel, const TextureSpec& spec,
                 int stride) {
  set_active(program, "u_channel.type", channel.type);
  glsl::set_uniform(program, "u_channel.fbm", channel.fbm, glsl::Members::active);
  glsl::set_uniform(program, "u_channel.worley", channel.worley, glsl::Members::active);
  set_active(program, "u_size", glsl::ivec3(spec.width, spec.height, spec.depth));
  set_active(program, "u_stride", stride);
}

// The frequency of the last octave, stepped as the shaders step it.
float last_frequency(const glsl::FbmParams& fbm) {
  float amplitude = 1.0f, frequency = fbm.frequency;
  glsl::ivec3 period = fbm.period;
  for (int k = 1; k < fbm.octaves; ++k) glsl::next_octave(fbm, amplitude, frequency, period);
  return frequency;
}

}  // namespace

TextureGenerator::TextureGenerator(size_t slab_bytes) : slab_bytes_(slab_bytes) {}

TextureGenerator::~TextureGenerator() = default;

gpu::ComputeProgram& TextureGenerator::program(const std::string& path, const Defines& defines) {
  std::string key = path;
  for (const auto& [name, value] : defines) key += " " + name + "=" + value;
  auto& slot = programs_[key];
  if (!slot) slot = std::make_unique<gpu::ComputeProgram>(path, defines);
  return *slot;
}

Volume TextureGenerator::generate(const TextureSpec& spec) {
  Volume out;
  generate(spec, out);
  return out;
}

void TextureGenerator::generate(const TextureSpec& spec, Volume& out) {
  validate(spec);
  timings_ = {};
  const int width = spec.width, height = spec.height, depth = spec.depth;
  const int channels = static_cast<int>(spec.channels.size());
  // Rows are stored a whole segment at a time (noise_rows.comp).
  const int stride = (width + glsl::NOISE_SEGMENT - 1) / glsl::NOISE_SEGMENT * glsl::NOISE_SEGMENT;
  const size_t slice_bytes = static_cast<size_t>(stride) * height * sizeof(float);
  GLint64 max_block = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &max_block);
  const size_t budget = std::min(slab_bytes_, static_cast<size_t>(std::max<GLint64>(max_block, 1)));
  if (slice_bytes > budget)
    throw std::runtime_error("one slice of " + std::to_string(width) + " x " + std::to_string(height) +
                             " texels exceeds the storage buffer limit");
  const int slices = static_cast<int>(std::min<size_t>(budget / slice_bytes, static_cast<size_t>(depth)));
  const int segments = (width + glsl::NOISE_SEGMENT - 1) / glsl::NOISE_SEGMENT;
  const GLuint capacity = static_cast<GLuint>(static_cast<size_t>(height) * slices * segments);

  gpu::reserve(values_, slice_bytes * slices);
  gpu::reserve(patches_, 16 + 16 * static_cast<size_t>(capacity));
  out.width = width;
  out.height = height;
  out.depth = depth;
  out.channels = channels;
  out.values.resize(static_cast<size_t>(width) * height * depth * channels);

  for (int c = 0; c < channels; ++c) {
    const glsl::NoiseChannel params = channel_params(spec, c);
    // Variants per type and octave count (noise_rows.comp): a SIMD driver runs both sides of
    // every branch, so the shader must know what it need not do.
    const bool has_worley = params.type != glsl::NOISE_PERLIN;
    Defines defines{{"NOISE_TYPE", std::to_string(params.type)},
                    {"NOISE_OCTAVES", std::to_string(params.fbm.octaves)},
                    {"NOISE_WORLEY_OCTAVES", std::to_string(params.worley.octaves)}};
    if (params.type == glsl::NOISE_PERLIN && glsl::perlin_row_is_wide(last_frequency(params.fbm)))
      defines.emplace_back("NOISE_PERLIN_WIDE", "1");
    gpu::ComputeProgram& rows = program("noise/noise_rows.comp", defines);
    set_channel(rows, params, spec, stride);
    gpu::ComputeProgram* patch =
        has_worley ? &program("noise/noise_patch.comp", {{"NOISE_TYPE", std::to_string(params.type)}}) : nullptr;
    if (patch) set_channel(*patch, params, spec, stride);
    for (int z0 = 0; z0 < depth; z0 += slices) {
      const int n = std::min(slices, depth - z0);
      gpu::PassTimer timer;
      const GLuint header[4] = {0u, capacity, 0u, 0u};
      patches_.write(header, sizeof header);
      // noise_patch.comp binds the same two buffers at the same points.
      static_assert(shader_bindings::noise_noise_patch::values == shader_bindings::noise_noise_rows::values &&
                    shader_bindings::noise_noise_patch::patches == shader_bindings::noise_noise_rows::patches);
      values_.bind(shader_bindings::noise_noise_rows::values);
      patches_.bind(shader_bindings::noise_noise_rows::patches);
      rows.set("u_z0", z0);
      rows.set("u_slices", n);
      gpu::DeviceTimer device;
      device.begin();
      rows.dispatch_covering(height, n, segments);
      device.end();
      ++timings_.dispatches;
      if (patch) {
        // The patch pass reads the list the row walk wrote; the host reads its count.
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        GLuint count = 0;
        patches_.read(&count, sizeof count);
        count = std::min(count, capacity);
        if (count > 0) {
          patch->set("u_z0", z0);
          device.begin();
          patch->dispatch_covering(static_cast<int>(count), 1, 1);
          device.end();
          timings_.patched_segments += count;
        }
      }
      glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
      timings_.compute_ms += timer.milliseconds();
      timings_.device_ms += device.milliseconds();

      timer.restart();
      // Mapped, a software driver's buffer is read in place (no staging copy).
      const auto* mapped = static_cast<const float*>(
          glMapNamedBufferRange(values_.id(), 0, static_cast<GLsizeiptr>(slice_bytes * n), GL_MAP_READ_BIT));
      if (!mapped) throw std::runtime_error("could not map the noise buffer");
      for (int z = 0; z < n; ++z)
        for (int y = 0; y < height; ++y) {
          const float* src = mapped + (static_cast<size_t>(z) * height + y) * stride;
          float* dst = out.values.data() + ((static_cast<size_t>(z0 + z) * height + y) * width) * channels + c;
          if (channels == 1) {
            std::copy(src, src + width, dst);
          } else {
            for (int x = 0; x < width; ++x) dst[static_cast<size_t>(x) * channels] = src[x];
          }
        }
      glUnmapNamedBuffer(values_.id());
      timings_.readback_ms += timer.milliseconds();
    }
  }
  if (glGetError() != GL_NO_ERROR) throw std::runtime_error("OpenGL error while generating noise");
}

Volume generate_cpu(const TextureSpec& spec) {
  validate(spec);
  using namespace glsl;
  Volume out{spec.width, spec.height, spec.depth, static_cast<int>(spec.channels.size()), {}};
  out.values.resize(static_cast<size_t>(out.width) * out.height * out.depth * out.channels);
  for (int c = 0; c < out.channels; ++c) {
    const NoiseChannel params = channel_params(spec, c);
    std::vector<float> row(static_cast<size_t>(out.width));
    for (int z = 0; z < out.depth; ++z)
      for (int y = 0; y < out.height; ++y) {
        for (int t0 = 0; t0 < out.width; t0 += NOISE_SEGMENT) {
          // As noise_rows.comp.
          const int count = std::min(NOISE_SEGMENT, out.width - t0);
          float sums[NOISE_SUMS] = {};
          const NoiseRowTarget target{sums, row.data()};
          const NoiseFinish finish{params.type, fbm_norm(params.fbm), fbm_norm(params.worley)};
          uvec2 beyond(0u);
          if (params.type == NOISE_PERLIN) {
            perlin_fbm_row(t0, count, y, z, params.fbm, 0, true, finish, target);
          } else if (params.type == NOISE_PERLIN_WORLEY) {
            perlin_fbm_row(t0, count, y, z, params.fbm, 0, false, finish, target);
            worley_fbm_row(t0, count, y, z, params.worley, NOISE_SEGMENT, true, finish, beyond, target);
          } else {
            worley_fbm_row(t0, count, y, z, params.fbm, 0, true, finish, beyond, target);
          }
          // As noise_patch.comp.
          for (int i = 0; i < count; ++i)
            if ((beyond[i >> 5] >> (i & 31)) & 1u) row[t0 + i] = reference_value(params, t0 + i, y, z);
        }
        for (int x = 0; x < out.width; ++x)
          out.values[((static_cast<size_t>(z) * out.height + y) * out.width + x) * out.channels + c] = row[x];
      }
  }
  return out;
}

float reference_value(const glsl::NoiseChannel& channel, int x, int y, int z) {
  return glsl::noise_channel_value(glsl::vec3(glsl::ivec3(x, y, z)) + 0.5f, channel);
}

double host_bytes(const TextureSpec& spec) {
  const double volume = 4.0 * spec.width * spec.height * spec.depth * static_cast<double>(spec.channels.size());
  // The volume, the atlas image handed to the writer and its encoded copy, plus one slab.
  return 3.0 * volume + static_cast<double>(TextureGenerator::slab_budget_bytes);
}

}  // namespace nephele::noise
