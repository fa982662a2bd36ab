#include "render/cloud_renderer.hpp"

#include <GeographicLib/Constants.hpp>
#include <GeographicLib/Ellipsoid.hpp>
#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "gpu/compute_program.hpp"
#include "gpu/pass_timer.hpp"
#include "gpu/textures.hpp"
#include "render/sun_position.hpp"
#include "shader_math/shader_math.hpp"

namespace nephele::render {
namespace {

constexpr int max_layers = 8;
// The wind's offset is wrapped at a length that every noise period divides, so the noise stays
// continuous in time while the offset stays small enough for float precision.
constexpr double offset_wrap_m = 120000.0;

// Replaces each channel's values by their ranks, (rank + 1/2) / n: uniformly distributed noise,
// so that a coverage threshold covers the intended fraction of the sky.
void equalise_histogram(GLuint volume, int size) {
  const size_t n = static_cast<size_t>(size) * size * size;
  std::vector<float> texels(2 * n);
  glGetTextureImage(volume, 0, GL_RG, GL_FLOAT, static_cast<GLsizei>(texels.size() * sizeof(float)), texels.data());
  std::vector<unsigned> order(n);
  for (int channel = 0; channel < 2; ++channel) {
    for (size_t k = 0; k < n; ++k) order[k] = static_cast<unsigned>(k);
    std::sort(order.begin(), order.end(), [&](unsigned a, unsigned b) {
      return texels[2 * a + channel] < texels[2 * b + channel];
    });
    for (size_t rank = 0; rank < n; ++rank)
      texels[2 * order[rank] + channel] = static_cast<float>((rank + 0.5) / n);
  }
  glTextureSubImage3D(volume, 0, 0, 0, 0, size, size, size, GL_RG, GL_FLOAT, texels.data());
}

GLuint make_texture(GLenum target) {
  GLuint id = 0;
  glCreateTextures(target, 1, &id);
  return id;
}

}  // namespace

double osculating_earth_radius(double latitude_deg) {
  const GeographicLib::Ellipsoid& e = GeographicLib::Ellipsoid::WGS84();
  return std::sqrt(e.MeridionalCurvatureRadius(latitude_deg) * e.TransverseCurvatureRadius(latitude_deg));
}

glm::dvec3 sun_direction_enu(double unix_seconds, double latitude_deg, double longitude_deg, double* elevation_deg) {
  const SunPosition sun = sun_position(unix_seconds, latitude_deg, longitude_deg);
  if (elevation_deg) *elevation_deg = sun.elevation_deg;
  const double el = sun.elevation_deg * M_PI / 180, az = sun.azimuth_deg * M_PI / 180;
  return {std::cos(el) * std::sin(az), std::cos(el) * std::cos(az), std::sin(el)};
}

glm::vec3 sky_irradiance(glm::vec3 sun, double earth_radius, double altitude_m) {
  using namespace glsl;
  const vec3 origin(0.0f, 0.0f, static_cast<float>(earth_radius + altitude_m));
  vec3 irradiance(0.0f);
  // Midpoint rule over the upper hemisphere: 6 zenith rings x 12 azimuths.
  const int rings = 6, azimuths = 12;
  for (int i = 0; i < rings; ++i) {
    const float theta = (i + 0.5f) * (0.5f * PI_F) / rings;
    const float d_omega = std::sin(theta) * (0.5f * PI_F / rings) * (2.0f * PI_F / azimuths);
    for (int k = 0; k < azimuths; ++k) {
      const float phi = (k + 0.5f) * 2.0f * PI_F / azimuths;
      const vec3 d(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
      const vec2 top = ray_sphere(origin, d, vec3(0.0f), static_cast<float>(earth_radius) + ATMOSPHERE_THICKNESS);
      vec3 total, split, t_total, t_split;
      sky_single_scattering(origin, d, std::max(top.y, 0.0f), 0.0f, sun, static_cast<float>(earth_radius), 8, total,
                            split, t_total, t_split);
      irradiance += total * std::cos(theta) * d_omega;
    }
  }
  return irradiance;
}

NoiseVolume::NoiseVolume(int size, std::uint32_t seed) : size_(size), seed_(seed) {
  gpu::ComputeProgram program("render/noise_volume.comp");
  texture_ = make_texture(GL_TEXTURE_3D);
  const int levels = 1 + static_cast<int>(std::log2(size));
  glTextureStorage3D(texture_, levels, GL_RG32F, size, size, size);
  glTextureParameteri(texture_, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(texture_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R}) glTextureParameteri(texture_, wrap, GL_REPEAT);
  program.set("u_seed", static_cast<unsigned>(seed));
  glBindImageTexture(0, texture_, 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RG32F);
  program.dispatch_covering(size, size, size);
  gpu::image_barrier();
  equalise_histogram(texture_, size);
  glGenerateTextureMipmap(texture_);
}

NoiseVolume::~NoiseVolume() {
  if (texture_ != 0) glDeleteTextures(1, &texture_);
}

RenderResult render_clouds(const Camera& camera, const std::vector<regional::CloudLayer>& layers,
                           const regional::WeatherField& field, double unix_seconds, const RenderSettings& settings,
                           glm::dvec2 wind_towards, double wind_speed, const NoiseVolume* noise) {
  RenderResult result;
  auto timed = [&](const std::string& name, auto&& work) { result.timings_ms.emplace_back(name, gpu::time_pass(work)); };

  // Only layers with cloud somewhere in the field are marched.
  std::vector<const regional::CloudLayer*> active;
  for (const auto& layer : layers) {
    if (field.max_of(int(layer.channel)) <= 0.0f) {
      result.passes.push_back(std::string("skip layer ") + regional::cloud_type_name(layer.type) + " (no cloud)");
      continue;
    }
    if (static_cast<int>(active.size()) < max_layers) active.push_back(&layer);
  }

  // Noise volume, only when a layer will read it.
  std::unique_ptr<NoiseVolume> own_noise;
  if (!active.empty()) {
    if (noise == nullptr) {
      timed("noise_volume", [&] { own_noise = std::make_unique<NoiseVolume>(settings.noise_size, settings.seed); });
      noise = own_noise.get();
      result.passes.push_back("noise_volume");
    } else if (noise->size() != settings.noise_size || noise->seed() != settings.seed) {
      throw std::logic_error("render_clouds: the shared noise volume was made for other settings");
    }
  }

  GLuint weather = make_texture(GL_TEXTURE_2D_ARRAY);
  glTextureStorage3D(weather, 1, GL_R32F, field.size, field.size, regional::coverage_channels);
  glTextureSubImage3D(weather, 0, 0, 0, 0, field.size, field.size, regional::coverage_channels, GL_RED, GL_FLOAT,
                      field.values.data());
  glTextureParameteri(weather, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(weather, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(weather, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(weather, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);

  const double earth_radius = osculating_earth_radius(camera.latitude_deg);
  const glm::dvec3 sun = sun_direction_enu(unix_seconds, camera.latitude_deg, camera.longitude_deg, &result.sun_elevation_deg);
  result.sun_direction = sun;
  const glm::vec3 ambient = sky_irradiance(glm::vec3(sun), earth_radius, 2000.0);

  gpu::Texture image = gpu::Texture::plane(camera.width, camera.height, GL_RGBA32F);
  timed("clouds", [&] {
    gpu::ComputeProgram program("render/clouds.comp");
    const glm::dvec2 wind = glm::length(wind_towards) > 0 ? glm::normalize(wind_towards) : glm::dvec2(0, 1);
    const double travelled = std::fmod(wind_speed * unix_seconds, offset_wrap_m);
    for (size_t i = 0; i < active.size(); ++i) {
      const auto& l = *active[i];
      const std::string name = "u_layers[" + std::to_string(i) + "].";
      program.set(name + "type", static_cast<int>(l.type));
      program.set(name + "channel", static_cast<int>(l.channel));
      program.set(name + "base", l.base_m);
      program.set(name + "top", l.top_m);
      program.set(name + "extinction", l.extinction);
      program.set(name + "morph", l.morph);
      program.set(name + "darkness", l.darkness);
      program.set(name + "min_distance", l.min_distance_m);
      glProgramUniform2f(program.id(), glGetUniformLocation(program.id(), (name + "wind").c_str()),
                         static_cast<float>(wind.x), static_cast<float>(wind.y));
      glProgramUniform2f(program.id(), glGetUniformLocation(program.id(), (name + "noise_offset").c_str()),
                         static_cast<float>(travelled), 0.0f);
      result.passes.push_back(std::string("march layer ") + regional::cloud_type_name(l.type));
    }
    program.set("u_layer_count", static_cast<int>(active.size()));
    program.set("u_earth_radius", static_cast<float>(earth_radius));
    program.set("u_camera_altitude", static_cast<float>(camera.height_m));
    const double heading = camera.heading_deg * M_PI / 180, pitch = camera.pitch_deg * M_PI / 180;
    const glm::dvec3 forward(std::sin(heading) * std::cos(pitch), std::cos(heading) * std::cos(pitch), std::sin(pitch));
    const glm::dvec3 right(std::cos(heading), -std::sin(heading), 0.0);
    const glm::dvec3 up = glm::cross(right, forward);
    program.set("u_forward", glm::vec3(forward));
    program.set("u_right", glm::vec3(right));
    program.set("u_up", glm::vec3(up));
    program.set("u_tan_half_fov", static_cast<float>(std::tan(camera.fov_deg * M_PI / 360)));
    program.set("u_panorama", camera.panorama ? 1 : 0);
    program.set("u_heading", static_cast<float>(heading));
    program.set("u_sun", glm::vec3(sun));
    program.set("u_ambient", ambient);
    {
      // Lambertian ground of albedo 0.15 under the camera, lit by the sun and the sky.
      using namespace glsl;
      const vec3 ground(0.0f, 0.0f, static_cast<float>(earth_radius + camera.height_m));
      const vec3 sunlight = solar_irradiance() * transmittance_to_space(ground, vec3(sun), static_cast<float>(earth_radius)) *
                            std::max(static_cast<float>(sun.z), 0.0f);
      program.set("u_ground_radiance", (0.15f / PI_F) * (sunlight + ambient));
    }
    program.set("u_view_steps", settings.view_steps);
    program.set("u_light_steps", settings.light_steps);
    program.set("u_sky_steps", settings.sky_steps);
    program.set("u_weather_extent", static_cast<float>(field.extent_m));
    program.set("u_max_distance", static_cast<float>(settings.max_distance_m));
    const double pixel_angle = camera.panorama ? 2 * M_PI / camera.width
                                               : 2 * std::tan(camera.fov_deg * M_PI / 360) / camera.width;
    program.set("u_pixel_angle", static_cast<float>(pixel_angle));
    program.set("u_noise_texels", static_cast<float>(settings.noise_size));
    image.bind_image(0, GL_WRITE_ONLY);
    glBindTextureUnit(1, noise != nullptr ? noise->texture() : 0);
    glBindTextureUnit(2, weather);
    GLuint guard = 0;
    const GLuint zero = 0;
    glCreateBuffers(1, &guard);
    glNamedBufferStorage(guard, sizeof zero, &zero, GL_MAP_READ_BIT);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, guard);
    program.dispatch_covering(camera.width, camera.height, 1);
    gpu::image_barrier();
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(guard, 0, sizeof result.loop_limited_pixels, &result.loop_limited_pixels);
    glDeleteBuffers(1, &guard);
  });
  result.passes.push_back("sky");
  result.radiance = {camera.width, camera.height, 4, image.read()};
  glDeleteTextures(1, &weather);
  return result;
}

core::ImageData tone_map(const core::ImageData& radiance, double exposure) {
  core::ImageData out{radiance.width, radiance.height, 3, {}};
  out.pixels.reserve(static_cast<size_t>(radiance.width) * radiance.height * 3);
  for (size_t k = 0; k < radiance.pixels.size(); k += radiance.channels) {
    for (int c = 0; c < 3; ++c) {
      const double x = std::max(0.0, radiance.pixels[k + c] * exposure);
      const double mapped = std::clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
      // sRGB transfer function (IEC 61966-2-1).
      const double encoded = mapped <= 0.0031308 ? 12.92 * mapped : 1.055 * std::pow(mapped, 1 / 2.4) - 0.055;
      out.pixels.push_back(static_cast<float>(encoded));
    }
  }
  return out;
}

}  // namespace nephele::render
