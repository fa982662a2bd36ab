#include "render/model_preview.hpp"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "gpu/shader_bindings.hpp"
#include "gpu/compute_program.hpp"
#include "gpu/textures.hpp"
#include "render/cloud_renderer.hpp"

namespace nephele::render {
namespace {

// The sphere the light is computed on (the preview has no viewpoint on the Earth): the mean
// Earth radius, the cloud at 2 km.
constexpr double kEarthRadius = 6371000.0;
constexpr double kCloudAltitude = 2000.0;

void set(const gpu::ComputeProgram& p, const std::string& name, glsl::vec3 v) { p.set(name, v); }

}  // namespace

glsl::ModelView preview_view(const model::CloudModel& m, const PreviewSettings& s) {
  using namespace glsl;
  ModelView v;
  const float e = static_cast<float>(m.extent_m);
  v.extent = e;
  v.extinction = static_cast<float>(model::density_to_extinction_per_m);
  // The orbit's axes in double, then the camera `distance` extents back from the target.
  const double h = s.heading_deg * M_PI / 180.0, p = s.pitch_deg * M_PI / 180.0;
  const double forward[3] = {std::sin(h) * std::cos(p), std::cos(h) * std::cos(p), std::sin(p)};
  const double right[3] = {std::cos(h), -std::sin(h), 0.0};
  // up = right x forward: level when the pitch is 0, always perpendicular to both.
  const double up[3] = {right[1] * forward[2] - right[2] * forward[1], right[2] * forward[0] - right[0] * forward[2],
                        right[0] * forward[1] - right[1] * forward[0]};
  for (int a = 0; a < 3; ++a) {
    v.origin[a] = float((double(s.target[a]) - s.distance * forward[a]) * e);
    v.forward[a] = float(forward[a]);
    v.right[a] = float(right[a]);
    v.up[a] = float(up[a]);
  }
  v.tan_half_fov = static_cast<float>(std::tan(0.5 * s.fov_deg * M_PI / 180.0));
  const double el = s.sun_elevation_deg * M_PI / 180.0, az = s.sun_azimuth_deg * M_PI / 180.0;
  v.sun = vec3(float(std::cos(el) * std::sin(az)), float(std::cos(el) * std::cos(az)), float(std::sin(el)));
  const float radius = static_cast<float>(kEarthRadius);
  const vec3 cloud(0.0f, 0.0f, radius + static_cast<float>(kCloudAltitude));
  v.sunlight = solar_irradiance() * transmittance_to_space(cloud, v.sun, radius);
  v.ambient = sky_irradiance(v.sun, kEarthRadius, kCloudAltitude);
  // Lambertian ground of albedo 0.15 (as the regional renderer's) lit by the sun and the sky.
  v.ground_radiance = (0.15f / PI_F) * (v.sunlight * std::max(v.sun.z, 0.0f) + v.ambient);
  // The clear sky 10 degrees above the horizon towards the view, from 2 km.
  const vec3 d(0.0f, float(std::cos(M_PI / 18)), float(std::sin(M_PI / 18)));
  const vec2 top = ray_sphere(cloud, d, vec3(0.0f), radius + ATMOSPHERE_THICKNESS);
  vec3 total, split, t_total, t_split;
  sky_single_scattering(cloud, d, std::max(top.y, 0.0f), 0.0f, v.sun, radius, 16, total, split, t_total, t_split);
  v.background = total;
  v.view_steps = s.view_steps;
  v.light_steps = s.light_steps;
  return v;
}

PreviewRenderer::PreviewRenderer() : program_(std::make_unique<gpu::ComputeProgram>("model/preview.comp")) {}
PreviewRenderer::~PreviewRenderer() = default;

core::ImageData PreviewRenderer::render(const model::DensityVolume& volume, const PreviewSettings& s) {
  const glsl::ModelView v = preview_view(volume.model(), s);
  const gpu::ComputeProgram& program = *program_;
  program.use();
  set(program, "u_view.origin", v.origin);
  set(program, "u_view.forward", v.forward);
  set(program, "u_view.right", v.right);
  set(program, "u_view.up", v.up);
  program.set("u_view.tan_half_fov", v.tan_half_fov);
  set(program, "u_view.sun", v.sun);
  set(program, "u_view.sunlight", v.sunlight);
  set(program, "u_view.ambient", v.ambient);
  set(program, "u_view.ground_radiance", v.ground_radiance);
  set(program, "u_view.background", v.background);
  program.set("u_view.extent", v.extent);
  program.set("u_view.extinction", v.extinction);
  program.set("u_view.view_steps", v.view_steps);
  program.set("u_view.light_steps", v.light_steps);
  const int first = std::clamp(s.first_row, 0, s.height);
  const int rows = s.row_count > 0 ? std::min(s.row_count, s.height - first) : s.height - first;
  program.set("u_first_row", first);
  gpu::Texture image = gpu::Texture::plane(s.width, s.height, GL_RGBA32F);
  if (rows < s.height) {
    const float zero[4] = {0, 0, 0, 0};
    glClearTexImage(image.id(), 0, GL_RGBA, GL_FLOAT, zero);
  }
  image.bind_image(shader_bindings::model_preview::radiance_image, GL_WRITE_ONLY);
  glBindTextureUnit(shader_bindings::model_preview::model_density, volume.texture());
  if (rows > 0) program.dispatch_covering(s.width, rows, 1);
  gpu::image_barrier();
  if (glGetError() != GL_NO_ERROR) throw std::runtime_error("OpenGL error in the model preview pass");
  return {s.width, s.height, 4, image.read()};
}

core::ImageData render_preview(const model::DensityVolume& volume, const PreviewSettings& s) {
  return PreviewRenderer().render(volume, s);
}

core::ImageData render_preview_cpu(const std::vector<float>& values, int size, const model::CloudModel& m,
                                   const PreviewSettings& s) {
  const glsl::ModelView v = preview_view(m, s);
  const glsl::DensitySource density{size, values.data()};
  core::ImageData out{s.width, s.height, 4, std::vector<float>(static_cast<size_t>(s.width) * s.height * 4)};
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x) {
      const glsl::vec4 c = glsl::model_pixel(glsl::ivec2(x, y), glsl::ivec2(s.width, s.height), v, density);
      for (int k = 0; k < 4; ++k) out.pixels[(static_cast<size_t>(y) * s.width + x) * 4 + k] = c[k];
    }
  return out;
}

}  // namespace nephele::render
