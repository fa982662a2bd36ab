#include "model/density_volume.hpp"

#include <epoxy/gl.h>

#include <algorithm>
#include <set>
#include <stdexcept>

#include "gpu/pass_timer.hpp"
#include "gpu/shader_bindings.hpp"

namespace nephele::model {
namespace {

static_assert(sizeof(glsl::ModelPrimitive) == 80, "ModelPrimitive must match its std430 layout: 5 vec4");

// Work groups per dispatch row (GL guarantees 65535 per dimension).
constexpr int kGroupsPerRow = 65535;

}  // namespace

double DensityVolume::device_bytes(int size) { return 4.0 * size * double(size) * size; }

DensityVolume::DensityVolume(int size) {
  grid_.size = size;
  GLint max_3d = 0;
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &max_3d);
  if (size < 1 || size > max_3d)
    throw ModelError("--size", std::to_string(size),
                     "1 to " + std::to_string(max_3d) + " (this driver's 3D texture limit)");
  glCreateTextures(GL_TEXTURE_3D, 1, &texture_);
  glTextureStorage3D(texture_, 1, GL_R32F, size, size, size);
  if (glGetError() != GL_NO_ERROR) {
    glDeleteTextures(1, &texture_);
    throw std::runtime_error("could not allocate a " + std::to_string(size) + "^3 density volume");
  }
  glTextureParameteri(texture_, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(texture_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
    glTextureParameteri(texture_, wrap, GL_CLAMP_TO_EDGE);
  program_ = std::make_unique<gpu::ComputeProgram>("model/density.comp");
  stats_.bricks = grid_.count();
}

DensityVolume::~DensityVolume() {
  if (texture_) glDeleteTextures(1, &texture_);
}

void DensityVolume::compute(const CloudModel& model, bool cull) {
  validate(model, "");
  model_ = model;
  cull_ = cull;
  if (cull) {
    lists_ = brick_lists(grid_, model_);
  } else {
    std::vector<std::uint32_t> all(model_.primitives.size());
    for (size_t i = 0; i < all.size(); ++i) all[i] = std::uint32_t(i);
    lists_.assign(static_cast<size_t>(grid_.count()), all);
  }
  std::vector<glsl::ModelPrimitive> packed;
  for (const Primitive& p : model_.primitives) packed.push_back(pack(p));
  gpu::upload(primitives_, packed.data(), packed.size() * sizeof(glsl::ModelPrimitive));
  std::vector<int> bricks;
  for (int b = 0; b < grid_.count(); ++b)
    if (!lists_[static_cast<size_t>(b)].empty()) bricks.push_back(b);
  gpu::PassTimer timer;
  const float zero = 0.0f;
  glClearTexImage(texture_, 0, GL_RED, GL_FLOAT, &zero);
  run(bricks);
  stats_.ms = timer.milliseconds();
}

void DensityVolume::edit(int index, const Primitive& primitive) {
  if (index < 0 || index >= int(model_.primitives.size()))
    throw ModelError("primitive", std::to_string(index), "0 to " + std::to_string(int(model_.primitives.size()) - 1));
  CloudModel next = model_;
  next.primitives[size_t(index)] = primitive;
  validate(next, "");
  std::set<int> touched;
  if (cull_) {
    for (int b : footprint(grid_, model_.primitives[size_t(index)])) touched.insert(b);
    for (int b : footprint(grid_, primitive)) touched.insert(b);
    // Rebuild the touched bricks' lists in the model's order: drop the index, insert it where
    // the new footprint reaches.
    const std::vector<int> now = footprint(grid_, primitive);
    const std::set<int> reached(now.begin(), now.end());
    const auto i = std::uint32_t(index);
    for (int b : touched) {
      auto& list = lists_[size_t(b)];
      list.erase(std::remove(list.begin(), list.end(), i), list.end());
      if (reached.count(b)) list.insert(std::lower_bound(list.begin(), list.end(), i), i);
    }
  } else {
    for (int b = 0; b < grid_.count(); ++b) touched.insert(b);
  }
  model_ = std::move(next);
  const glsl::ModelPrimitive packed = pack(primitive);
  primitives_.write(&packed, sizeof packed, static_cast<size_t>(index) * sizeof packed);
  gpu::PassTimer timer;
  run(std::vector<int>(touched.begin(), touched.end()));
  stats_.ms = timer.milliseconds();
}

void DensityVolume::run(const std::vector<int>& bricks) {
  std::vector<glsl::uvec4> jobs;
  std::vector<std::uint32_t> indices;
  jobs.reserve(bricks.size());
  stats_.pairs = 0;
  for (int b : bricks) {
    const auto& list = lists_[size_t(b)];
    jobs.emplace_back(std::uint32_t(b), std::uint32_t(indices.size()), std::uint32_t(list.size()), 0u);
    indices.insert(indices.end(), list.begin(), list.end());
    stats_.pairs += long(list.size());
  }
  stats_.bricks_computed = int(bricks.size());
  if (jobs.empty()) return;
  gpu::upload(jobs_, jobs.data(), jobs.size() * sizeof(glsl::uvec4));
  gpu::upload(indices_, indices.data(), indices.size() * sizeof(std::uint32_t));
  program_->use();
  program_->set("u_size", grid_.size);
  program_->set("u_jobs", int(jobs.size()));
  program_->set("u_blend", blend_code(model_.blend));
  program_->set("u_scale", model_.scale);
  program_->set("u_max_frequency", max_noise_frequency(model_, grid_.size));
  const glsl::vec2 cut = levels(model_);
  glProgramUniform2f(program_->id(), glGetUniformLocation(program_->id(), "u_levels"), cut.x, cut.y);
  const glsl::ModelNoise noise = pack(model_.noise);
  if (program_->has_uniform("u_noise_shape")) {
    glProgramUniform4fv(program_->id(), glGetUniformLocation(program_->id(), "u_noise_shape"), 1, &noise.shape.x);
    glProgramUniform4fv(program_->id(), glGetUniformLocation(program_->id(), "u_noise_extra"), 1, &noise.extra.x);
  }
  namespace density = shader_bindings::model_density;
  glBindImageTexture(density::u_density, texture_, 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R32F);
  primitives_.bind(density::primitives);
  jobs_.bind(density::jobs);
  indices_.bind(density::indices);
  const int count = int(jobs.size());
  const int x = std::min(count, kGroupsPerRow);
  glDispatchCompute(GLuint(x), GLuint((count + x - 1) / x), 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  if (glGetError() != GL_NO_ERROR) throw std::runtime_error("OpenGL error in the density volume pass");
}

std::vector<float> DensityVolume::read() const {
  const size_t count = size_t(grid_.size) * size_t(grid_.size) * size_t(grid_.size);
  std::vector<float> values(count);
  glGetTextureImage(texture_, 0, GL_RED, GL_FLOAT, GLsizei(count * sizeof(float)), values.data());
  return values;
}

std::vector<float> density_cpu(const CloudModel& model, int size) {
  validate(model, "");
  std::vector<float> values(size_t(size) * size_t(size) * size_t(size));
  for (int z = 0; z < size; ++z)
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x)
        values[(size_t(z) * size + y) * size + x] =
            density_at(model, (glsl::vec3(glsl::ivec3(x, y, z)) + 0.5f) / float(size), size);
  return values;
}

}  // namespace nephele::model
