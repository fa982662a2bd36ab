#pragma once
// Tileable 3D noise textures on the GPU (shaders/noise/*.comp) and their CPU twin, which runs
// the same GLSL functions compiled as C++.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "gpu/compute_program.hpp"
#include "gpu/storage_buffer.hpp"
#include "noise/noise_spec.hpp"

namespace nephele::noise {

// Texel (x, y, z), channel c is values[((z * height + y) * width + x) * channels + c].
struct Volume {
  int width = 0, height = 0, depth = 0, channels = 0;
  std::vector<float> values;
  float at(int x, int y, int z, int c) const {
    return values[((static_cast<size_t>(z) * height + y) * width + x) * channels + c];
  }
};

struct GeneratorTimings {
  double compute_ms = 0;      // row walks and patches, until the GPU finished
  double device_ms = 0;       // their dispatches' GPU time (GL_TIME_ELAPSED; 0 where the driver gives none)
  double readback_ms = 0;     // copies to host memory and channel interleaving
  long patched_segments = 0;  // row segments with texels recomputed by noise_patch.comp
  int dispatches = 0;         // slabs times channels
};

// Needs a current OpenGL 4.5 context. Programs are compiled on first use and kept.
class TextureGenerator {
 public:
  // Largest storage buffer a dispatch uses; slices are grouped to stay within it.
  static constexpr size_t slab_budget_bytes = size_t(64) << 20;
  explicit TextureGenerator(size_t slab_bytes = slab_budget_bytes);
  ~TextureGenerator();
  TextureGenerator(const TextureGenerator&) = delete;
  TextureGenerator& operator=(const TextureGenerator&) = delete;

  // Validates the spec (SpecError) and computes every channel.
  Volume generate(const TextureSpec& spec);
  // The same into `out`, reusing its storage (as FastNoise fills a caller's array).
  void generate(const TextureSpec& spec, Volume& out);
  const GeneratorTimings& timings() const { return timings_; }

 private:
  using Defines = std::vector<std::pair<std::string, std::string>>;
  gpu::ComputeProgram& program(const std::string& path, const Defines& defines);
  std::map<std::string, std::unique_ptr<gpu::ComputeProgram>> programs_;
  size_t slab_bytes_;
  // Storage buffers kept between textures and grown when one needs more (allocating them costs a
  // software driver a page fault per 4 KiB): the values of one slab, and the patch list.
  gpu::StorageBuffer values_, patches_;
  GeneratorTimings timings_;
};

// The CPU twin: the same row walk and patching, one thread. For tests and small textures.
Volume generate_cpu(const TextureSpec& spec);

// One texel of one channel by the point functions (tileable_noise.glsl): the reference.
float reference_value(const glsl::NoiseChannel& channel, int x, int y, int z);

// Bytes of host memory generate() needs for a spec (the volume and its staging copies).
double host_bytes(const TextureSpec& spec);

}  // namespace nephele::noise
