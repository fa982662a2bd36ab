#include "render/orbit_renderer.hpp"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "gpu/storage_buffer.hpp"
#include "gpu/shader_bindings.hpp"
#include "gpu/compute_program.hpp"
#include "gpu/pass_timer.hpp"
#include "gpu/textures.hpp"
#include "params/table.hpp"
#include "render/orbit_textures.hpp"
#include "render/orbit_tiles.hpp"
#include "render/sky_table.hpp"
#include "render/sun_position.hpp"
#include "shader_math/shader_math.hpp"

namespace nephele::render {

std::vector<params::FieldBinding> field_bindings(OrbitCamera& c) {
  namespace sc = params::scene;
  return {{&sc::latitude, &c.latitude_deg},
          {&sc::longitude, &c.longitude_deg},
          {&sc::heading, &c.heading_deg},
          {&sc::pitch, &c.pitch_deg},
          {&sc::fov, &c.fov_deg}};
}
namespace {

constexpr double degree = M_PI / 180.0;
// The atmosphere's top above the sphere: atmosphere.glsl's constant, through its C++ twin.
const double atmosphere_thickness_m = glsl::ATMOSPHERE_THICKNESS;

struct Enu {
  glm::dvec3 east, north, up;
};

Enu enu_at(double latitude_deg, double longitude_deg) {
  const double lat = latitude_deg * degree, lon = longitude_deg * degree;
  return {{-std::sin(lon), std::cos(lon), 0.0},
          {-std::sin(lat) * std::cos(lon), -std::sin(lat) * std::sin(lon), std::cos(lat)},
          {std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)}};
}

void check_camera(const OrbitCamera& c) {
  auto bad = [](const std::string& what) { throw std::invalid_argument("orbit camera: " + what); };
  if (!(c.latitude_deg >= -90 && c.latitude_deg <= 90)) bad("latitude outside -90..90 degrees");
  if (!(c.longitude_deg >= -360 && c.longitude_deg <= 360)) bad("longitude outside -360..360 degrees");
  if (!(c.altitude_m >= 1 && c.altitude_m <= 4.0e7)) bad("altitude outside 1 m..40000 km");
  if (!(c.fov_deg >= 0.001 && c.fov_deg <= 179)) bad("field of view outside 0.001..179 degrees");
  if (!(c.pitch_deg >= -90 && c.pitch_deg <= 90) || !std::isfinite(c.heading_deg)) bad("pitch or heading out of range");
  if (c.width < 1 || c.height < 1) bad("image size below 1 x 1");
}

void check_settings(const OrbitSettings& s) {
  auto bad = [](const std::string& what) { throw std::invalid_argument("orbit settings: " + what); };
  if (!(s.planet_radius_m >= 1000 && s.planet_radius_m <= 1.0e9)) bad("planet radius outside 1 km..1e6 km");
  if (!(s.cloud_base_m >= 0) || !(s.cloud_thickness_m > 0) || !cloud_shell_fits(s.cloud_base_m, s.cloud_thickness_m))
    bad("the cloud shell must lie within the atmosphere (" + std::to_string(atmosphere_top_km()) +
        " km) and have a thickness above 0");
  if (!(s.night_lights >= 0) || !(s.sea_wind_ms >= 0)) bad("negative night lights or sea wind");
  if (!(s.cloud_detail >= 0 && s.cloud_detail <= 1)) bad("cloud detail outside 0..1");
  if (!(s.cloud_tau_spread >= 0 && s.cloud_tau_spread <= 2)) bad("cloud tau spread outside 0..2");
  if (s.cloud_steps < 1 || s.cloud_steps > 1024 || s.shadow_steps < 0 || s.shadow_steps > 256 || s.sky_steps < 1 ||
      s.sky_steps > 256)
    bad("step counts out of range");
}

}  // namespace

double atmosphere_top_km() { return atmosphere_thickness_m / 1000.0; }
bool cloud_shell_fits(double base_m, double thickness_m) { return base_m + thickness_m < atmosphere_thickness_m; }

namespace {

void check_cover(const CoverCube& cover) {
  const size_t texels = 6 * static_cast<size_t>(std::max(cover.size, 0)) * std::max(cover.size, 0);
  if (cover.size < 1 || cover.texels.size() != texels)
    throw std::invalid_argument("orbit renderer: the cover cube needs 6 x size x size texels");
  if ((!cover.optical_thickness.empty() || !cover.cloud_top.empty()) &&
      (cover.optical_thickness.size() != texels || cover.cloud_top.size() != texels))
    throw std::invalid_argument("orbit renderer: the cover's tau and cloud tops need a value per texel, or none");
}

// Smooth value noise on the lattice of integers (for the procedural planet).
double lattice(int x, int y, int z) {
  std::uint32_t h = static_cast<std::uint32_t>(x) * 73856093u ^ static_cast<std::uint32_t>(y) * 19349663u ^
                    static_cast<std::uint32_t>(z) * 83492791u;
  h ^= h >> 13;
  h *= 0x5bd1e995u;
  h ^= h >> 15;
  return (h & 0xffffffu) / double(0xffffff);
}

double value_noise(glm::dvec3 p) {
  const glm::dvec3 f = glm::floor(p), t = p - f;
  const glm::dvec3 w = t * t * (3.0 - 2.0 * t);
  const int x = int(f.x), y = int(f.y), z = int(f.z);
  double result = 0;
  for (int k = 0; k < 8; ++k) {
    const int dx = k & 1, dy = (k >> 1) & 1, dz = (k >> 2) & 1;
    result += lattice(x + dx, y + dy, z + dz) * (dx ? w.x : 1 - w.x) * (dy ? w.y : 1 - w.y) * (dz ? w.z : 1 - w.z);
  }
  return result;
}

}  // namespace

OrbitFrame orbit_frame(const OrbitCamera& camera, double planet_radius_m) {
  const Enu local = enu_at(camera.latitude_deg, camera.longitude_deg);
  const double heading = camera.heading_deg * degree, pitch = camera.pitch_deg * degree;
  const glm::dvec3 f(std::sin(heading) * std::cos(pitch), std::cos(heading) * std::cos(pitch), std::sin(pitch));
  const glm::dvec3 r(std::cos(heading), -std::sin(heading), 0.0);
  const glm::dvec3 u = glm::cross(r, f);
  auto to_ecef = [&](glm::dvec3 v) { return v.x * local.east + v.y * local.north + v.z * local.up; };
  return {(planet_radius_m + camera.altitude_m) * local.up, glm::normalize(to_ecef(f)), glm::normalize(to_ecef(r)),
          glm::normalize(to_ecef(u))};
}

glm::dvec3 sun_direction_ecef(double unix_seconds) {
  // The sun's direction is the same everywhere (parallax below 5e-5 rad): read it at latitude 0,
  // longitude 0, where east, north and up are +Y, +Z and +X.
  const SunPosition sun = sun_position(unix_seconds, 0.0, 0.0);
  const double el = sun.elevation_deg * degree, az = sun.azimuth_deg * degree;
  return {std::sin(el), std::cos(el) * std::sin(az), std::cos(el) * std::cos(az)};
}

glm::dvec2 project_to_pixel(const OrbitCamera& camera, double planet_radius_m, glm::dvec3 point) {
  const OrbitFrame frame = orbit_frame(camera, planet_radius_m);
  const glm::dvec3 v = point - frame.position;
  const double z = glm::dot(v, frame.forward);
  if (z <= 0) return {-1, -1};
  const double tan_half = std::tan(camera.fov_deg * degree / 2);
  const double x = glm::dot(v, frame.right) / z / tan_half;
  const double y = glm::dot(v, frame.up) / z / tan_half / (double(camera.height) / camera.width);
  return {(x + 1) / 2 * camera.width, (1 - y) / 2 * camera.height};
}

double framing_fov_deg(double altitude_m, double planet_radius_m, int width, int height) {
  // Angular radius of the disc including the atmosphere's glow; the vertical field gets 15 % more.
  const double radius = planet_radius_m + 60000.0;
  const double distance = planet_radius_m + altitude_m;
  const double half = distance > radius ? std::asin(radius / distance) : M_PI / 2;
  const double vertical_tan = std::tan(std::min(1.15 * half, 1.4));
  const double horizontal = 2 * std::atan(vertical_tan * double(width) / height) / degree;
  return std::clamp(horizontal, 10.0, 120.0);
}

double sunlit_white_luminance(const OrbitCamera& camera, double unix_seconds, double planet_radius_m) {
  const OrbitFrame frame = orbit_frame(camera, planet_radius_m);
  const glsl::vec3 sun(sun_direction_ecef(unix_seconds));
  const float R = static_cast<float>(planet_radius_m);
  const TileView view{frame.position, frame.forward, frame.right, frame.up, std::tan(camera.fov_deg * degree / 2),
                      camera.width,   camera.height};
  const int columns = 64, rows = 36;
  double brightest = 0.0;
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) {
      // The ray through the grid cell's centre, as orbit.comp makes a pixel's.
      const glm::dvec3 d = view_ray(view, (i + 0.5) / columns * camera.width, (j + 0.5) / rows * camera.height);
      const double t = sphere_entry(frame.position, d, planet_radius_m);
      if (t <= 0.0) continue;
      const glsl::vec3 n(glm::normalize(frame.position + t * d));
      const float mu = dot(n, sun);
      if (mu <= 0.0f) continue;
      // The surface's radiance, and what of it reaches the camera through the air (the path
      // towards the camera, outside the air or in it: its transmittance to space is the bound).
      const glsl::vec3 p = n * (R + 1.0f);
      const glsl::vec3 white = glsl::solar_irradiance() * glsl::transmittance_to_space(p, sun, R) * (mu / glsl::PI_F) +
                               glsl::sky_ambient(n, sun);
      const glsl::vec3 seen = white * glsl::transmittance_to_space(p, glsl::vec3(-d), R);
      brightest = std::max(brightest, 0.2126 * seen.x + 0.7152 * seen.y + 0.0722 * seen.z);
    }
  return brightest;
}

struct OrbitRenderer::Gl {
  gpu::ComputeProgram program{"render/orbit.comp"};
  GLuint day = 0, night = 0, water = 0, relief = 0, cover = 0, coast = 0;
  glm::vec4 coast_window{0.0f};  // radians: south, north, west, east (west >= east: none)
  float coast_texel = 1.0f;      // m north to south
  bool sea_colour = false;
  GLuint sky_table = 0;      // the air's multiple scattering for the planet's radius
  GLuint transmittance = 0;  // and its transmittance
  double sky_table_radius = 0;
  gpu::StorageBuffer tiles;  // the frame's tiles to draw (orbit_tiles.hpp), uvec2 each
  int day_width = 1, relief_width = 1, cover_size = 1;
  bool cover_properties = false;  // the cover has its own tau and cloud tops
  ~Gl() {
    for (GLuint id : {day, night, water, relief, cover, coast, sky_table, transmittance})
      if (id != 0) glDeleteTextures(1, &id);
  }
};

OrbitRenderer::OrbitRenderer(const PlanetImages& planet, const CoverCube& cover, const OrbitSettings& settings)
    : gl_(std::make_unique<Gl>()), settings_(settings) {
  check_settings(settings);
  // An image with at least `channels` channels and a value for each of them at every pixel.
  auto usable = [](const core::ImageData& image, int channels) {
    return image.width >= 1 && image.height >= 1 && image.channels >= channels &&
           image.pixels.size() == static_cast<size_t>(image.width) * image.height * image.channels;
  };
  if (!usable(planet.day, 1) || planet.day.width < 2)
    throw std::invalid_argument("orbit renderer: the day image is empty or malformed");
  check_cover(cover);
  // A missing or malformed night, water or relief image stands for none (no lights, no water,
  // flat ground), by a one-texel stand-in; the images themselves are not copied.
  auto or_none = [&](const core::ImageData& image, int channels, const core::ImageData& none) -> const auto& {
    return usable(image, channels) ? image : none;
  };
  static const core::ImageData no_lights{1, 1, 3, {0.0f, 0.0f, 0.0f}}, no_water{1, 1, 1, {0.0f}},
      flat{1, 1, 2, {0.0f, 0.0f}};
  gl_->day = colour_map_texture(planet.day);
  gl_->day_width = planet.day.width;
  gl_->night = colour_map_texture(or_none(planet.night, 1, no_lights));
  gl_->water = water_fraction_texture(or_none(planet.water, 1, no_water));
  set_coast(planet.coast, planet.coast_south_deg, planet.coast_north_deg, planet.coast_west_deg, planet.coast_east_deg);
  gl_->sea_colour = planet.sea_colour;
  const core::ImageData& relief = or_none(planet.relief, 2, flat);
  gl_->relief = slope_texture(relief);
  gl_->relief_width = relief.width;
  gl_->cover = cover_texture(cover);
  gl_->cover_size = cover.size;
  gl_->cover_properties = !cover.optical_thickness.empty();
  update_sky_table();
}

OrbitRenderer::~OrbitRenderer() = default;

void OrbitRenderer::update_sky_table() {
  if (gl_->sky_table != 0 && gl_->sky_table_radius == settings_.planet_radius_m) return;
  if (gl_->sky_table != 0) glDeleteTextures(1, &gl_->sky_table);
  if (gl_->transmittance != 0) glDeleteTextures(1, &gl_->transmittance);
  gl_->transmittance = transmittance_texture(static_cast<float>(settings_.planet_radius_m));
  gl_->sky_table =
      multiple_scattering_texture(gl_->transmittance, static_cast<float>(settings_.planet_radius_m), kPlanetAlbedo);
  gl_->sky_table_radius = settings_.planet_radius_m;
}

void OrbitRenderer::set_settings(const OrbitSettings& settings) {
  check_settings(settings);
  settings_ = settings;
  update_sky_table();
}

void OrbitRenderer::set_cover(const CoverCube& cover) {
  check_cover(cover);
  const GLuint texture = cover_texture(cover);
  glDeleteTextures(1, &gl_->cover);
  gl_->cover = texture;
  gl_->cover_size = cover.size;
  gl_->cover_properties = !cover.optical_thickness.empty();
}

void OrbitRenderer::set_coast(const core::ImageData& coast, double south_deg, double north_deg, double west_deg,
                              double east_deg) {
  const bool usable = coast.width >= 1 && coast.height >= 1 && coast.channels >= 1 &&
                      coast.pixels.size() == static_cast<size_t>(coast.width) * coast.height * coast.channels &&
                      north_deg > south_deg && east_deg > west_deg;
  static const core::ImageData no_water{1, 1, 1, {0.0f}};
  if (gl_->coast != 0) glDeleteTextures(1, &gl_->coast);
  gl_->coast = water_fraction_texture(usable ? coast : no_water);
  glTextureParameteri(gl_->coast, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);  // a window, not the globe
  gl_->coast_window = glm::vec4(0.0f);                                   // west >= east: none
  gl_->coast_texel = 1.0f;
  if (usable) {
    gl_->coast_window = glm::vec4(south_deg, north_deg, west_deg, east_deg) * float(degree);
    gl_->coast_texel = float((north_deg - south_deg) * degree * settings_.planet_radius_m / coast.height);
  }
}

std::vector<glm::uvec2> OrbitRenderer::tiles_in_air(const OrbitCamera& camera) const {
  check_camera(camera);
  const OrbitFrame frame = orbit_frame(camera, settings_.planet_radius_m);
  TileView view{frame.position, frame.forward, frame.right, frame.up, std::tan(camera.fov_deg * degree / 2),
                camera.width,   camera.height};
  return tiles_meeting_sphere(view, settings_.planet_radius_m + atmosphere_thickness_m);
}

double OrbitRenderer::render_into(const OrbitCamera& camera, double unix_seconds, unsigned rgba32f_texture) const {
  return render_tiles(camera, unix_seconds, rgba32f_texture, tiles_in_air(camera));
}

double OrbitRenderer::render_tiles(const OrbitCamera& camera, double unix_seconds, unsigned rgba32f_texture,
                                   const std::vector<glm::uvec2>& tiles) const {
  check_camera(camera);
  const OrbitSettings& s = settings_;
  const double R = s.planet_radius_m;
  const OrbitFrame frame = orbit_frame(camera, R);
  const glm::dvec3 sun = sun_direction_ecef(unix_seconds);
  // q = |camera - centre|^2 - r^2 = (h - h_r)(2R + h + h_r) for a sphere at altitude h_r: exact
  // in double, and no cancellation at all when the camera is 1 m above the ground.
  const double h = camera.altitude_m;
  auto q = [&](double sphere_altitude) {
    return static_cast<float>((h - sphere_altitude) * (2 * R + h + sphere_altitude));
  };
  const gpu::ComputeProgram& p = gl_->program;
  gpu::upload(gl_->tiles, tiles.data(), tiles.size() * sizeof(glm::uvec2), sizeof(glm::uvec2));
  return gpu::time_pass([&] {
    // Space: the pixels of the tiles not drawn see neither air nor planet.
    const float space[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearTexSubImage(rgba32f_texture, 0, 0, 0, 0, camera.width, camera.height, 1, GL_RGBA, GL_FLOAT, space);
    if (tiles.empty()) return;
    p.use();
    p.set("u_tile_count", static_cast<int>(tiles.size()));
    p.set("u_image_size", glm::ivec2(camera.width, camera.height));
    p.set("u_centre", glm::vec3(-frame.position));
    p.set("u_q_ground", q(0.0));
    p.set("u_q_base", q(s.cloud_base_m));
    p.set("u_q_top", q(s.cloud_base_m + s.cloud_thickness_m));
    p.set("u_q_atmosphere", q(atmosphere_thickness_m));
    p.set("u_radius", static_cast<float>(R));
    p.set("u_cloud_base", static_cast<float>(s.cloud_base_m));
    p.set("u_cloud_top", static_cast<float>(s.cloud_base_m + s.cloud_thickness_m));
    p.set("u_forward", glm::vec3(frame.forward));
    p.set("u_right", glm::vec3(frame.right));
    p.set("u_up", glm::vec3(frame.up));
    const double tan_half = std::tan(camera.fov_deg * degree / 2);
    p.set("u_tan_half_fov", static_cast<float>(tan_half));
    p.set("u_pixel_angle", static_cast<float>(2 * tan_half / camera.width));
    p.set("u_sun", glm::vec3(sun));
    p.set("u_night_lights", static_cast<float>(s.night_lights));
    p.set("u_sea_wind", static_cast<float>(s.sea_wind_ms));
    p.set("u_cover_texel", static_cast<float>(R * (M_PI / 2) / gl_->cover_size));
    p.set("u_cover_size", static_cast<float>(gl_->cover_size));
    p.set("u_cover_properties", gl_->cover_properties ? 1 : 0);
    p.set("u_tau_median", params::cover::tau_median.default_float());
    p.set("u_tau_spread", params::cover::tau_spread.default_float());
    p.set("u_cloud_detail", static_cast<float>(s.cloud_detail));
    p.set("u_cloud_tau_spread", static_cast<float>(s.cloud_tau_spread));
    p.set("u_day_texel", static_cast<float>(2 * M_PI * R / gl_->day_width));
    p.set("u_relief_texel", static_cast<float>(2 * M_PI * R / gl_->relief_width));
    p.set("u_coast_window", gl_->coast_window);
    p.set("u_coast_texel", gl_->coast_texel);
    p.set("u_sea_colour", gl_->sea_colour ? 1 : 0);
    p.set("u_cloud_steps", s.cloud_steps);
    p.set("u_shadow_steps", s.shadow_steps);
    p.set("u_sky_steps", s.sky_steps);
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    namespace orbit = shader_bindings::render_orbit;
    glBindImageTexture(orbit::radiance_image, rgba32f_texture, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindTextureUnit(orbit::day_texture, gl_->day);
    glBindTextureUnit(orbit::night_texture, gl_->night);
    glBindTextureUnit(orbit::water_texture, gl_->water);
    glBindTextureUnit(orbit::relief_texture, gl_->relief);
    glBindTextureUnit(orbit::coast_texture, gl_->coast);
    glBindTextureUnit(orbit::cover_map, gl_->cover);
    glBindTextureUnit(orbit::sky_table, gl_->sky_table);
    glBindTextureUnit(orbit::transmittance_table, gl_->transmittance);
    gl_->tiles.bind(orbit::tiles);
    // A work group per tile, in rows of at most 65535 groups (the dispatch's per-axis minimum).
    const GLuint count = GLuint(tiles.size()), per_row = std::min<GLuint>(count, 65535u);
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    glDispatchCompute(per_row, (count + per_row - 1) / per_row, 1);
    gpu::image_barrier();
  });
}

RenderResult OrbitRenderer::render(const OrbitCamera& camera, double unix_seconds, int first_row, int row_count) const {
  check_camera(camera);
  RenderResult result;
  const OrbitSettings& s = settings_;
  result.sun_direction =
      sun_direction_enu(unix_seconds, camera.latitude_deg, camera.longitude_deg, &result.sun_elevation_deg);
  gpu::Texture image = gpu::Texture::plane(camera.width, camera.height, GL_RGBA32F);
  const std::vector<glm::uvec2> tiles = tiles_in_rows(tiles_in_air(camera), first_row, row_count);
  const glm::ivec2 grid = tile_grid(camera.width, camera.height);
  result.timings_ms.emplace_back("orbit", render_tiles(camera, unix_seconds, image.id(), tiles));
  result.passes = {"orbit: " + std::to_string(tiles.size()) + " of " + std::to_string(grid.x * grid.y) +
                   " tiles, ground, cloud shell (" + std::to_string(s.cloud_steps) + " steps), shadows (" +
                   std::to_string(s.shadow_steps) + "), atmosphere (" + std::to_string(s.sky_steps) + ")"};
  result.timings_ms.emplace_back("read back", gpu::time_pass([&] {
                                   result.radiance = {camera.width, camera.height, 4, image.read()};
                                 }));
  return result;
}

RenderResult render_orbit(const OrbitCamera& camera, double unix_seconds, const PlanetImages& planet,
                          const CoverCube& cover, const OrbitSettings& settings) {
  RenderResult result;
  double upload_ms = 0;
  std::unique_ptr<OrbitRenderer> renderer;
  upload_ms = gpu::time_pass([&] { renderer = std::make_unique<OrbitRenderer>(planet, cover, settings); });
  result = renderer->render(camera, unix_seconds);
  result.passes.insert(result.passes.begin(), "upload textures");
  result.timings_ms.insert(result.timings_ms.begin(), {"upload textures", upload_ms});
  return result;
}

PlanetImages procedural_planet(int width, int height) {
  PlanetImages planet;
  planet.day = {width, height, 3, {}};
  planet.water = {width, height, 1, {}};
  planet.day.pixels.reserve(static_cast<size_t>(width) * height * 3);
  for (int j = 0; j < height; ++j) {
    const double lat = M_PI / 2 - (j + 0.5) * M_PI / height;
    for (int i = 0; i < width; ++i) {
      const double lon = -M_PI + (i + 0.5) * 2 * M_PI / width;
      const glm::dvec3 n(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat));
      double land = 0, amplitude = 0.5, frequency = 2.0;
      for (int octave = 0; octave < 5; ++octave, amplitude *= 0.5, frequency *= 2.0)
        land += amplitude * value_noise(n * frequency + glm::dvec3(17.0 * octave));
      glm::dvec3 colour = land > 0.52 ? glm::mix(glm::dvec3(0.06, 0.10, 0.03), glm::dvec3(0.25, 0.20, 0.12),
                                                 std::clamp((land - 0.52) * 5, 0.0, 1.0))
                                      : glm::dvec3(0.005, 0.015, 0.05);
      const bool ice = std::abs(lat) > 70 * degree;
      if (ice) colour = glm::dvec3(0.7, 0.72, 0.75);
      for (int c = 0; c < 3; ++c) planet.day.pixels.push_back(static_cast<float>(colour[c]));
      planet.water.pixels.push_back(land <= 0.52 && !ice ? 1.0f : 0.0f);
    }
  }
  return planet;
}

}  // namespace nephele::render
