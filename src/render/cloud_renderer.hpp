#pragma once
// Renders the cloud layers, sky and ground seen from a point near the ground (GPU ray marching).
#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "params/field_binding.hpp"
#include "params/table.hpp"
#include "core/image.hpp"
#include "gpu/textures.hpp"
#include "regional/cloud_layers.hpp"
#include "regional/terrain.hpp"
#include "regional/weather_field.hpp"
#include "shader_math/shader_math.hpp"

namespace nephele::render {

class ConvectiveVolumes;  // render/convective_volumes.hpp

// The strength of the heaped clouds' render-time detail erosion (MarchParams::detail_erosion,
// cloud_march.glsl): the detail noise takes up to a third of an edge's density, a little less
// than the models' own erosion (0.5), which shapes the larger lobes.
constexpr float detail_erosion_strength = 0.35f;

struct Camera {
  double latitude_deg = 0, longitude_deg = 0, height_m = 0;  // WGS84, height above the ellipsoid
  double heading_deg = 0;                                    // clockwise from north
  double pitch_deg = 0;                                      // up from the horizon
  double fov_deg = 60;                                       // horizontal field of view
  bool panorama = false;                                     // full 360 x 180 view sphere instead of a perspective view
  int width = 1280, height = 720;
};

// The camera's fields by the parameters that declare them (position, heading, pitch, fov), so
// that a scene or the viewer's state moves into it through the table (params/field_binding.hpp).
std::vector<params::FieldBinding> field_bindings(Camera& camera);

// A perspective camera's axes in its east-north-up frame (level right, up = right x forward)
// and tan(fov / 2): what the marcher's view_direction spans its pixels with.
struct CameraFrame {
  glm::dvec3 forward, right, up;
  double tan_half_fov;
};
CameraFrame camera_frame(const Camera& camera);

// The layers' shadow maps of a render, kept by a caller that renders the same scene again (the
// viewer's bands of one frame): render_clouds makes them again only when their key changes.
struct ShadowMapCache {
  gpu::Texture maps;
  gpu::Texture sky;  // the sky's map (crepuscular rays)
  std::uint64_t key = 0;
};

struct RenderSettings {
  int view_steps = 48;   // samples per layer interval along the view ray
  int light_steps = 12;  // samples towards the sun per cloud sample
  int sky_steps = 16;    // samples of the clear-sky integral
  float powder = 0.0f;   // strength of the powder term (cloud_density.glsl), 0: none
  int frames = 1;        // frames averaged, each with its own jitter of the march start
  // render_prepared marches 1/N of the width and height and upsamples (render/upsample.hpp);
  // render_clouds itself always renders the camera's size.
  int resolution_divisor = 1;
  double max_distance_m = 150000;
  std::uint32_t seed = 1;
  int noise_size = 64;  // texels per side of the noise volume
  // Texels per side of the shadow maps of layers with layers above them (docs/rendering.md,
  // "Shadows between layers"); they span max_distance_m each way from the camera. 0: none.
  int shadow_map_size = 512;
  bool read_shadow_maps = false;                 // RenderResult::shadow_maps gets their texels (tests)
  std::shared_ptr<ShadowMapCache> shadow_cache;  // none: the maps are made for each render
  // Only rows [first_row, first_row + row_count) of the image are marched (row_count 0: every
  // row); the others are left undefined. Each pixel is the same as in a whole render: the
  // viewer refines a frame in bands of rows across frames.
  int first_row = 0, row_count = 0;
  // Reduced-rate marching (the viewer's moving preview; docs/rendering.md, "Reprojection:
  // march_stride"): only
  // the pixels (x, y) with x % march_stride == march_phase.x and y % march_stride ==
  // march_phase.y are marched, each the same as in a whole render; the others are left
  // undefined (render/reprojection.hpp fills them). Stride 1: every pixel. A stride above 1
  // needs the whole image (no band), one frame and no resolution divisor.
  int march_stride = 1;
  glm::ivec2 march_phase{0, 0};
  // The ground's height field about the camera (io::load_terrain); none: the bare sphere.
  std::shared_ptr<const regional::TerrainGrid> terrain;
  // The size the image will be upsampled to (render_prepared sets it when a divisor is above 1;
  // 0 x 0: none). render_clouds then also finds where every pixel's view ray meets the ground, at
  // the camera's size and at this one: the guide of render::upsample_guided.
  glm::ivec2 upsample_size{0, 0};
};

// The fields of `settings` that a scene's parameters set (render_settings copies through them).
std::vector<params::FieldBinding> field_bindings(RenderSettings& settings);

struct RenderResult {
  core::ImageData radiance;         // RGBA float, linear; A = cloud opacity
  std::vector<std::string> passes;  // what ran, in order (for --verbose and tests)
  std::vector<std::pair<std::string, double>> timings_ms;
  glm::dvec3 sun_direction;  // east, north, up
  double sun_elevation_deg = 0;
  // Pixels whose shader loops needed 65535 iterations or more: llvmpipe cuts those short (in
  // any frame of an accumulation, counted per frame); and which: pixel y width + x is bit k % 32
  // of word k / 32 (see loop_limited()).
  std::uint32_t loop_limited_pixels = 0;
  // With RenderSettings::read_shadow_maps: the maps, shadow_map_size^2 floats each in the order
  // of LayerParams::shadow_map, rows from v = 0 (south).
  std::vector<float> shadow_maps;
  std::vector<float> sky_shadow_map;  // likewise the sky's, sky_shadow_map_size^2 floats
  // With RenderSettings::upsample_size: the distance (m) along each pixel's view ray to the
  // ground, -1 where the ray meets none (one channel), at the camera's size and at that size
  // (render/view_depth.comp).
  core::ImageData ground_distance, upsampled_ground_distance;
  std::vector<std::uint32_t> loop_limited_bits;
  // The march lattice this render used (RenderSettings::march_stride, march_phase): with a
  // stride above 1 only its pixels hold values (render/reprojection.hpp fills the others).
  int march_stride = 1;
  glm::ivec2 march_phase{0, 0};
  bool loop_limited(int x, int y) const {
    const std::size_t k = static_cast<std::size_t>(y) * radiance.width + x;
    return k / 32 < loop_limited_bits.size() && ((loop_limited_bits[k / 32] >> (k % 32)) & 1u) != 0;
  }
};

// The Gaussian radius of curvature sqrt(M N) of WGS84 at a latitude: the sphere that osculates
// the ellipsoid best at the viewpoint.
double osculating_earth_radius(double latitude_deg);
// Sun direction in the local east-north-up frame.
glm::dvec3 sun_direction_enu(double unix_seconds, double latitude_deg, double longitude_deg,
                             double* elevation_deg = nullptr);
// Sky irradiance on a horizontal surface at an altitude (CPU twin of the shader's sky), used as
// the clouds' ambient light.
glm::vec3 sky_irradiance(glm::vec3 sun, double earth_radius, double altitude_m);

// The clear sky's diffuse share of the global irradiance on a horizontal surface, measured:
// Erbs, Klein and Duffie, "Estimation of the diffuse radiation fraction for hourly, daily and
// monthly-average global radiation", Solar Energy 28(4), 1982: 0.165 at clearness indices above
// 0.8 (the clearest skies; hazier ones have more).
constexpr float clear_sky_diffuse_fraction = 0.165f;

// The sky's irradiance on the ground at altitude_m: sky_irradiance's single scattering (its
// colour) raised, where it is less, to the measured clear-sky diffuse share of the global
// irradiance: D = f / (1 - f) x the direct sun's on the horizontal (green). Single scattering
// through the clean model atmosphere (Mie optical depth 0.005) gives a third of that with the
// sun high, which left cloud shadows near-black (docs/rendering.md).
glm::vec3 ground_sky_irradiance(glm::vec3 sun, double earth_radius, double altitude_m);

// The tileable shape and detail noise the marcher reads (render/noise_volume.comp,
// mipmapped): size^3 texels, RGBA (shape and detail noise, rank-equalised; the G3 and W3
// fields of the Webanck forms). Needs a current OpenGL 4.5 context.
class NoiseVolume {
 public:
  static constexpr int channels = 4;
  NoiseVolume(int size, std::uint32_t seed);
  // A volume made before (level0() of one of the same size and seed, e.g. from a disk cache):
  // level 0 uploaded, the mip levels generated from it as the constructor above does, so the
  // texture is the same to the bit.
  NoiseVolume(int size, std::uint32_t seed, const std::vector<float>& level0);
  ~NoiseVolume();
  NoiseVolume(const NoiseVolume&) = delete;
  NoiseVolume& operator=(const NoiseVolume&) = delete;
  unsigned texture() const { return texture_; }
  int size() const { return size_; }
  std::uint32_t seed() const { return seed_; }
  // Every mip level read back, for the marcher's C++ twin (tests).
  glsl::VolumeSource host_copy() const;
  // Level 0 read back: size^3 RGBA texels of floats, x fastest.
  std::vector<float> level0() const;
  // What determines the volume besides size and seed: a hash of the expanded shader source
  // and the version of the host's equalisation; a cache key must include it.
  static std::string recipe_key();

 private:
  unsigned texture_ = 0;
  int size_;
  std::uint32_t seed_;
};

// Whether render_clouds marches a layer, and so reads a noise volume.
bool needs_noise_volume(const std::vector<regional::CloudLayer>& layers, const regional::WeatherField& field);

// What the marcher (shaders/lib/cloud_march.glsl) is given for a render: the layers with cloud
// in the field (at most MAX_LAYERS), camera, sun, sky light and step counts. render_clouds
// uploads it; the marcher's C++ twin takes it as it is.
glsl::MarchParams march_params(const Camera& camera, const std::vector<regional::CloudLayer>& layers,
                               const regional::WeatherField& field, double unix_seconds, const RenderSettings& settings,
                               glm::dvec2 wind_towards = {0, 1}, double wind_speed = 0,
                               const ConvectiveVolumes* convective = nullptr);

// How many shadow maps a render with these parameters makes (layers with layers above them).
int shadow_map_count(const glsl::MarchParams& params);
// Texels per side of the sky's shadow map (crepuscular rays; MarchParams::sky_shadow_map): a
// quarter of the layers' maps, since the clear-sky integral's samples lie kilometres apart; 0
// with shadow_map_size 0.
int sky_shadow_map_size(int shadow_map_size);

// Needs a current OpenGL 4.5 context. Layers whose coverage channel is zero everywhere in the
// field are not marched (their absence is listed in passes). The noise volume is made when a
// layer is marched, unless `noise` (of settings.noise_size and settings.seed) is given: renders
// of one scene with other step counts share it. `convective`: the convective clouds' volumes,
// marched with the layers (docs/convection.md); none: no convective cloud.
RenderResult render_clouds(const Camera& camera, const std::vector<regional::CloudLayer>& layers,
                           const regional::WeatherField& field, double unix_seconds, const RenderSettings& settings,
                           glm::dvec2 wind_towards = {0, 1}, double wind_speed = 0, const NoiseVolume* noise = nullptr,
                           const ConvectiveVolumes* convective = nullptr);

// Display encoding for PNG: exposure, the ACES filmic curve fit of Narkowicz (2015), sRGB.
core::ImageData tone_map(const core::ImageData& radiance, double exposure);

}  // namespace nephele::render
