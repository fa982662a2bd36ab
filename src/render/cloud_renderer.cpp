#include "render/cloud_renderer.hpp"

#include "render/upsample.hpp"

#include <GeographicLib/Constants.hpp>
#include <GeographicLib/Ellipsoid.hpp>
#include <epoxy/gl.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include "core/hash.hpp"
#include "core/time.hpp"
#include "gpu/shader_bindings.hpp"
#include "gpu/compute_program.hpp"
#include "gpu/pass_timer.hpp"
#include "gpu/shader_sources.hpp"
#include "gpu/storage_buffer.hpp"
#include "gpu/textures.hpp"
#include "render/convective_volumes.hpp"
#include "render/sun_position.hpp"
#include "shader_math/shader_math.hpp"
#include "shader_math/uniforms.hpp"

namespace nephele::render {
namespace {

// The wind's offset is wrapped at a length that every noise period divides, so the noise stays
// continuous in time while the offset stays small enough for float precision.
// 2160 km: also a whole number of periods of every baked Webanck field (f tau m / 4 with tau
// = offset / 108 km, f m a multiple of 1/5 of an integer: 5 x 4 x 108 km).
constexpr double offset_wrap_m = 2160000.0;

// Replaces the shape and detail channels' values by their ranks, (rank + 1/2) / n: uniformly
// distributed noise, so that a coverage threshold covers the intended fraction of the sky; and
// standardises the G3 channel (B) to mean 0 and variance 1, which the trilinear bake of three
// octaves lowers a little from the 8-octave mean's, so that normal_cdf maps it as webanck_g3
// maps the exact field (docs/layers.md).
void equalise_histogram(GLuint volume, int size) {
  const size_t n = static_cast<size_t>(size) * size * size;
  std::vector<float> texels(4 * n);
  glGetTextureImage(volume, 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(texels.size() * sizeof(float)), texels.data());
  std::vector<unsigned> order(n);
  for (int channel = 0; channel < 2; ++channel) {
    for (size_t k = 0; k < n; ++k) order[k] = static_cast<unsigned>(k);
    std::sort(order.begin(), order.end(),
              [&](unsigned a, unsigned b) { return texels[4 * a + channel] < texels[4 * b + channel]; });
    for (size_t rank = 0; rank < n; ++rank) texels[4 * order[rank] + channel] = static_cast<float>((rank + 0.5) / n);
  }
  double sum = 0, sum_squares = 0;
  for (size_t k = 0; k < n; ++k) sum += texels[4 * k + 2];
  const double mean = sum / n;
  for (size_t k = 0; k < n; ++k) sum_squares += (texels[4 * k + 2] - mean) * (texels[4 * k + 2] - mean);
  const double deviation = std::sqrt(sum_squares / n);
  for (size_t k = 0; k < n; ++k) texels[4 * k + 2] = static_cast<float>((texels[4 * k + 2] - mean) / deviation);
  glTextureSubImage3D(volume, 0, 0, 0, 0, size, size, size, GL_RGBA, GL_FLOAT, texels.data());
}

GLuint make_texture(GLenum target) {
  GLuint id = 0;
  glCreateTextures(target, 1, &id);
  return id;
}

// GL_LINEAR within and between texels, clamped to the edge in s and t: how the marcher's 2D
// textures are read (their C++ twins filter the same way, hooks.hpp).
// Two planes of floats interleaved as the red and green channels of one texture.
std::vector<float> red_green(const std::vector<float>& red, const std::vector<float>& green) {
  std::vector<float> texels(2 * red.size());
  for (size_t k = 0; k < red.size(); ++k) {
    texels[2 * k] = red[k];
    texels[2 * k + 1] = green[k];
  }
  return texels;
}

void filter_linear_clamped(GLuint texture) {
  glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(texture, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(texture, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
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

glm::vec3 ground_sky_irradiance(glm::vec3 sun, double earth_radius, double altitude_m) {
  using namespace glsl;
  const glm::vec3 sky = sky_irradiance(sun, earth_radius, altitude_m);
  const vec3 ground(0.0f, 0.0f, static_cast<float>(earth_radius + altitude_m));
  const float direct = solar_irradiance().y * transmittance_to_space(ground, sun, static_cast<float>(earth_radius)).y *
                       std::max(sun.z, 0.0f);
  const float measured = clear_sky_diffuse_fraction / (1.0f - clear_sky_diffuse_fraction) * direct;
  return sky.y > 0.0f && sky.y < measured ? sky * (measured / sky.y) : sky;
}

namespace {

GLuint make_volume_texture(int size) {
  const GLuint texture = make_texture(GL_TEXTURE_3D);
  const int levels = 1 + static_cast<int>(std::log2(size));
  glTextureStorage3D(texture, levels, GL_RGBA32F, size, size, size);
  glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
    glTextureParameteri(texture, wrap, GL_REPEAT);
  return texture;
}

// Raise when equalise_histogram or the mip chain changes what a volume holds.
constexpr int noise_volume_host_version = 2;

}  // namespace

std::string NoiseVolume::recipe_key() {
  // FNV-1a, 64 bits, of the shader as compiled (includes expanded).
  const std::uint64_t hash = core::fnv1a(gpu::expand_shader("render/noise_volume.comp").text);
  return "noise_volume.comp:" + core::hex_digits(hash) + ",host:" + std::to_string(noise_volume_host_version);
}

NoiseVolume::NoiseVolume(int size, std::uint32_t seed, const std::vector<float>& level0) : size_(size), seed_(seed) {
  if (level0.size() != 4 * static_cast<size_t>(size) * size * size)
    throw std::invalid_argument("NoiseVolume: level 0 has the wrong number of values");
  texture_ = make_volume_texture(size);
  glTextureSubImage3D(texture_, 0, 0, 0, 0, size, size, size, GL_RGBA, GL_FLOAT, level0.data());
  glGenerateTextureMipmap(texture_);
}

std::vector<float> NoiseVolume::level0() const {
  std::vector<float> texels(4 * static_cast<size_t>(size_) * size_ * size_);
  glGetTextureImage(texture_, 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(texels.size() * sizeof(float)), texels.data());
  return texels;
}

NoiseVolume::NoiseVolume(int size, std::uint32_t seed) : size_(size), seed_(seed) {
  gpu::ComputeProgram program("render/noise_volume.comp");
  texture_ = make_volume_texture(size);
  program.set("u_seed", static_cast<unsigned>(seed));
  glBindImageTexture(shader_bindings::render_noise_volume::noise_volume, texture_, 0, GL_TRUE, 0, GL_WRITE_ONLY,
                     GL_RGBA32F);
  program.dispatch_covering(size, size, size);
  gpu::image_barrier();
  equalise_histogram(texture_, size);
  glGenerateTextureMipmap(texture_);
}

NoiseVolume::~NoiseVolume() {
  if (texture_ != 0) glDeleteTextures(1, &texture_);
}

namespace {

// Layers with cloud somewhere in the field, at most MAX_LAYERS of them: those the marcher sees.
std::vector<const regional::CloudLayer*> marched_layers(const std::vector<regional::CloudLayer>& layers,
                                                        const regional::WeatherField& field) {
  std::vector<const regional::CloudLayer*> active;
  for (const auto& layer : layers)
    if (field.max_of(int(layer.channel)) > 0.0f && static_cast<int>(active.size()) < glsl::MAX_LAYERS)
      active.push_back(&layer);
  return active;
}

}  // namespace

glsl::VolumeSource NoiseVolume::host_copy() const {
  glsl::VolumeSource source;
  source.size = size_;
  for (int level = 0, n = size_; n >= 1; ++level, n /= 2) {
    std::vector<glm::vec4> texels(static_cast<size_t>(n) * n * n);
    glGetTextureImage(texture_, level, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(texels.size() * sizeof(glm::vec4)),
                      texels.data());
    source.levels.push_back(std::move(texels));
  }
  return source;
}

bool needs_noise_volume(const std::vector<regional::CloudLayer>& layers, const regional::WeatherField& field) {
  return !marched_layers(layers, field).empty();
}

CameraFrame camera_frame(const Camera& camera) {
  const double heading = camera.heading_deg * M_PI / 180, pitch = camera.pitch_deg * M_PI / 180;
  CameraFrame f;
  f.forward = {std::sin(heading) * std::cos(pitch), std::cos(heading) * std::cos(pitch), std::sin(pitch)};
  f.right = {std::cos(heading), -std::sin(heading), 0.0};
  f.up = glm::cross(f.right, f.forward);
  f.tan_half_fov = std::tan(camera.fov_deg * M_PI / 360);
  return f;
}

glsl::MarchParams march_params(const Camera& camera, const std::vector<regional::CloudLayer>& layers,
                               const regional::WeatherField& field, double unix_seconds, const RenderSettings& settings,
                               glm::dvec2 wind_towards, double wind_speed, const ConvectiveVolumes* convective) {
  glsl::MarchParams m{};
  const auto active = marched_layers(layers, field);
  const glm::dvec2 wind = glm::length(wind_towards) > 0 ? glm::normalize(wind_towards) : glm::dvec2(0, 1);
  const double travelled = std::fmod(wind_speed * unix_seconds, offset_wrap_m);
  for (size_t i = 0; i < active.size(); ++i) {
    const auto& l = *active[i];
    m.layers[i] = {static_cast<int>(l.type),
                   static_cast<int>(l.channel),
                   l.base_m,
                   l.top_m,
                   l.extinction,
                   l.morph,
                   l.darkness,
                   l.min_distance_m,
                   glm::vec2(wind),
                   glm::vec2(static_cast<float>(travelled), 0.0f),
                   -1};
  }
  m.layer_count = static_cast<int>(active.size());
  // A layer with layers wholly above it (their base at or above its top) gets a shadow map of
  // the depth through them (cloud_march.glsl's higher_layers_depth).
  int maps = 0;
  for (int i = 0; i < glsl::MAX_LAYERS; ++i) {
    bool below_another = false;
    if (i < m.layer_count && settings.shadow_map_size > 0)
      for (const auto* other : active)
        below_another = below_another || (other != active[i] && other->base_m >= active[i]->top_m);
    m.layers[i].shadow_map = below_another ? maps++ : -1;
  }
  m.shadow_extent = static_cast<float>(settings.max_distance_m);

  const double earth_radius = osculating_earth_radius(camera.latitude_deg);
  const glm::dvec3 sun = sun_direction_enu(unix_seconds, camera.latitude_deg, camera.longitude_deg);
  const glm::vec3 ambient = sky_irradiance(glm::vec3(sun), earth_radius, 2000.0);
  m.earth_radius = static_cast<float>(earth_radius);
  m.camera_altitude = static_cast<float>(camera.height_m);
  const CameraFrame frame = camera_frame(camera);
  m.forward = glm::vec3(frame.forward);
  m.right = glm::vec3(frame.right);
  m.up = glm::vec3(frame.up);
  m.tan_half_fov = static_cast<float>(frame.tan_half_fov);
  m.panorama = camera.panorama ? 1 : 0;
  m.heading = static_cast<float>(camera.heading_deg * M_PI / 180);
  m.sun = glm::vec3(sun);
  m.ambient = ambient;
  // The ground in view of a camera near it lies about at its altitude; a camera higher up sees
  // ground far below it, taken at 2 km as the clouds' light is.
  m.ground_ambient = ground_sky_irradiance(glm::vec3(sun), earth_radius, std::clamp(camera.height_m, 0.0, 2000.0));
  {
    // Lambertian ground of albedo 0.15 under the camera, lit by the sun and the sky.
    using namespace glsl;
    const vec3 ground(0.0f, 0.0f, static_cast<float>(earth_radius + camera.height_m));
    const vec3 sunlight = solar_irradiance() *
                          transmittance_to_space(ground, vec3(sun), static_cast<float>(earth_radius)) *
                          std::max(static_cast<float>(sun.z), 0.0f);
    m.ground_radiance = (0.15f / PI_F) * (sunlight + m.ground_ambient);
  }
  m.view_steps = settings.view_steps;
  m.light_steps = settings.light_steps;
  m.sky_steps = settings.sky_steps;
  m.powder = settings.powder;
  m.weather_extent = static_cast<float>(field.extent_m);
  m.max_distance = static_cast<float>(settings.max_distance_m);
  const double pixel_angle =
      camera.panorama ? 2 * M_PI / camera.width : 2 * std::tan(camera.fov_deg * M_PI / 360) / camera.width;
  m.pixel_angle = static_cast<float>(pixel_angle);
  m.noise_texels = static_cast<float>(settings.noise_size);
  m.terrain = settings.terrain ? regional::terrain_params(*settings.terrain) : regional::no_terrain_params();
  const int day = core::day_of_year(unix_seconds);
  m.terrain.snow_line = static_cast<float>(regional::seasonal_snow_line_m(day));
  m.terrain.crop_stage = static_cast<float>(regional::seasonal_crop_stage(day));
  m.convective_count = convective != nullptr ? convective->count() : 0;
  m.detail_erosion = detail_erosion_strength;
  for (int c = 0; c < m.convective_count; ++c) m.convective[c] = convective->params(c);
  // The sky's map (crepuscular rays): the depth through all clouds from the lowest base.
  m.sky_shadow_map = -1;
  m.sky_shadow_base = 0.0f;
  if (settings.shadow_map_size > 0 && m.layer_count + m.convective_count > 0) {
    float lowest = std::numeric_limits<float>::max();
    for (int i = 0; i < m.layer_count; ++i) lowest = std::min(lowest, m.layers[i].base);
    for (int c = 0; c < m.convective_count; ++c) lowest = std::min(lowest, m.convective[c].cloud_base);
    m.sky_shadow_map = 0;  // layer 0 of its own texture
    m.sky_shadow_base = lowest;
  }
  return m;
}

// What a render's shadow maps depend on: the layers, the camera's place, the sun, the maps'
// extent and size, the noise volume and the weather field (not the view's direction, the steps
// or the frame).
std::uint64_t shadow_map_key(const glsl::MarchParams& p, int size, const NoiseVolume* noise,
                             const regional::WeatherField& field) {
  std::uint64_t h = core::fnv1a(p.layers, sizeof(glsl::LayerParams) * static_cast<std::size_t>(p.layer_count));
  const float numbers[] = {p.earth_radius,   p.camera_altitude, p.sun.x,           p.sun.y,
                           p.sun.z,          p.shadow_extent,   p.noise_texels,    p.max_distance,
                           p.weather_extent, float(size),       p.sky_shadow_base, float(p.sky_shadow_map)};
  h = core::fnv1a(numbers, sizeof numbers, h);
  h = core::fnv1a(p.convective, sizeof(glsl::ConvectiveParams) * static_cast<std::size_t>(p.convective_count), h);
  const std::uint64_t volume[] = {noise != nullptr ? noise->texture() : 0u, noise != nullptr ? noise->seed() : 0u};
  h = core::fnv1a(volume, sizeof volume, h);
  return core::fnv1a(field.values.data(), field.values.size() * sizeof(float), h);
}

int sky_shadow_map_size(int shadow_map_size) { return shadow_map_size > 0 ? std::max(1, shadow_map_size / 4) : 0; }

int shadow_map_count(const glsl::MarchParams& params) {
  int maps = 0;
  for (int layer = 0; layer < params.layer_count; ++layer) maps += params.layers[layer].shadow_map >= 0 ? 1 : 0;
  return maps;
}

std::vector<params::FieldBinding> field_bindings(Camera& c) {
  namespace sc = params::scene;
  return {{&sc::latitude, &c.latitude_deg}, {&sc::longitude, &c.longitude_deg}, {&sc::height, &c.height_m},
          {&sc::heading, &c.heading_deg},   {&sc::pitch, &c.pitch_deg},         {&sc::fov, &c.fov_deg}};
}

std::vector<params::FieldBinding> field_bindings(RenderSettings& s) {
  namespace sc = params::scene;
  return {{&sc::view_steps, &s.view_steps},
          {&sc::light_steps, &s.light_steps},
          {&sc::sky_steps, &s.sky_steps},
          {&sc::powder, &s.powder},
          {&sc::frames, &s.frames},
          {&sc::resolution_divisor, &s.resolution_divisor},
          {&sc::shadow_map_size, &s.shadow_map_size},
          {&sc::seed, &s.seed}};
}

RenderResult render_clouds(const Camera& camera, const std::vector<regional::CloudLayer>& layers,
                           const regional::WeatherField& field, double unix_seconds, const RenderSettings& settings,
                           glm::dvec2 wind_towards, double wind_speed, const NoiseVolume* noise,
                           const ConvectiveVolumes* convective) {
  RenderResult result;
  auto timed = [&](const std::string& name, auto&& work) {
    result.timings_ms.emplace_back(name, gpu::time_pass(work));
  };

  for (const auto& layer : layers)
    if (field.max_of(int(layer.channel)) <= 0.0f)
      result.passes.push_back(std::string("skip layer ") + regional::cloud_type_name(layer.type) + " (no cloud)");
  const auto active = marched_layers(layers, field);

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
  filter_linear_clamped(weather);

  GLuint terrain = 0, land_cover = 0;
  if (settings.terrain) {
    const regional::TerrainGrid& t = *settings.terrain;
    terrain = make_texture(GL_TEXTURE_2D);
    // Heights in red, ceilings in green (terrain.glsl's TerrainTexture).
    const std::vector<float> texels = red_green(t.altitudes, t.ceilings);
    glTextureStorage2D(terrain, 1, GL_RG32F, t.size, t.size);
    glTextureSubImage2D(terrain, 0, 0, 0, t.size, t.size, GL_RG, GL_FLOAT, texels.data());
    filter_linear_clamped(terrain);
    result.passes.push_back("terrain (" + t.source + ")");
    if (t.land && !t.land->empty()) {
      // Water distance in red, built-up fraction in green (land_cover.glsl), a layer per level;
      // half floats keep the distances within 1 m out to the far level's band (2.3 km).
      const regional::LandCoverGrid& land = *t.land;
      land_cover = make_texture(GL_TEXTURE_2D_ARRAY);
      const std::vector<float> rg = red_green(land.water, land.urban);
      glTextureStorage3D(land_cover, 1, GL_RG16F, land.size, land.size, regional::land_cover_levels);
      glTextureSubImage3D(land_cover, 0, 0, 0, 0, land.size, land.size, regional::land_cover_levels, GL_RG, GL_FLOAT,
                          rg.data());
      filter_linear_clamped(land_cover);
      result.passes.push_back("land cover (" + land.source + ")");
    }
  }

  result.sun_direction =
      sun_direction_enu(unix_seconds, camera.latitude_deg, camera.longitude_deg, &result.sun_elevation_deg);

  const int rows = settings.row_count > 0 ? settings.row_count : camera.height;
  if (settings.first_row < 0 || rows > camera.height - settings.first_row)
    throw std::logic_error("render_clouds: rows " + std::to_string(settings.first_row) + " + " + std::to_string(rows) +
                           " outside an image of " + std::to_string(camera.height));
  const int stride = settings.march_stride;
  const glm::ivec2 phase = settings.march_phase;
  if (stride < 1 || phase.x < 0 || phase.y < 0 || phase.x >= stride || phase.y >= stride ||
      (stride > 1 && (rows != camera.height || settings.frames > 1)))
    throw std::logic_error("render_clouds: march stride " + std::to_string(stride) +
                           " needs a phase below it, the whole image and one frame");
  const glsl::MarchParams params =
      march_params(camera, layers, field, unix_seconds, settings, wind_towards, wind_speed, convective);
  // The layers' shadow maps, only where a layer has layers above it, and the sky's wherever
  // there is cloud (crepuscular rays), a quarter of their size.
  const int maps = shadow_map_count(params);
  const bool sky_map = params.sky_shadow_map >= 0;
  // A caller's cache (the viewer's bands of one frame) keeps them while nothing they depend on
  // changes; without one they are made for this render alone.
  const std::shared_ptr<ShadowMapCache> cache =
      settings.shadow_cache ? settings.shadow_cache : std::make_shared<ShadowMapCache>();
  gpu::Texture& shadow_maps = cache->maps;
  gpu::Texture& sky_shadow = cache->sky;
  const std::uint64_t key = maps > 0 || sky_map ? shadow_map_key(params, settings.shadow_map_size, noise, field) : 0;
  // One program fills both kinds of map (made at the first that is not cached).
  std::unique_ptr<gpu::ComputeProgram> shadow_program;
  const auto fill_maps = [&](gpu::Texture& target, int size, int first_layer, int last_layer) {
    if (!shadow_program) {
      shadow_program = std::make_unique<gpu::ComputeProgram>("render/layer_shadows.comp");
      glsl::set_uniform(*shadow_program, "u_march", params);
    }
    gpu::ComputeProgram& program = *shadow_program;
    namespace sources = shader_bindings::render_march_sources;
    target.bind_image(shader_bindings::render_layer_shadows::shadow_maps, GL_WRITE_ONLY);
    glBindTextureUnit(sources::noise_volume, noise != nullptr ? noise->texture() : 0);
    glBindTextureUnit(sources::weather_field, weather);
    glBindTextureUnit(sources::terrain_heights, terrain);
    glBindTextureUnit(sources::land_cover, land_cover);
    glBindTextureUnit(sources::convective_volumes, convective != nullptr ? convective->texture() : 0);
    for (int layer = first_layer; layer <= last_layer; ++layer)
      if (layer < 0 || params.layers[layer].shadow_map >= 0) {
        program.set("u_layer", layer);
        program.dispatch_covering(size, size, 1);
      }
    gpu::image_barrier();
    filter_linear_clamped(target.id());
  };
  const bool cached = cache->key == key && (maps == 0 || shadow_maps.id() != 0) && (!sky_map || sky_shadow.id() != 0);
  if ((maps > 0 || sky_map) && cached) {
    if (maps > 0) result.passes.push_back("layer_shadows (reused)");
    if (sky_map) result.passes.push_back("sky_shadow (reused)");
  } else {
    if (maps > 0) {
      const int size = settings.shadow_map_size;
      timed("layer_shadows", [&] {
        shadow_maps = gpu::Texture::layered(size, size, maps, GL_R32F);
        fill_maps(shadow_maps, size, 0, params.layer_count - 1);
      });
      result.passes.push_back("layer_shadows (" + std::to_string(maps) + " of " + std::to_string(size) + "^2)");
    }
    if (sky_map) {
      const int size = sky_shadow_map_size(settings.shadow_map_size);
      timed("sky_shadow", [&] {
        sky_shadow = gpu::Texture::layered(size, size, 1, GL_R32F);
        fill_maps(sky_shadow, size, -1, -1);
      });
      result.passes.push_back("sky_shadow (" + std::to_string(size) + "^2)");
    }
    cache->key = key;
  }
  if (maps > 0 && settings.read_shadow_maps) result.shadow_maps = shadow_maps.read();
  if (sky_map && settings.read_shadow_maps) result.sky_shadow_map = sky_shadow.read();
  gpu::Texture image = gpu::Texture::plane(camera.width, camera.height, GL_RGBA32F);
  gpu::Texture ground_distance = gpu::Texture::plane(camera.width, camera.height, GL_R32F);
  // Frames of an accumulation, each with its own jitter of the march start, averaged.
  std::vector<double> sum;
  timed("clouds", [&] {
    gpu::ComputeProgram program("render/clouds.comp");
    glsl::set_uniform(program, "u_march", params);
    for (const auto* l : active)
      result.passes.push_back(std::string("march layer ") + regional::cloud_type_name(l->type));
    for (int c = 0; c < params.convective_count; ++c)
      result.passes.push_back(std::string("march convective ") +
                              regional::convective_kind_name(convective->clouds()[c].kind));
    namespace sources = shader_bindings::render_march_sources;
    image.bind_image(shader_bindings::render_clouds::radiance_image, GL_WRITE_ONLY);
    ground_distance.bind_image(shader_bindings::render_clouds::ground_distance_image, GL_WRITE_ONLY);
    glBindTextureUnit(sources::noise_volume, noise != nullptr ? noise->texture() : 0);
    glBindTextureUnit(sources::weather_field, weather);
    glBindTextureUnit(sources::terrain_heights, terrain);
    glBindTextureUnit(sources::land_cover, land_cover);
    glBindTextureUnit(sources::convective_volumes, convective != nullptr ? convective->texture() : 0);
    glBindTextureUnit(sources::layer_shadows, maps > 0 ? shadow_maps.id() : 0);
    glBindTextureUnit(sources::sky_shadow, sky_map ? sky_shadow.id() : 0);
    // The count, then a bit per pixel of the whole image.
    const std::vector<GLuint> zeros(1 + (static_cast<std::size_t>(camera.width) * camera.height + 31) / 32, 0u);
    const gpu::StorageBuffer guard(zeros.size() * sizeof(GLuint), zeros.data());
    guard.bind(shader_bindings::render_clouds::loop_guard);
    program.set("u_first_row", settings.first_row);
    program.set("u_stride", stride);
    program.set("u_phase", phase);
    const int frames = std::max(settings.frames, 1);
    for (int frame = 0; frame < frames; ++frame) {
      program.set("u_march.frame", frame);
      program.dispatch_covering((camera.width - phase.x + stride - 1) / stride, (rows - phase.y + stride - 1) / stride,
                                1);
      gpu::image_barrier();
      if (frames > 1) {
        const std::vector<float> pixels = image.read();
        sum.resize(pixels.size(), 0.0);
        for (size_t k = 0; k < pixels.size(); ++k) sum[k] += pixels[k];
      }
    }
    std::vector<GLuint> guard_words(zeros.size());
    guard.read(guard_words.data(), guard_words.size() * sizeof(GLuint));
    result.loop_limited_pixels = guard_words[0];
    result.loop_limited_bits.assign(guard_words.begin() + 1, guard_words.end());
  });
  result.passes.push_back("sky");
  if (settings.upsample_size.x > 0 && settings.upsample_size.y > 0) {
    result.ground_distance = {camera.width, camera.height, 1, ground_distance.read()};
    const glm::ivec2 full = settings.upsample_size;
    std::size_t guided = 0;
    timed("view_depth", [&] {
      gpu::ComputeProgram program("render/view_depth.comp");
      glsl::set_uniform(program, "u_march", params);
      glBindTextureUnit(shader_bindings::render_march_sources::terrain_heights, terrain);
      // The ground distance of each listed pixel of an image of `size`.
      const auto distances = [&](const std::vector<glm::ivec2>& pixels, glm::ivec2 size) {
        std::vector<float> out(pixels.size());
        if (pixels.empty()) return out;
        const gpu::StorageBuffer listed(pixels.size() * sizeof(glm::ivec2), pixels.data());
        const gpu::StorageBuffer distance_buffer(out.size() * sizeof(float));
        listed.bind(shader_bindings::render_view_depth::guide_pixels);
        distance_buffer.bind(shader_bindings::render_view_depth::ground_distances);
        program.set("u_image_size", size);
        program.set("u_pixel_count", static_cast<int>(pixels.size()));
        program.dispatch_covering(static_cast<int>(pixels.size()), 1, 1);
        distance_buffer.read(out.data(), out.size() * sizeof(float));
        return out;
      };
      // The marcher found the marched image's (clouds.comp); of the full size only the pixels
      // near an edge of that guide need theirs, the others have none (NaN: bilinear).
      const std::vector<glm::ivec2> near_edges = guide_pixels(result.ground_distance, full.x, full.y);
      const std::vector<float> found = distances(near_edges, full);
      result.upsampled_ground_distance = {full.x, full.y, 1,
                                          std::vector<float>(static_cast<std::size_t>(full.x) * full.y, NAN)};
      for (std::size_t k = 0; k < near_edges.size(); ++k)
        result.upsampled_ground_distance.pixels[static_cast<std::size_t>(near_edges[k].y) * full.x + near_edges[k].x] =
            found[k];
      guided = near_edges.size();
    });
    result.passes.push_back("view_depth " + std::to_string(camera.width) + "x" + std::to_string(camera.height) +
                            " and " + std::to_string(guided) + " pixels of " + std::to_string(full.x) + "x" +
                            std::to_string(full.y));
  }
  if (stride > 1) result.passes.push_back("march 1 of " + std::to_string(stride * stride) + " pixels");
  result.march_stride = stride;
  result.march_phase = phase;
  if (sum.empty()) {
    result.radiance = {camera.width, camera.height, 4, image.read()};
  } else {
    std::vector<float> mean(sum.size());
    for (size_t k = 0; k < sum.size(); ++k) mean[k] = static_cast<float>(sum[k] / std::max(settings.frames, 1));
    result.radiance = {camera.width, camera.height, 4, std::move(mean)};
    result.passes.push_back("accumulate " + std::to_string(settings.frames) + " frames");
  }
  glDeleteTextures(1, &weather);
  if (terrain != 0) glDeleteTextures(1, &terrain);
  if (land_cover != 0) glDeleteTextures(1, &land_cover);
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
