#include "render/convective_volumes.hpp"

#include <epoxy/gl.h>

#include <cmath>
#include <stdexcept>

#include "model/density_volume.hpp"

namespace nephele::render {

ConvectiveVolumes::ConvectiveVolumes(const std::vector<regional::ConvectiveCloud>& clouds, int size)
    : clouds_(clouds), size_(size) {
  if (static_cast<int>(clouds.size()) > glsl::MAX_CONVECTIVE)
    throw std::logic_error("ConvectiveVolumes: " + std::to_string(clouds.size()) + " clouds, at most " +
                           std::to_string(glsl::MAX_CONVECTIVE));
  if (clouds.empty()) return;  // a scene without convection computes no volume
  glCreateTextures(GL_TEXTURE_3D, 1, &texture_);
  glTextureStorage3D(texture_, 1, GL_R32F, size, size, size * count());
  glTextureParameteri(texture_, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(texture_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
    glTextureParameteri(texture_, wrap, GL_CLAMP_TO_EDGE);
  for (int c = 0; c < count(); ++c) {
    model::DensityVolume volume(size);
    volume.compute(clouds[c].model);
    glCopyImageSubData(volume.texture(), GL_TEXTURE_3D, 0, 0, 0, 0, texture_, GL_TEXTURE_3D, 0, 0, 0, c * size, size,
                       size, size);
    const model::PassStats& stats = volume.stats();
    build_ms_.push_back(stats.ms);
    passes_.push_back("convective_volume " + std::string(regional::convective_kind_name(clouds[c].kind)) + " " +
                      std::to_string(size) + "^3 (" + std::to_string(stats.bricks_computed) + " of " +
                      std::to_string(stats.bricks) + " bricks)");
  }
}

ConvectiveVolumes::~ConvectiveVolumes() {
  if (texture_ != 0) glDeleteTextures(1, &texture_);
}

std::vector<float> ConvectiveVolumes::read() const {
  std::vector<float> values(static_cast<size_t>(size_) * size_ * size_ * count());
  if (texture_ != 0)
    glGetTextureImage(texture_, 0, GL_RED, GL_FLOAT, static_cast<GLsizei>(values.size() * sizeof(float)),
                      values.data());
  return values;
}

glsl::ConvectiveParams ConvectiveVolumes::params(int c) const {
  const regional::ConvectiveCloud& cloud = clouds_.at(c);
  const double axis = cloud.axis_deg * M_PI / 180;
  glsl::ConvectiveParams p{};
  p.centre = glm::vec2(static_cast<float>(cloud.east_m), static_cast<float>(cloud.north_m));
  p.axis = glm::vec2(static_cast<float>(std::sin(axis)), static_cast<float>(std::cos(axis)));
  p.bottom = static_cast<float>(cloud.bottom_m);
  p.extent = static_cast<float>(cloud.extent_m);
  p.cloud_base = static_cast<float>(cloud.cloud_base_m);
  p.cloud_top = static_cast<float>(cloud.cloud_top_m);
  p.extinction = static_cast<float>(model::density_to_extinction_per_m);
  return p;
}

}  // namespace nephele::render
