#pragma once
// The density volumes of a scene's convective clouds (docs/convection.md): one model volume
// (model::DensityVolume) per placed cloud, stacked as the z-layers of one 3D texture that the
// marcher reads (shaders/render/clouds.comp, unit 5). Needs a current OpenGL 4.5 context.
#include <string>
#include <vector>

#include "regional/convection.hpp"
#include "shader_math/shader_math.hpp"

namespace nephele::render {

class ConvectiveVolumes {
 public:
  // Voxels per edge of each cloud's volume: a cumulonimbus of about 11 km gets 86 m voxels,
  // finer than the renderer's steps through it at 15 km and more (docs/convection.md).
  static constexpr int default_size = 128;
  // Computes each cloud's volume (at most MAX_CONVECTIVE clouds); none for an empty list.
  explicit ConvectiveVolumes(const std::vector<regional::ConvectiveCloud>& clouds, int size = default_size);
  ~ConvectiveVolumes();
  ConvectiveVolumes(const ConvectiveVolumes&) = delete;
  ConvectiveVolumes& operator=(const ConvectiveVolumes&) = delete;

  const std::vector<regional::ConvectiveCloud>& clouds() const { return clouds_; }
  int size() const { return size_; }
  int count() const { return static_cast<int>(clouds_.size()); }
  unsigned texture() const { return texture_; }  // 0 when there are no clouds
  // One line per volume built: "convective_volume cumulonimbus 128^3 (N bricks of M)".
  const std::vector<std::string>& passes() const { return passes_; }
  // GPU time of each volume's density pass, ms.
  const std::vector<double>& build_ms() const { return build_ms_; }
  // The stack read back (volume c's voxels from c size^3 on), for the marcher's C++ twin.
  std::vector<float> read() const;
  // The marcher's parameters of cloud c.
  glsl::ConvectiveParams params(int c) const;

 private:
  std::vector<regional::ConvectiveCloud> clouds_;
  int size_;
  unsigned texture_ = 0;
  std::vector<std::string> passes_;
  std::vector<double> build_ms_;
};

}  // namespace nephele::render
