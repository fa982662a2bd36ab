#pragma once
// The orbit view: the planet seen from anywhere between 1 m and 40000 km above it, with a
// volumetric cloud shell driven by the global cover, cloud shadows, city lights on the night
// side and the atmosphere (shaders/render/orbit.comp, docs/orbit_view.md).
//
// Use: make one OrbitRenderer (it uploads the textures once; needs a current OpenGL 4.5
// context, e.g. gpu::EglContext or a window's), then render(camera, time) per frame.
#include <glm/glm.hpp>

#include <memory>
#include <vector>

#include "core/image.hpp"
#include "params/field_binding.hpp"
#include "params/table.hpp"
#include "render/cloud_renderer.hpp"

namespace nephele::render {

struct OrbitCamera {
  double latitude_deg = 0, longitude_deg = 0;  // the point below the camera (spherical planet)
  double altitude_m = 2000000;                 // above the planet's sphere, 1 m to 4e7 m
  double heading_deg = 0;                      // clockwise from north
  double pitch_deg = -90;                      // up from the local horizon; -90 looks at the planet's centre
  double fov_deg = 70;                         // horizontal field of view
  int width = 1280, height = 720;
};

// The orbit camera's fields by the parameters that declare them: the point below it by the
// camera's position (params::scene::latitude, longitude), heading, pitch and fov; so that the
// viewer's camera becomes an orbit camera through the table (its height, above the ellipsoid,
// becomes altitude_m above the sphere by the caller's rule).
std::vector<params::FieldBinding> field_bindings(OrbitCamera& camera);

// The top of the atmosphere above the planet's sphere (atmosphere.glsl's ATMOSPHERE_THICKNESS),
// and whether a cloud shell from base_m, thickness_m thick, ends below it: the rule the
// renderer and `render --view orbit`'s options share.
double atmosphere_top_km();
bool cloud_shell_fits(double base_m, double thickness_m);

struct OrbitSettings {
  double planet_radius_m = 6371000;  // mean Earth radius (IUGG)
  // The shell the clouds may lie in (their slabs come from the cover's tau and cloud_top,
  // clipped to it): from the lowest bases to the tropical tropopause.
  double cloud_base_m = 300;
  double cloud_thickness_m = 15700;
  double night_lights = 0.08;  // radiance (W m^-2 sr^-1 nm^-1) of a city-light texel of value 1
  // The mean wind over the sea (m/s) for the glint's facet slopes: 7 m/s, about the global ocean
  // mean of the 10 m wind (scatterometer climatologies: 7 to 7.5 m/s; docs/orbit_view.md). The
  // wind varies about it from place to place (sun_glint.glsl's sea_wind_speed).
  double sea_wind_ms = 7.0;
  // The sub-texel cloud (fractal edges and top relief below the cover's texels, cloud_properties.glsl's
  // subtexel_cloud): 1 draws it, 0 the cover's texels as smooth slabs, between a mix.
  double cloud_detail = 1.0;
  // The deviation of ln tau inside a cover texel's cloud, drawn with the sub-texel cloud
  // (cloud_properties.glsl's subtexel_optical_thickness; the parameter table's cloud_tau_spread).
  double cloud_tau_spread = params::scene::cloud_tau_spread.default_number;
  int cloud_steps = 32;  // samples along a view ray through the shell
  int shadow_steps = 6;  // samples from the ground towards the sun
  int sky_steps = 12;    // samples of the atmosphere along a view ray
};

// The planet's surface: equirect images, longitude -180 at the left edge, north up, RGB or RGBA,
// linear values (io::read_planet_textures decodes sRGB). An empty night image means no lights.
struct PlanetImages {
  core::ImageData day, night;
  // The fraction of each pixel that is open water (one channel, the same equirect layout), where
  // the sun glints (shaders/lib/sun_glint.glsl); empty: no glint.
  core::ImageData water;
  // The ground's slopes (two channels: metres of rise per metre towards the east and the north,
  // the same equirect layout), which turn the ground towards or away from the sun
  // (shaders/lib/ground_relief.glsl), and optionally a third: the slopes' root mean square around
  // each texel, which sets how steep the relief drawn below the texels is (land_mosaic.glsl;
  // without it none is drawn); empty: flat ground.
  core::ImageData relief;
  // The water along a window of the planet, finer than `water` (GSHHG's shorelines:
  // io/coastline_files.hpp): one channel, an equirect of the window's edges (degrees; west may
  // lie below -180); empty: `water` alone.
  core::ImageData coast;
  double coast_south_deg = 0, coast_north_deg = 0, coast_west_deg = 0, coast_east_deg = 0;
  // The water has the sea's own colour (sun_glint.glsl's SEA_BODY_ALBEDO, mirroring the sky)
  // where the day map's alpha, the share of its texel that is not ice, lets it; false: the day
  // map's colours as they are (a named day map).
  bool sea_colour = false;
};

// The global cover as a cube map: faces +X, -X, +Y, -Y, +Z, -Z, size x size floats each, rows
// from t = 0 (io::read_cover_faces, or cover::GlobalCover's fields read back): the coverage, and
// where known the optical thickness and the cloud-top height (km; empty: derived from the
// coverage by cloud_properties.glsl's fallbacks).
struct CoverCube {
  int size = 0;
  std::vector<float> texels;
  std::vector<float> optical_thickness, cloud_top;
};

// Camera frame in Earth-centred, Earth-fixed axes (+Z north, +X latitude 0 longitude 0), double.
struct OrbitFrame {
  glm::dvec3 position;            // camera, m from the planet's centre
  glm::dvec3 forward, right, up;  // unit vectors of the view
};
OrbitFrame orbit_frame(const OrbitCamera& camera, double planet_radius_m);
// Unit direction towards the sun in Earth-centred, Earth-fixed axes at a UTC time.
glm::dvec3 sun_direction_ecef(double unix_seconds);
// The pixel (column, row from the top; fractional, centres at .5) where the ray towards an
// ECEF point meets the image, or (-1, -1) when the point is behind the camera.
glm::dvec2 project_to_pixel(const OrbitCamera& camera, double planet_radius_m, glm::dvec3 point);
// The horizontal field of view that shows the whole planet disc with a margin when looking at
// its centre (clamped to 10..120 degrees): the default of `render --view orbit`.
double framing_fov_deg(double altitude_m, double planet_radius_m, int width, int height);
// The brightest a white surface could look in the frame: the luminance (Rec. 709 weights,
// W m^-2 sr^-1 nm^-1) of a white Lambertian surface on the ground, lit by the sun through the
// air (the transmittance of atmosphere.glsl) and by the sky's ambient light, times the air's
// transmittance from it towards the camera, largest over the ground points of a grid of
// 64 x 36 of the frame's rays; 0 where none of them meets sunlit ground. What an incident-light
// meter gives a photographer; render::highlight_exposure never exposes brighter than this
// surface needs.
double sunlit_white_luminance(const OrbitCamera& camera, double unix_seconds, double planet_radius_m);

class OrbitRenderer {
 public:
  // Uploads the textures (mipmapped) and builds the program. Throws std::invalid_argument for an
  // empty day image or a cover of the wrong size.
  OrbitRenderer(const PlanetImages& planet, const CoverCube& cover, const OrbitSettings& settings = {});
  ~OrbitRenderer();
  OrbitRenderer(const OrbitRenderer&) = delete;
  OrbitRenderer& operator=(const OrbitRenderer&) = delete;

  // One frame: RGBA float linear radiance (A = cloud opacity), the passes and their times, the
  // sun at the sub-camera point. Throws std::invalid_argument for a camera out of range. With
  // row_count > 0 only the tiles that hold rows [first_row, first_row + row_count) are drawn (a
  // band of the viewer's refinement); the other rows are 0.
  RenderResult render(const OrbitCamera& camera, double unix_seconds, int first_row = 0, int row_count = 0) const;
  // The same frame into a texture the caller owns (GL_RGBA32F, 2D, at least camera.width x
  // camera.height; a window viewer draws it without reading it back). Returns milliseconds.
  // Only the tiles whose rays can meet the air are drawn (tiles_in_air); the rest of the
  // camera's pixels are cleared to 0, black clear space.
  double render_into(const OrbitCamera& camera, double unix_seconds, unsigned rgba32f_texture) const;
  // The tiles render_into draws (orbit_tiles.hpp), and the frame drawing the given ones (e.g.
  // all_tiles, to check that the others show space).
  std::vector<glm::uvec2> tiles_in_air(const OrbitCamera& camera) const;
  double render_tiles(const OrbitCamera& camera, double unix_seconds, unsigned rgba32f_texture,
                      const std::vector<glm::uvec2>& tiles) const;
  const OrbitSettings& settings() const { return settings_; }
  void set_settings(const OrbitSettings& settings);  // same textures; checks as the constructor
  void set_cover(const CoverCube& cover);            // a new cover (e.g. regenerated), same checks
  // A new window of water finer than the water map (as PlanetImages::coast and its edges, degrees);
  // an empty or malformed image, or edges that enclose nothing, remove the window.
  void set_coast(const core::ImageData& coast, double south_deg, double north_deg, double west_deg, double east_deg);

 private:
  void update_sky_table();  // makes the air's tables anew when the radius changed
  struct Gl;
  std::unique_ptr<Gl> gl_;
  OrbitSettings settings_;
};

// One frame without keeping the renderer (uploads everything each call).
RenderResult render_orbit(const OrbitCamera& camera, double unix_seconds, const PlanetImages& planet,
                          const CoverCube& cover, const OrbitSettings& settings = {});

// A planet texture when no image is at hand: ocean and land from smooth value noise, ice caps.
PlanetImages procedural_planet(int width = 1024, int height = 512);

}  // namespace nephele::render
