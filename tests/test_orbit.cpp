// The orbit view (src/render/orbit_renderer.*, shaders/render/orbit.comp): orientation of the
// planet texture, night side and city lights, the limb, a cloud patch at its pixel, its shadow,
// the descent from 2000 km to 1 km, and the command line's checks. Frames are tiny (llvmpipe).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cmath>
#include <cstdint>
#include <vector>

#include "case_tags.hpp"
#include "cli_support.hpp"
#include "core/half_float.hpp"
#include "core/json.hpp"
#include "core/mip_levels.hpp"
#include "core/time.hpp"
#include "cover/global_cover.hpp"
#include "gl_support.hpp"
#include "files/image_files.hpp"
#include "io/cover_files.hpp"
#include "io/planet_textures.hpp"
#include "gpu/compute_program.hpp"
#include "gpu/textures.hpp"
#include "render/exposure.hpp"
#include "render/orbit_renderer.hpp"
#include "render/orbit_textures.hpp"
#include "render/orbit_tiles.hpp"
#include "shader_math/shader_math.hpp"

using namespace nephele;

namespace {

constexpr double degree = M_PI / 180.0;
const double june_morning = core::parse_utc_time("2026-06-21T08:00Z");  // noon near 60 E

glm::dvec3 unit_of(double latitude_deg, double longitude_deg) {
  const double lat = latitude_deg * degree, lon = longitude_deg * degree;
  return {std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)};
}

// An equirect image of `width` x width/2 whose RGB is f(latitude, longitude) at texel centres.
template <class F>
core::ImageData equirect(int width, F f) {
  const int height = width / 2;
  core::ImageData image{width, height, 3, {}};
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      const glm::dvec3 c = f(90.0 - (j + 0.5) * 180.0 / height, -180.0 + (i + 0.5) * 360.0 / width);
      for (int k = 0; k < 3; ++k) image.pixels.push_back(static_cast<float>(c[k]));
    }
  return image;
}

// The smooth test pattern: each channel changes sign under a flip of latitude or longitude, so a
// mirrored or shifted map gives other colours.
glm::dvec3 pattern(double latitude_deg, double longitude_deg) {
  const double lat = latitude_deg * degree, lon = longitude_deg * degree;
  return {0.5 + 0.4 * std::sin(lon) * std::cos(lat), 0.5 + 0.4 * std::sin(lat),
          0.5 + 0.4 * std::cos(lon) * std::cos(lat)};
}

render::CoverCube clear_cover(int size = 8) { return {size, std::vector<float>(6 * size * size, 0.0f)}; }

// The same cover, optical thickness and cloud top (km) everywhere.
render::CoverCube uniform_cover(int size, float cover, float tau, float top_km) {
  const size_t texels = 6 * size * size;
  return {size, std::vector<float>(texels, cover), std::vector<float>(texels, tau), std::vector<float>(texels, top_km)};
}

// A cover with coverage 1 within `radius_deg` of a point and 0 elsewhere (texel centres).
render::CoverCube patch_cover(int size, double latitude_deg, double longitude_deg, double radius_deg) {
  render::CoverCube cover{size, {}};
  const glm::dvec3 centre = unit_of(latitude_deg, longitude_deg);
  for (int face = 0; face < 6; ++face)
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i) {
        const double sc = 2 * (i + 0.5) / size - 1, tc = 2 * (j + 0.5) / size - 1;
        // OpenGL table 8.19 inverted (shaders/lib/cube_faces.glsl).
        const glm::dvec3 faces[6] = {{1, -tc, -sc}, {-1, -tc, sc}, {sc, 1, tc},
                                     {sc, -1, -tc}, {sc, -tc, 1},  {-sc, -tc, -1}};
        const double angle = std::acos(std::clamp(glm::dot(glm::normalize(faces[face]), centre), -1.0, 1.0));
        cover.texels.push_back(angle < radius_deg * degree ? 1.0f : 0.0f);
      }
  return cover;
}

glm::vec4 pixel(const render::RenderResult& r, int x, int y) {
  const size_t k = 4 * (static_cast<size_t>(y) * r.radiance.width + x);
  const auto& p = r.radiance.pixels;
  return {p[k], p[k + 1], p[k + 2], p[k + 3]};
}

double luminance(glm::vec4 c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

render::OrbitCamera nadir_camera(double latitude_deg, double longitude_deg, double altitude_m, int width, int height,
                                 double fov_deg = 20) {
  render::OrbitCamera c;
  c.latitude_deg = latitude_deg;
  c.longitude_deg = longitude_deg;
  c.altitude_m = altitude_m;
  c.pitch_deg = -90;
  c.fov_deg = fov_deg;
  c.width = width;
  c.height = height;
  return c;
}

// The steps of a series (frame to frame) that are jumps: more than three times as large as every
// step within two frames of it (a spike in the steps) and larger than `floor`, the size below which
// a step is noise (the fixed per-pixel jitter of the march on a 96 x 54 frame). Two frames, not
// one: where a cloud leaves the view as another enters, two frames can have the same cloud
// fraction by chance, and a step beside that flat one was judged against nothing (the default
// cover's descent on 2026-12-02: a step of 0.0095 between steps of 0.0028 and 0.000001, with
// 0.0113 and 0.0053 one further). A median over the whole
// series (issue 11's wording) fails series that are smooth but change unevenly: straight down
// over a clear hole, the cloud fraction falls to 0 in the first frames (the hole fills the view)
// and then stays 0, so the median step is 0; a local median still flags a fast but smooth decay.
// A switch between representations is a step out of line with the steps on both sides of it;
// the first and last steps have one side only, where the start of a smooth change (at 2000 km
// the limb leaves the frame within a few frames) looks the same, so they are not judged.
std::vector<size_t> largest_jumps(const std::vector<double>& series, double floor) {
  std::vector<double> steps;
  for (size_t k = 1; k < series.size(); ++k) steps.push_back(std::abs(series[k] - series[k - 1]));
  std::vector<size_t> jumps;
  for (size_t k = 1; k + 1 < steps.size(); ++k) {
    double around = 0;
    for (size_t j = k > 2 ? k - 2 : 0; j <= std::min(k + 2, steps.size() - 1); ++j)
      if (j != k) around = std::max(around, steps[j]);
    if (steps[k] > std::max(3 * around, floor)) jumps.push_back(k);
  }
  return jumps;
}

render::PlanetImages uniform_planet(double albedo) {
  return {equirect(16, [&](double, double) { return glm::dvec3(albedo); }), {}};
}

}  // namespace

TEST_CASE("orbit: the nadir pixel shows the texture's colour at the sub-camera point", "[orbit]") {
  test::test_context();
  // The ground is linear in its albedo a: L = L0 + a (L1 - L0), with L0 and L1 the renders of
  // uniform albedo 0 and 1 (the same light, air and camera). The pattern's albedo at the point,
  // sampled here on the CPU, then predicts the pixel.
  const double lat = 30, lon = 60;
  const auto camera = nadir_camera(lat, lon, 1.0e6, 17, 9);  // odd size: the centre pixel is the nadir
  const auto black = render::render_orbit(camera, june_morning, uniform_planet(0.0), clear_cover());
  const auto white = render::render_orbit(camera, june_morning, uniform_planet(1.0), clear_cover());
  const auto patterned = render::render_orbit(camera, june_morning, {equirect(256, pattern), {}}, clear_cover());
  const glm::vec4 l0 = pixel(black, 8, 4), l1 = pixel(white, 8, 4), l = pixel(patterned, 8, 4);
  const glm::dvec3 expected = pattern(lat, lon);
  for (int c = 0; c < 3; ++c) {
    INFO("channel " << c);
    REQUIRE(l1[c] - l0[c] > 1e-3f);  // the sun is up (about 53 deg at 08:00 UTC)
    const double albedo = (l[c] - l0[c]) / (l1[c] - l0[c]);
    // Tolerance: the pattern's slope (0.4 per radian) over the pixel's footprint (1000 km x
    // 2 tan(10 deg) / 17 = 21 km = 0.0033 rad: 0.0013), half-float texels (rel. 1e-3: 0.0009)
    // and the bilinear error of a 256-texel map (0.4 x 0.0245^2 / 8 = 3e-5); 0.01 covers them
    // three times over. A flipped latitude or longitude misses by 0.3 or more.
    CHECK(albedo == Approx(expected[c]).margin(0.01));
  }
}

TEST_CASE("orbit: with the xplanet map, 23 N 12 E is desert and 10 N 30 W is ocean", "[orbit]") {
  test::test_context();
  const io::PlanetTextures textures = io::read_planet_textures("");
  if (textures.day_source == "procedural") {
    test::skip_case("xplanet-images is not installed");
    return;
  }
  // The map's conventions (longitude -180 at the left edge, north up) as the renderer reads them:
  // the Sahara at 23 N 12 E is sand (red above blue even under the blue air light); the Atlantic
  // at 10 N 30 W is ocean (blue above red). A mirrored or shifted map swaps them.
  const auto land = render::render_orbit(nadir_camera(23, 12, 1.0e6, 9, 5), core::parse_utc_time("2026-03-20T11:00Z"),
                                         textures.images, clear_cover());
  const auto ocean = render::render_orbit(nadir_camera(10, -30, 1.0e6, 9, 5), core::parse_utc_time("2026-03-20T14:00Z"),
                                          textures.images, clear_cover());
  const glm::vec4 l = pixel(land, 4, 2), o = pixel(ocean, 4, 2);
  CHECK(l.r > l.b);
  CHECK(o.b > o.r);
  // Made ready for the sea's own colour: alpha is the share not ice (the Arctic's pack ice at
  // 88 N, none in the Sahara), and the map's North Sea (55 N 3 E, painted blue and turquoise) is
  // filled from the land around it, no longer blue above 1.2 red.
  REQUIRE(textures.images.sea_colour);
  const core::ImageData& day = textures.images.day;
  REQUIRE(day.channels == 4);
  auto at = [&](double lat, double lon) {
    const int i = std::clamp(int((lon + 180.0) / 360.0 * day.width), 0, day.width - 1);
    const int j = std::clamp(int((90.0 - lat) / 180.0 * day.height), 0, day.height - 1);
    const float* p = &day.pixels[(std::size_t(j) * day.width + i) * 4];
    return glm::vec4(p[0], p[1], p[2], p[3]);
  };
  CHECK(at(88, 0).a < 0.5f);
  CHECK(at(23, 12).a == 1.0f);
  const glm::vec4 north_sea = at(55, 3);
  CHECK(north_sea.b <= 1.2f * north_sea.r);
}

TEST_CASE("orbit: the night side is dark except for the city lights", "[orbit]") {
  test::test_context();
  // Sun elevation at 30 N 60 E at 20:00 UTC in June: about -40 deg. No direct light (mu < 0),
  // no sky light (the ambient fades out below -7 deg) and no air light (every point of the
  // atmosphere along the view is in the planet's shadow: transmittance_to_space is 0), so a
  // pixel without lights is black up to rounding; a lit texel of value 1 shows night_lights
  // times the air's transmittance (above 0.5 straight down).
  const double night = core::parse_utc_time("2026-06-21T20:00Z");
  render::PlanetImages planet = uniform_planet(0.3);
  planet.night = equirect(360, [](double lat, double lon) {
    return glm::dvec3(std::abs(lat - 30) < 2 && std::abs(lon - 60) < 2 ? 1.0 : 0.0);
  });
  const render::OrbitSettings settings;
  const auto city = render::render_orbit(nadir_camera(30, 60, 2.0e5, 9, 5, 10), night, planet, clear_cover(), settings);
  const auto dark = render::render_orbit(nadir_camera(30, 75, 2.0e5, 9, 5, 10), night, planet, clear_cover(), settings);
  REQUIRE(city.sun_elevation_deg < -20);
  CHECK(luminance(pixel(dark, 4, 2)) < 1e-6);
  CHECK(luminance(pixel(city, 4, 2)) > 0.5 * settings.night_lights);
}

TEST_CASE("orbit: the limb glows blue against black space", "[orbit]") {
  test::test_context();
  // The camera above the subsolar point, 20000 km up, looking at the centre: the ray 10 km
  // above the limb (in the middle row) crosses only air, lit by the sun; a corner ray misses
  // the atmosphere and stays black. Rayleigh scattering (5.8e-6 red, 33.1e-6 blue) makes it blue.
  const glm::dvec3 sun = render::sun_direction_ecef(june_morning);
  const double lat = std::asin(sun.z) / degree, lon = std::atan2(sun.y, sun.x) / degree;
  auto camera = nadir_camera(lat, lon, 2.0e7, 401, 21, 40);
  const double R = render::OrbitSettings{}.planet_radius_m, D = R + camera.altitude_m;
  const double angle = std::asin((R + 10000) / D);
  const int x = static_cast<int>(std::lround(200 + 200.5 * std::tan(angle) / std::tan(20 * degree)));
  const auto r = render::render_orbit(camera, june_morning, uniform_planet(0.1), clear_cover());
  const glm::vec4 limb = pixel(r, x, 10), space = pixel(r, 0, 0);
  CHECK(luminance(space) == 0.0);
  CHECK(luminance(limb) > 1e-4);
  CHECK(limb.b > limb.r);
  CHECK(limb.a == 0.0f);  // no cloud
}

TEST_CASE("orbit: a cloud patch of the cover appears at its pixel and nowhere else", "[orbit]") {
  test::test_context();
  const double lat = 20, lon = -40, radius_deg = 4;
  const auto cover = patch_cover(48, lat, lon, radius_deg);
  // Camera off to the north-east, looking at the centre: the patch is off the image centre.
  auto camera = nadir_camera(lat + 8, lon + 10, 3.0e6, 64, 48, 60);
  const auto r = render::render_orbit(camera, june_morning + 4 * 3600, uniform_planet(0.1), cover);
  const double R = render::OrbitSettings{}.planet_radius_m;
  const glm::dvec2 at = render::project_to_pixel(camera, R, (R + 4000) * unit_of(lat, lon));
  const glm::dvec2 mirrored = render::project_to_pixel(camera, R, R * unit_of(lat, -lon + 2 * (lon + 10)));
  INFO("patch at pixel " << at.x << ", " << at.y);
  REQUIRE(at.x > 4);
  REQUIRE(at.x < 60);
  REQUIRE(at.y > 4);
  REQUIRE(at.y < 44);
  // Optical depth through the patch's middle: 0.02 /m x about 6 km x density > 0.5 = 60 and more.
  CHECK(pixel(r, int(at.x), int(at.y)).a > 0.99f);
  double alpha_elsewhere = 0;
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 64; ++x)
      if (std::hypot(x + 0.5 - at.x, y + 0.5 - at.y) > 20)
        alpha_elsewhere = std::max<double>(alpha_elsewhere, pixel(r, x, y).a);
  // 20 px at 3000 km with a 60 deg view is about 1200 km on the ground: well outside the 440 km patch.
  CHECK(alpha_elsewhere == 0.0);
  if (mirrored.x >= 0 && mirrored.x < 64 && mirrored.y >= 0 && mirrored.y < 48)
    CHECK(pixel(r, int(mirrored.x), int(mirrored.y)).a == 0.0f);
  // A renderer made with a clear cover shows the patch once it is given the patch's cover.
  render::OrbitRenderer renderer(uniform_planet(0.1), clear_cover());
  CHECK(pixel(renderer.render(camera, june_morning + 4 * 3600), int(at.x), int(at.y)).a == 0.0f);
  renderer.set_cover(cover);
  CHECK(pixel(renderer.render(camera, june_morning + 4 * 3600), int(at.x), int(at.y)).a > 0.99f);
}

TEST_CASE("orbit: with the sun overhead the ground below the cloud patch is darker than beside it", "[orbit]") {
  test::test_context();
  // The patch at the subsolar point; the camera 200 m up (below the lowest base, 300 m) looks
  // straight down, once under the patch and once 8 deg away. The patch's cover 1 is thick cloud
  // (tau 163 by the fallback) whose slab reaches from 0.5 to 8 km. Under it the sunlight is cut
  // to exp(-tau) + (1 - exp(-tau)) / (1 + 0.1125 tau) = 0.05; the sky light (about a fifth of the
  // total) is not, so the ground keeps about 0.25 of its brightness: below 0.5.
  const glm::dvec3 sun = render::sun_direction_ecef(june_morning);
  const double lat = std::asin(sun.z) / degree, lon = std::atan2(sun.y, sun.x) / degree;
  const auto cover = patch_cover(48, lat, lon, 4);
  const auto planet = uniform_planet(0.2);
  const auto under = render::render_orbit(nadir_camera(lat, lon, 200, 9, 5), june_morning, planet, cover);
  const auto beside = render::render_orbit(nadir_camera(lat, lon + 8, 200, 9, 5), june_morning, planet, cover);
  const glm::vec4 u = pixel(under, 4, 2), b = pixel(beside, 4, 2);
  CHECK(u.a == 0.0f);  // looking down from below the base: no cloud in the way
  CHECK(luminance(u) < 0.5 * luminance(b));
  CHECK(luminance(u) > 0.0);
}

TEST_CASE("orbit: thin cloud lets the ground through by its optical thickness, and thick cloud hides it",
          "[orbit][thickness]") {
  test::test_context();
  // A cover of 0.15 everywhere with tau 0.15 (ISCCP's thinnest cirrus) and tops at 3 km, seen
  // straight down from 2000 km: a nadir ray crosses the whole slab, whose optical depth is that
  // of the texel's mean transmittance, -ln(1 - 0.15 (1 - exp(-0.15))) = 0.0211, so the cloud's
  // opacity (alpha) is 1 - exp(-0.0211) = 0.0209. The slab integral is exact per segment; the
  // half floats of the cover's texture round tau and the cover by 2^-11 relative: 0.3 % of alpha,
  // and the B-spline of equal texels is exact.
  const int size = 16;
  const render::CoverCube thin = uniform_cover(size, 0.15f, 0.15f, 3.0f);
  // Without the sub-texel cloud (which draws where in the texel the cloud is; below) a pixel has
  // the texel's mean.
  const auto camera = nadir_camera(10, 60, 2.0e6, 9, 5, 2);
  const auto planet = uniform_planet(0.05);
  render::OrbitSettings smooth;
  smooth.cloud_detail = 0;
  const glm::vec4 seen = pixel(render::render_orbit(camera, june_morning, planet, thin, smooth), 4, 2);
  const double tau = -std::log(1 - 0.15 * (1 - std::exp(-0.15)));
  CHECK(seen.a == Approx(1 - std::exp(-tau)).epsilon(0.01));
  // The ground shows through: the pixel keeps at least the clear pixel's light times the view's
  // transmittance exp(-tau) and the sunlight's through the slab, exp(-tau / mu) (the light the
  // cloud scatters and the air before it only add).
  const glm::vec4 clear = pixel(render::render_orbit(camera, june_morning, planet, clear_cover(size), smooth), 4, 2);
  const double mu = glm::dot(unit_of(10, 60), render::sun_direction_ecef(june_morning));
  REQUIRE(mu > 0.2);
  const double through = std::exp(-tau) * std::exp(-tau / mu);
  for (int c = 0; c < 3; ++c) CHECK(seen[c] >= through * clear[c] * (1 - 1e-3));
  // The same cover with tau 30 (thick): opaque.
  const render::CoverCube thick = uniform_cover(size, 1.0f, 30.0f, 3.0f);
  CHECK(pixel(render::render_orbit(camera, june_morning, planet, thick, smooth), 4, 2).a > 0.99f);
}

TEST_CASE("orbit: a deck seen straight down reflects the delta-Eddington share of the sunlight, thin decks dim",
          "[orbit][thickness]") {
  test::test_context();
  // Decks of tau 1, 4 and 32 with tops at 3 km over a black planet, straight down from 2000 km:
  // the pixel's light is the sunlight at the tops, E T_sun, reflected by R(tau, mu0) over the
  // directions as R mu0 / pi (slab_scattering.glsl: the slab's source is solved for that nadir
  // radiance, its single scattering included), seen through the air above the tops, T_view,
  // plus what the sky's light (atmosphere.glsl's sky_ambient) adds by the share the deck
  // reflects, 1 - slab_diffuse_transmittance(tau), plus the air's own light, at most
  // the clear view's over the black ground. The march's segments hold the source piecewise
  // constant: a few per cent of the sun's term (10 % allowed). Before, a deck reflected as if its
  // reflectance were above 1 whatever its tau: the "paper-white" clouds of issue 31.
  const int size = 16;
  const auto planet = uniform_planet(0.0);
  render::OrbitSettings smooth;
  smooth.cloud_detail = 0;
  const glm::dvec3 sun = render::sun_direction_ecef(june_morning);
  for (const double latitude : {20.0, -20.0}) {
    const auto camera = nadir_camera(latitude, 60, 2.0e6, 9, 5, 2);
    const glm::dvec3 up = unit_of(latitude, 60);
    const double mu0 = glm::dot(up, sun);
    REQUIRE(mu0 > 0.7);
    const glsl::vec3 top(glm::vec3(up * (6371000.0 + 3000.0)));
    const glsl::vec3 e = glsl::solar_irradiance();
    const glsl::vec3 t_sun = glsl::transmittance_to_space(top, glsl::vec3(glm::vec3(sun)), 6371000.0f);
    const glsl::vec3 t_view = glsl::transmittance_to_space(top, glsl::vec3(glm::vec3(up)), 6371000.0f);
    const double air =
        luminance(pixel(render::render_orbit(camera, june_morning, planet, clear_cover(size), smooth), 4, 2));
    double previous = 0;
    for (const double tau : {1.0, 4.0, 32.0}) {
      const glm::vec4 seen =
          pixel(render::render_orbit(camera, june_morning, planet, uniform_cover(size, 1.0f, float(tau), 3.0f), smooth),
                4, 2);
      const double reflectance = glsl::slab_reflectance(float(tau), float(mu0));
      const glm::dvec3 sun_term =
          glm::dvec3(e.x * t_sun.x * t_view.x, e.y * t_sun.y * t_view.y, e.z * t_sun.z * t_view.z) *
          (reflectance * mu0 / M_PI);
      const glsl::vec3 sky = glsl::sky_ambient(glsl::vec3(glm::vec3(up)), glsl::vec3(glm::vec3(sun)));
      const glm::dvec3 sky_term = glm::dvec3(sky.x * t_view.x, sky.y * t_view.y, sky.z * t_view.z) *
                                  (1.0 - glsl::slab_diffuse_transmittance(float(tau)));
      const double low = 0.9 * luminance(glm::vec4(glm::vec3(sun_term), 0));
      const double high =
          1.1 * luminance(glm::vec4(glm::vec3(sun_term), 0)) + luminance(glm::vec4(glm::vec3(sky_term), 0)) + air;
      INFO("air " << air << ", latitude " << latitude << ", mu0 " << mu0 << ", tau " << tau << ": R " << reflectance
                  << ", luminance " << luminance(seen) << " in [" << low << ", " << high << "]");
      CHECK(luminance(seen) >= low);
      CHECK(luminance(seen) <= high);
      CHECK(luminance(seen) > previous);  // thicker is brighter
      previous = luminance(seen);
    }
  }
}

TEST_CASE("orbit: the sub-texel cloud draws clear and cloudy places and keeps the cover's opacity on average",
          "[orbit][thickness]") {
  test::test_context();
  // A cover of 0.15 everywhere, tau 30 (opaque where cloudy): with the sub-texel cloud a nadir
  // pixel's opacity is c' (1 - exp(-30)), c' its footprint's cloudy share, whose expectation is
  // the cover's 0.15 (tests/test_cloud_properties.cpp). 160 x 90 pixels of 7 km from 1000 km under
  // 39 km texels (the field's first wavelength): the image holds some 500 independent cells of
  // that size, so its mean opacity is within 4 standard errors (the pixels' deviation over the
  // root of that count) of 0.15; and it is no haze: clear and cloudy pixels both.
  const int size = 256;
  const render::CoverCube sparse = uniform_cover(size, 0.15f, 30.0f, 3.0f);
  const auto camera = nadir_camera(10, 60, 1.0e6, 160, 90, 60);
  const auto r = render::render_orbit(camera, june_morning, uniform_planet(0.05), sparse);
  double sum = 0, squares = 0, low = 1, high = 0;
  for (int y = 0; y < 90; ++y)
    for (int x = 0; x < 160; ++x) {
      const double a = pixel(r, x, y).a;
      sum += a;
      squares += a * a;
      low = std::min(low, a);
      high = std::max(high, a);
    }
  const double n = 160 * 90, mean = sum / n, deviation = std::sqrt(squares / n - mean * mean);
  const double width_m = 2 * 1.0e6 * std::tan(30 * degree), cells = width_m * width_m * 90 / 160 / (39000.0 * 39000.0);
  INFO("mean opacity " << mean << ", deviation " << deviation << ", " << cells << " cells, range " << low << ".."
                       << high);
  CHECK(std::abs(mean - 0.15) < 4 * deviation / std::sqrt(cells));
  CHECK(low < 0.02);
  CHECK(high > 0.9);
}

TEST_CASE("orbit: a veil of thin high cloud stays whole below its texels while the same cloud low down breaks up",
          "[orbit][thickness]") {
  test::test_context();
  // A cover of 0.5 everywhere with tau 2, as cirrus with tops at 9 km and as cumulus with tops at
  // 2 km, straight down from 1000 km (pixels of 7 km under 39 km texels, as the test above). The
  // cumulus is carved into clouds and clear sky: pixels near 0 and near its opaque cloud's
  // 1 - exp(-2) = 0.86. The cirrus is a veil (cloud_properties.glsl's subtexel_carving): every pixel
  // keeps about the texel's opacity 0.5 (1 - exp(-2)) = 0.43, moved only by the tops' relief and
  // the thickness's variation, no clear pixel and none as opaque as a cloud.
  const int size = 256;
  const auto camera = nadir_camera(10, 60, 1.0e6, 160, 90, 60);
  const auto planet = uniform_planet(0.05);
  const auto opacities = [&](float top_km) {
    const auto r = render::render_orbit(camera, june_morning, planet, uniform_cover(size, 0.5f, 2.0f, top_km));
    std::vector<double> a;
    for (int y = 0; y < 90; ++y)
      for (int x = 0; x < 160; ++x) a.push_back(pixel(r, x, y).a);
    std::sort(a.begin(), a.end());
    return a;
  };
  const std::vector<double> veil = opacities(9.0f), cumulus = opacities(2.0f);
  const double mean_opacity = 0.5 * (1 - std::exp(-2.0));
  INFO("veil opacity " << veil.front() << ".." << veil.back() << " (median " << veil[veil.size() / 2] << "); cumulus "
                       << cumulus.front() << ".." << cumulus.back());
  CHECK(cumulus.front() < 0.05);
  CHECK(cumulus.back() > 0.8);
  CHECK(veil.front() > 0.5 * mean_opacity);
  CHECK(veil.back() < 0.8);
  CHECK(veil[veil.size() / 2] == Approx(mean_opacity).epsilon(0.2));
}

TEST_CASE("orbit: under a low sun the cloud tops' relief shows as texture, under a high sun hardly",
          "[orbit][relief]") {
  test::test_context();
  // An overcast of tau 20 with its tops at 8 km (a 3.3 km deep slab, so the sub-texel field's
  // relief moves its tops by some 0.15 x 3.3 km = 500 m per deviation) seen straight down from
  // 400 km over 35 km. Shading by slopes s goes as s tan(zenith angle) of the sun: at 85 degrees
  // (elevation 5) 11.4 s, at 30 degrees 0.58 s, twenty times less; the light that diffuses through
  // the cloud evens both out alike. So the luminance's relative deviation under the low sun is at
  // least twice that under the high sun (a margin of ten on the slopes' factor). Without the
  // sub-texel cloud the flat overcast has the march's noise only (the per-pixel jitter of the
  // segments, whose light paths are longest under a low sun): a fifth of the relief's texture at most.
  const int size = 64;
  const render::CoverCube overcast = uniform_cover(size, 1.0f, 20.0f, 8.0f);
  const glm::dvec3 sun = render::sun_direction_ecef(june_morning);
  const glm::dvec3 east = glm::normalize(glm::cross(glm::dvec3(0, 0, 1), sun));
  auto point_at = [&](double zenith_deg) {
    const glm::dvec3 u = std::cos(zenith_deg * degree) * sun + std::sin(zenith_deg * degree) * glm::cross(sun, east);
    return std::pair{std::asin(u.z) / degree, std::atan2(u.y, u.x) / degree};
  };
  auto relative_deviation = [&](double zenith_deg, double detail) {
    const auto [lat, lon] = point_at(zenith_deg);
    render::OrbitSettings settings;
    settings.cloud_detail = detail;
    settings.cloud_tau_spread = 0;  // the relief alone (the optical thickness's texture: the next case)
    const auto r = render::render_orbit(nadir_camera(lat, lon, 4.0e5, 64, 64, 5), june_morning, uniform_planet(0.1),
                                        overcast, settings);
    double sum = 0, squares = 0;
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 64; ++x) {
        const double l = luminance(pixel(r, x, y));
        sum += l;
        squares += l * l;
      }
    const double mean = sum / 4096;
    return std::sqrt(std::max(squares / 4096 - mean * mean, 0.0)) / mean;
  };
  const double low = relative_deviation(85, 1), high = relative_deviation(30, 1);
  const double low_smooth = relative_deviation(85, 0), high_smooth = relative_deviation(30, 0);
  INFO("relative deviation: low sun " << low << ", high sun " << high << "; without the detail " << low_smooth << ", "
                                      << high_smooth);
  CHECK(low > 2 * high);
  CHECK(low > 0.02);
  CHECK(low_smooth < 0.2 * low);
  CHECK(high_smooth < 0.01);
}

TEST_CASE("orbit: an overcast varies in brightness inside as clouds seen from orbit do, few 8.8 km windows uniform",
          "[orbit][relief]") {
  test::test_context();
  // Genkova and Davies (2003, GRL 30, 2096) found that only 1.4 % of 8.8 km cloudy regions seen by
  // MISR at 275 m have all their reflectivities within 5 % of the central value (2.3 % at 1100 m).
  // An overcast of tau 12 with its tops at 2 km (a deck) seen straight down from 400 km under a sun
  // 30 degrees from the zenith, 128 x 128 pixels of 0.55 km: 64 windows of 16 x 16 pixels (8.8
  // km). With the optical thickness's spread inside the texel's cloud (ln tau's deviation 0.84)
  // the reflectance of a window's thinner and thicker parts differs by far more than 5 %; without
  // it (spread 0, the cloud as uniform as the cover's texel) and under a high sun the deck is
  // mostly uniform but for the march's noise and the tops' faint relief. The cover has 512 texels a face
  // (20 km), as the default cover: the spread is the cloud's inside a texel, and a window holds the
  // field's octaves of 10 km and less, 0.4 of its variance.
  const render::CoverCube deck = uniform_cover(512, 1.0f, 12.0f, 2.0f);
  const glm::dvec3 sun = render::sun_direction_ecef(june_morning);
  const glm::dvec3 east = glm::normalize(glm::cross(glm::dvec3(0, 0, 1), sun));
  const glm::dvec3 u = std::cos(30 * degree) * sun + std::sin(30 * degree) * glm::cross(sun, east);
  const double lat = std::asin(u.z) / degree, lon = std::atan2(u.y, u.x) / degree;
  double mean_luminance = 0;
  auto uniform_windows = [&](double spread) {
    render::OrbitSettings settings;
    settings.cloud_tau_spread = spread;
    const int n = 128;
    const auto r = render::render_orbit(nadir_camera(lat, lon, 4.0e5, n, n, 2 * std::atan(35.2 / 400.0) / degree),
                                        june_morning, uniform_planet(0.1), deck, settings);
    int uniform = 0, windows = 0;
    mean_luminance = 0;
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) mean_luminance += luminance(pixel(r, x, y)) / (n * n);
    for (int wy = 0; wy < n; wy += 16)
      for (int wx = 0; wx < n; wx += 16) {
        const double centre = luminance(pixel(r, wx + 8, wy + 8));
        double low = centre, high = centre;
        for (int y = wy; y < wy + 16; ++y)
          for (int x = wx; x < wx + 16; ++x) {
            low = std::min(low, luminance(pixel(r, x, y)));
            high = std::max(high, luminance(pixel(r, x, y)));
          }
        ++windows;
        if (low >= 0.95 * centre && high <= 1.05 * centre) ++uniform;
      }
    return double(uniform) / windows;
  };
  const double textured = uniform_windows(0.84), textured_mean = mean_luminance;
  const double flat = uniform_windows(0.0), flat_mean = mean_luminance;
  INFO("uniform 8.8 km windows: " << textured << " with the spread, " << flat << " without");
  CHECK(textured <= 0.1);
  CHECK(flat >= 0.5);  // most: the tops' relief (77 m a deviation) shades little under a high sun
  // The texel's tau is its cloud's geometric mean, the effective thickness of Cahalan et al.: the
  // delta-Eddington reflectance averaged over the log-normal of deviation 0.84 about tau 12 (sun 30
  // degrees from the zenith) is 0.99 of the uniform deck's (1.14 about tau 4, 0.96 about tau 30), so
  // the deck seen close up is about as bright on average as the uniform one. The renderer's light
  // is not the slab's reflectance alone (its single scattering and the light diffusing through go
  // otherwise with tau), so the bound is the effective thickness's own error on thinner cloud,
  // 0.14 at tau 4, rounded down to a tenth.
  CHECK(textured_mean == Approx(flat_mean).epsilon(0.1));
}

TEST_CASE("orbit: towards the horizon the sub-texel cloud is filtered by its footprint's long axis, no speckle",
          "[orbit][relief]") {
  test::test_context();
  // Half cover everywhere (tau 10, tops at 2 km) from 400 km, looking 25 degrees down with a
  // 70-degree field as the README's view: towards the horizon the rays meet the clouds at grazing
  // incidence and a pixel's footprint on them is many times longer along the surface than across
  // the ray. The sub-texel cloud is band-limited by the footprint; taken as the short axis, the
  // octaves between the two alias into speckle, independent from pixel to pixel. Measure: the
  // luminance's variance between neighbouring pixels against that between means of 4 x 4 blocks
  // (a band), over the far part of the cloud. A field band-limited to the pixels varies less
  // between neighbours than between blocks four pixels apart (ratio below 1); speckle independent
  // from pixel to pixel has 16 times the block means' variance between neighbours. Measured here:
  // 1.12 with the footprint across the ray, 0.17 with the long axis (the README's 400 km view:
  // 9.5 and 0.66).
  const render::CoverCube half = uniform_cover(128, 0.5f, 10.0f, 2.0f);
  render::OrbitCamera camera;
  camera.latitude_deg = 20.0;
  camera.longitude_deg = -30.0;
  camera.altitude_m = 4.0e5;
  camera.heading_deg = 0.0;
  camera.pitch_deg = -25.0;
  camera.fov_deg = 70.0;
  camera.width = 256;
  camera.height = 144;
  const double noon = core::parse_utc_time("2026-06-21T14:00Z");
  const auto r = render::render_orbit(camera, noon, uniform_planet(0.1), half);
  // The far band: rows whose central ray meets the cloud tops at an incidence below 0.3 (the
  // footprint more than 3 times longer along the surface), found from the camera's geometry.
  const render::OrbitFrame frame = render::orbit_frame(camera, 6371000.0);
  const double tan_half = std::tan(camera.fov_deg * degree / 2), top = 6371000.0 + 2000.0;
  std::vector<int> rows;
  for (int y = 0; y < camera.height; ++y) {
    const double v = (1.0 - 2.0 * (y + 0.5) / camera.height) * tan_half * camera.height / camera.width;
    const glm::dvec3 d = glm::normalize(frame.forward + v * frame.up);
    const double b = glm::dot(frame.position, d), c = glm::dot(frame.position, frame.position) - top * top;
    if (b * b - c <= 0) continue;
    const glm::dvec3 hit = frame.position + (-b - std::sqrt(b * b - c)) * d;
    if (std::abs(glm::dot(d, glm::normalize(hit))) < 0.3) rows.push_back(y);
  }
  REQUIRE(rows.size() >= 16);
  const int first = rows.front(), bands = int(rows.size()) / 4;
  std::vector<std::vector<double>> l(size_t(4 * bands), std::vector<double>(size_t(camera.width)));
  for (int y = 0; y < 4 * bands; ++y)
    for (int x = 0; x < camera.width; ++x) l[size_t(y)][size_t(x)] = luminance(pixel(r, x, first + y));
  auto variance_of_steps = [](const std::vector<double>& steps) {
    double mean = 0, square = 0;
    for (double s : steps) mean += s / steps.size();
    for (double s : steps) square += (s - mean) * (s - mean) / steps.size();
    return square / 2;
  };
  std::vector<double> fine, coarse;
  for (int y = 0; y < 4 * bands; ++y)
    for (int x = 1; x < camera.width; ++x) fine.push_back(l[size_t(y)][size_t(x)] - l[size_t(y)][size_t(x - 1)]);
  for (int by = 0; by < bands; ++by) {
    std::vector<double> blocks;
    for (int bx = 0; bx < camera.width / 4; ++bx) {
      double m = 0;
      for (int y = 4 * by; y < 4 * by + 4; ++y)
        for (int x = 4 * bx; x < 4 * bx + 4; ++x) m += l[size_t(y)][size_t(x)] / 16;
      blocks.push_back(m);
    }
    for (size_t k = 1; k < blocks.size(); ++k) coarse.push_back(blocks[k] - blocks[k - 1]);
  }
  const double ratio = variance_of_steps(fine) / variance_of_steps(coarse);
  INFO("rows " << first << " to " << first + 4 * bands << ": neighbours' variance over the blocks' " << ratio);
  CHECK(ratio < 1.0);
}

TEST_CASE("orbit: a descent from 2000 km to 1 km changes luminance and cloud fraction smoothly", "[orbit][descent]") {
  test::test_context();
  // 60 frames at geometrically spaced altitudes (the ratio between frames is constant, as a
  // viewer's speed proportional to altitude gives), straight down over a point of the default
  // cover. No frame-to-frame step may exceed three times the median step (issue 11); steps below
  // the floor (0.2 % of the mean luminance, 0.002 of cloud fraction: the jittered march's noise
  // on 5184 pixels) count as smooth.
  cover::CoverParameters parameters;
  parameters.size = 32;
  // The descent's point and the floors were chosen on the one-threshold cover; this test judges
  // the renderer along the descent, not the latitude profile (test_latitude_profile.cpp).
  parameters.profile = cover::flat_profile();
  // Likewise the zonal winds of sfsim: with three cells the clearest point's last cloud leaves
  // the 96 x 54 view near 120 km in one frame (11 pixels, 0.0021 of the frame, just
  // over the floor), a change of content and not of the renderer.
  parameters.zonal_cells = 0;
  cover::GlobalCover generated(parameters);
  generated.run();
  const render::CoverCube cover{parameters.size, generated.cover_field().read()};
  // The descent's point: the texel centre farthest from every cloudy texel (the camera passes the
  // shell through a hole, not through a cloud: flying out of a cloud's base is a real change).
  std::vector<glm::dvec3> directions;
  const int n = parameters.size;
  for (int face = 0; face < 6; ++face)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double sc = 2 * (i + 0.5) / n - 1, tc = 2 * (j + 0.5) / n - 1;
        const glm::dvec3 faces[6] = {{1, -tc, -sc}, {-1, -tc, sc}, {sc, 1, tc},
                                     {sc, -1, -tc}, {sc, -tc, 1},  {-sc, -tc, -1}};
        directions.push_back(glm::normalize(faces[face]));
      }
  glm::dvec3 clearest(1, 0, 0);
  double best = -2;
  for (size_t a = 0; a < directions.size(); ++a) {
    if (cover.texels[a] > 0) continue;
    double nearest = 1;  // cosine of the angle to the nearest cloudy texel
    for (size_t b = 0; b < directions.size(); ++b)
      if (cover.texels[b] > 0)
        nearest = std::max(nearest == 1 ? -1.0 : nearest, glm::dot(directions[a], directions[b]));
    if (-nearest > best) best = -nearest, clearest = directions[a];
  }
  const double descent_lat = std::asin(clearest.z) / degree, descent_lon = std::atan2(clearest.y, clearest.x) / degree;
  render::OrbitSettings settings;
  settings.cloud_steps = 24;
  render::OrbitRenderer renderer(uniform_planet(0.15), cover, settings);
  const int frames = 60;
  // Daylight at the point: the time when the sun stands over its meridian.
  const double noon = core::parse_utc_time("2026-06-21T12:00Z") - descent_lon / 15.0 * 3600.0;
  std::vector<double> mean_luminance, cloud_fraction;
  for (int k = 0; k < frames; ++k) {
    const double altitude = 2.0e6 * std::pow(1000.0 / 2.0e6, k / double(frames - 1));
    render::OrbitCamera camera = nadir_camera(descent_lat, descent_lon, altitude, 96, 54, 60);
    camera.pitch_deg = -30;
    const auto r = renderer.render(camera, noon);
    double y = 0, a = 0;
    for (int py = 0; py < 54; ++py)
      for (int px = 0; px < 96; ++px) {
        const glm::vec4 c = pixel(r, px, py);
        y += luminance(c);
        a += c.a;
      }
    mean_luminance.push_back(y / (96 * 54));
    cloud_fraction.push_back(a / (96 * 54));
  }
  double mean = 0;
  for (double y : mean_luminance) mean += y / frames;
  CHECK(largest_jumps(mean_luminance, 0.002 * mean).empty());
  INFO("descent at " << descent_lat << ", " << descent_lon << "; cloud fraction by frame: " << [&] {
    std::string text;
    for (double a : cloud_fraction) text += std::to_string(a) + " ";
    return text;
  }());
  CHECK(largest_jumps(cloud_fraction, 0.002).empty());
  // The check sees a switch: 5 % of the mean luminance added from the middle frame on (a layer
  // that pops in) is flagged at that frame and nowhere else.
  std::vector<double> switched = mean_luminance;
  for (int k = frames / 2; k < frames; ++k) switched[k] += 0.05 * mean;
  CHECK(largest_jumps(switched, 0.002 * mean) == std::vector<size_t>{size_t(frames / 2 - 1)});
}

TEST_CASE("orbit: 1 m and 40000 km are both exact: the horizon's dip and the disc's size", "[orbit][precision]") {
  test::test_context();
  // At night with uniform city lights every ground pixel shines and every sky pixel is black
  // (the air is in the planet's shadow), so the ground's edge is where the geometry puts it. The
  // air keeps a trace of multiple scattering from the twilight far away (the sun is 37 degrees
  // below the horizon): its pixels are below 1e-16, the lights' 0.08.
  const double dark = 1e-5;
  const double night = core::parse_utc_time("2026-06-21T20:00Z");
  render::PlanetImages planet = uniform_planet(0.2);
  planet.night = equirect(16, [](double, double) { return glm::dvec3(1.0); });
  const double R = render::OrbitSettings{}.planet_radius_m;
  SECTION("1 m: the horizon lies acos(R / (R + 1 m)) = 0.0321 deg below the horizontal") {
    render::OrbitCamera camera = nadir_camera(30, 60, 1.0, 9, 101, 0.1);
    camera.pitch_deg = 0;
    const auto r = render::render_orbit(camera, night, planet, clear_cover());
    const double dip = std::acos(R / (R + 1.0));
    const double tan_half = std::tan(0.05 * degree), aspect = 101.0 / 9.0;
    int checked = 0;
    for (int row = 0; row < 101; ++row) {
      const double elevation = std::atan((1 - (row + 0.5) / 101 * 2) * aspect * tan_half);
      // Rows within a fifth of a pixel (0.0022 deg) of the edge are not judged.
      if (std::abs(elevation + dip) < 0.2 * 2 * aspect * tan_half / 101) continue;
      INFO("row " << row << " elevation " << elevation / degree << " deg");
      CHECK((luminance(pixel(r, 4, row)) > dark) == (elevation < -dip));
      ++checked;
    }
    CHECK(checked > 95);
  }
  SECTION("40000 km: the lit disc spans 2 asin(R / D) up to the air's 100 km") {
    const auto camera = nadir_camera(30, 60, 4.0e7, 401, 3, 20);
    const auto r = render::render_orbit(camera, night, planet, clear_cover());
    const double D = R + camera.altitude_m, tan_half = std::tan(10 * degree);
    auto half_width_px = [&](double radius) { return std::tan(std::asin(radius / D)) / tan_half * 200.5; };
    int lit = 0;
    for (int x = 0; x < 401; ++x) lit += luminance(pixel(r, x, 1)) > dark ? 1 : 0;
    CHECK(lit >= 2 * half_width_px(R) - 2);
    CHECK(lit <= 2 * half_width_px(R + 100000) + 2);
  }
}

TEST_CASE("render --view orbit writes the image and refuses bad values naming the option", "[orbit][cli]") {
  test::TemporaryDirectory out(true);
  const std::string file = (out.path / "orbit.png").string();
  const auto ok =
      test::run("render --view orbit --lat 10 --lon 20 --altitude-km 5000 --size 32x18 --quiet --out " + file);
  INFO(ok.output);
  CHECK(ok.exit_code == 0);
  CHECK(std::filesystem::exists(file));
  CHECK(std::filesystem::exists(out.path / "orbit.json"));
  // Without --exposure the frame is metered: an exposure within a factor 4 of the usual 2.5; with
  // it, the one given.
  const json::Value metered = json::parse(test::read_file(out.path / "orbit.json"));
  CHECK(metered.at("metering").as_string() == "highlights");
  CHECK(metered.at("exposure").as_number() >= 0.625);
  CHECK(metered.at("exposure").as_number() <= 10.0);
  REQUIRE(
      test::run("render --view orbit --lat 10 --lon 20 --altitude-km 5000 --size 32x18 --exposure 3 --quiet --out " +
                file)
          .exit_code == 0);
  const json::Value given = json::parse(test::read_file(out.path / "orbit.json"));
  CHECK(given.at("metering").as_string() == "given");
  CHECK(given.at("exposure").as_number() == 3.0);
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"--altitude-km 0", "--altitude-km"},
      {"--altitude-km 50000", "--altitude-km"},
      {"--lat 91", "--lat"},
      {"--lon -181", "--lon"},
      {"--cloud-base-km 50 --cloud-thickness-km 60", "--cloud-base-km"},
      {"--cloud-detail 1.5", "--cloud-detail"},
      {"--earth-texture /nonexistent/earth.jpg", "--earth-texture"},
      {"--cover /nonexistent/cover", "--cover"},
      {"--at 46,7,800", "--at"},
      {"--time 2026-13-01T00:00Z", "--time"},
      {"--size 0x10", "--size"},
  };
  for (const auto& [arguments, option] : bad) {
    const auto r = test::run("render --view orbit " + arguments + " --size 16x8 --quiet --out " + file);
    INFO(arguments << ": " << r.output);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Catch::Contains(option));
  }
  const auto ground = test::run("render --lat 10 --quiet --out " + file);
  INFO(ground.output);
  CHECK(ground.exit_code == 2);
  CHECK_THAT(ground.output, Catch::Contains("--view orbit"));
}

TEST_CASE("orbit: the procedural stand-in has ocean and land, and any equirect map and radius render", "[orbit][cli]") {
  const render::PlanetImages planet = render::procedural_planet(128, 64);
  REQUIRE(planet.day.pixels.size() == 128 * 64 * 3);
  int ocean = 0, land = 0;
  for (size_t k = 0; k < planet.day.pixels.size(); k += 3) {
    const float r = planet.day.pixels[k], b = planet.day.pixels[k + 2];
    ocean += b > r ? 1 : 0;
    land += r > b ? 1 : 0;
  }
  CHECK(ocean > 128 * 64 / 10);
  CHECK(land > 128 * 64 / 10);

  // Another planet: a small reddish map that is not 2:1 (warned about) on a 3390 km sphere.
  test::TemporaryDirectory out(true);
  core::ImageData mars{64, 48, 3, {}};
  for (int k = 0; k < 64 * 48; ++k) mars.pixels.insert(mars.pixels.end(), {0.7f, 0.35f, 0.2f});
  const auto map = out.path / "mars.png";
  files::write_image(map, mars, files::png_encoding(8));
  const auto r = test::run("render --view orbit --earth-texture " + map.string() +
                           " --planet-radius-km 3390 --altitude-km 8000 --size 24x12 --quiet --out " +
                           (out.path / "mars_view.exr").string());
  INFO(r.output);
  CHECK(r.exit_code == 0);
  CHECK_THAT(r.output, Catch::Contains("not 2:1"));
  CHECK(std::filesystem::exists(out.path / "mars_view.exr"));
}

TEST_CASE("render --view orbit refuses a map too small or unreadable by its option, writing nothing", "[orbit][cli]") {
  // The maps are decoded on a thread of their own beside the cover; their headers are checked
  // before any of that (io::check_planet_maps), so the command stops with exit 2 at once.
  test::TemporaryDirectory out(true);
  const auto tiny = out.path / "tiny.png";
  files::write_image(tiny, core::ImageData{1, 1, 3, {0.5f, 0.5f, 0.5f}}, files::png_encoding(8));
  const auto broken = out.path / "broken.jpg";
  std::FILE* f = std::fopen(broken.string().c_str(), "w");
  REQUIRE(f != nullptr);
  std::fputs("not a JPEG", f);
  std::fclose(f);
  const std::string image = (out.path / "view.png").string();
  const auto small =
      test::run("render --view orbit --verbose --earth-texture " + tiny.string() + " --size 16x8 --out " + image);
  INFO(small.output);
  CHECK(small.exit_code == 2);
  CHECK_THAT(small.output, Catch::Contains("--earth-texture") && Catch::Contains("too small"));
  const auto unreadable =
      test::run("render --view orbit --verbose --night-texture " + broken.string() + " --size 16x8 --out " + image);
  INFO(unreadable.output);
  CHECK(unreadable.exit_code == 2);
  CHECK_THAT(unreadable.output, Catch::Contains("--night-texture") && Catch::Contains("could not be read"));
  // Neither began the work: --verbose names the renderer once the context is made, and it was not.
  CHECK(small.output.find("renderer:") == std::string::npos);
  CHECK(unreadable.output.find("renderer:") == std::string::npos);
  CHECK_FALSE(std::filesystem::exists(image));
}

TEST_CASE("orbit: over an all-water planet the sun glints where the sea mirrors the sun into the camera",
          "[orbit][glint]") {
  test::test_context();
  // A dark sea everywhere, no cloud; the camera 3000 km up, 12 degrees from the subsolar point.
  const glm::dvec3 sun = render::sun_direction_ecef(june_morning);
  const double sun_lat = std::asin(sun.z) / degree, sun_lon = std::atan2(sun.y, sun.x) / degree;
  render::PlanetImages planet = uniform_planet(0.03);
  planet.water = {1, 1, 1, {1.0f}};
  const int w = 96, h = 64;
  const auto camera = nadir_camera(sun_lat - 12, sun_lon, 3.0e6, w, h, 50);
  const auto r = render::render_orbit(camera, june_morning, planet, clear_cover());
  // The brightest pixel of the disc and the ground point it shows.
  int bx = 0, by = 0;
  double brightest = -1;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (luminance(pixel(r, x, y)) > brightest) brightest = luminance(pixel(r, x, y)), bx = x, by = y;
  const double R = render::OrbitSettings{}.planet_radius_m;
  const render::OrbitFrame frame = render::orbit_frame(camera, R);
  const double tan_half = std::tan(camera.fov_deg * degree / 2);
  const double px = (2.0 * (bx + 0.5) / w - 1) * tan_half, py = (1 - 2.0 * (by + 0.5) / h) * double(h) / w * tan_half;
  const glm::dvec3 d = glm::normalize(frame.forward + px * frame.right + py * frame.up);
  const double b = glm::dot(frame.position, d), q = glm::dot(frame.position, frame.position) - R * R;
  REQUIRE(b * b - q > 0);  // on the disc
  const glm::dvec3 ground = frame.position + (-b - std::sqrt(b * b - q)) * d;
  // There the facets that mirror the sun into the camera (normal along the half vector) tilt by
  // beta from the vertical; the glint's radiance falls as exp(-tan^2 beta / sigma^2) while its
  // other factors change by less than a factor 2 across the frame, so the brightest point has
  // tan^2 beta <= sigma^2 ln 2: beta below sigma.
  const glm::dvec3 up = glm::normalize(ground), view = glm::normalize(frame.position - ground);
  const glm::dvec3 half = glm::normalize(view + sun);
  const double beta = std::acos(std::min(1.0, glm::dot(up, half)));
  const double sigma = std::sqrt(0.003 + 0.00512 * render::OrbitSettings{}.sea_wind_ms);
  INFO("brightest pixel " << bx << ", " << by << ", facet tilt " << beta << " rad, sigma " << sigma);
  CHECK(beta <= sigma);
  // The glint outshines the plain sea away from it (the frame's bottom edge, 20 degrees of arc
  // from the subsolar point), and without water there is none: the brightest pixel is then
  // the plain sea's.
  CHECK(brightest > 2 * luminance(pixel(r, w / 2, h - 2)));
  const auto dry = render::render_orbit(camera, june_morning, uniform_planet(0.03), clear_cover());
  CHECK(luminance(pixel(dry, bx, by)) < 0.5 * brightest);
}

TEST_CASE("orbit: the coast window's water takes the sea's colour and mirrors the sky, the day map's ice and land stay",
          "[orbit][glint]") {
  test::test_context();
  // Grey land of albedo 0.3 everywhere; the coast window 20-40 N, 40-80 E is water in its western
  // half. The ground's radiance is L0 + a (L1 - L0) for albedo a (L0, L1: the renders of albedo 0
  // and 1, the same light and air); the sea's is L0 + (L1 - L0) (body + 0.066 s), where s, the
  // sky's share of the ground's light, lies in [0, 1] (sun_glint.glsl's SEA_BODY_ALBEDO and
  // SEA_SKY_REFLECTANCE). The sun is 20 degrees high at 30 N 50 E (03:00 UTC), so the glint
  // (facets tilted 35 degrees, 5 of Cox and Munk's sigma) adds nothing measurable.
  const double when = core::parse_utc_time("2026-06-21T03:00Z");
  auto sea_planet = [](float not_ice) {
    render::PlanetImages planet = uniform_planet(0.3);
    core::ImageData rgba{planet.day.width, planet.day.height, 4, {}};  // alpha: the share not ice
    for (std::size_t k = 0; k < planet.day.pixels.size(); k += 3)
      rgba.pixels.insert(rgba.pixels.end(),
                         {planet.day.pixels[k], planet.day.pixels[k + 1], planet.day.pixels[k + 2], not_ice});
    planet.day = rgba;
    planet.coast = {64, 32, 1, std::vector<float>(64 * 32, 0.0f)};
    for (int j = 0; j < 32; ++j)
      for (int i = 0; i < 32; ++i) planet.coast.pixels[std::size_t(j) * 64 + i] = 1.0f;
    planet.coast_south_deg = 20, planet.coast_north_deg = 40, planet.coast_west_deg = 40, planet.coast_east_deg = 80;
    planet.sea_colour = true;
    return planet;
  };
  const auto sea_camera = nadir_camera(30, 50, 1.0e6, 9, 5), land_camera = nadir_camera(30, 70, 1.0e6, 9, 5);
  const render::PlanetImages open_sea = sea_planet(1.0f), ice = sea_planet(0.0f);
  for (const auto* camera : {&sea_camera, &land_camera}) {
    const glm::vec4 l0 = pixel(render::render_orbit(*camera, when, uniform_planet(0.0), clear_cover()), 4, 2);
    const glm::vec4 l1 = pixel(render::render_orbit(*camera, when, uniform_planet(1.0), clear_cover()), 4, 2);
    const glm::vec4 sea = pixel(render::render_orbit(*camera, when, open_sea, clear_cover()), 4, 2);
    const glm::vec4 frozen = pixel(render::render_orbit(*camera, when, ice, clear_cover()), 4, 2);
    const glm::dvec3 body(0.0006, 0.0057, 0.022);
    for (int c = 0; c < 3; ++c) {
      INFO("channel " << c << (camera == &sea_camera ? " over the water" : " over the land"));
      REQUIRE(l1[c] - l0[c] > 1e-3f);
      const double a = (sea[c] - l0[c]) / (l1[c] - l0[c]), a_ice = (frozen[c] - l0[c]) / (l1[c] - l0[c]);
      // Tolerance 0.003: half-float texels and the radiance's float sums (about 1e-3 of L1 - L0).
      if (camera == &sea_camera) {
        CHECK(a >= body[c] - 0.003);
        CHECK(a <= body[c] + 0.066 + 0.003);
      } else {
        CHECK(a == Approx(0.3).margin(0.003));
      }
      CHECK(a_ice == Approx(0.3).margin(0.003));  // ice (and land) keep the day map's colour
    }
  }
}

TEST_CASE("orbit: ground sloping towards a low sun is brighter and away from it darker, by the sines of the incidence",
          "[orbit][relief]") {
  test::test_context();
  // Straight down 200 km above a point 60 degrees from the subsolar point (the sun 30 degrees
  // high), over clear grey ground whose slope everywhere faces the sun, is flat, or faces away.
  const glm::dvec3 sun = render::sun_direction_ecef(june_morning);
  const double sun_lat = std::asin(sun.z) / degree, sun_lon = std::atan2(sun.y, sun.x) / degree;
  const double lat = sun_lat - 60, lon = sun_lon;
  const glm::dvec3 up(std::cos(lat * degree) * std::cos(lon * degree), std::cos(lat * degree) * std::sin(lon * degree),
                      std::sin(lat * degree));
  const glm::dvec3 east = glm::normalize(glm::dvec3(-up.y, up.x, 0.0)), north = glm::cross(up, east);
  const double elevation = std::asin(glm::dot(up, sun));
  const glm::dvec2 towards_sun = glm::normalize(glm::dvec2(glm::dot(sun, east), glm::dot(sun, north)));
  const double tan_beta = 0.2, beta = std::atan(tan_beta);
  const auto camera = nadir_camera(lat, lon, 2.0e5, 17, 9);  // odd size: the centre pixel is the nadir
  auto nadir = [&](double rise_towards_sun) {
    render::PlanetImages planet = uniform_planet(0.3);
    const glm::dvec2 slopes = rise_towards_sun * tan_beta * towards_sun;
    planet.relief = {1, 1, 2, {float(slopes.x), float(slopes.y)}};
    return luminance(pixel(render::render_orbit(camera, june_morning, planet, clear_cover()), 8, 4));
  };
  const double facing = nadir(-1.0), flat = nadir(0.0), away = nadir(1.0);
  // The relief changes only the direct sunlight's incidence, sin(e) on flat ground: sin(e + beta)
  // facing the sun, sin(e - beta) facing away. Albedo, sunlight, air and the sky's light are the
  // same in the three renders and cancel in the ratio of the differences. Tolerance: the slopes'
  // half floats (0.2 to 1e-4) move the cosines by 1e-4 against differences of 0.16 and 0.18:
  // 1e-3 of the ratio; 0.01 covers it ten times over. A slope's sign or axis swapped gives a
  // ratio of 1.12 or none.
  const double expected =
      (std::sin(elevation + beta) - std::sin(elevation)) / (std::sin(elevation) - std::sin(elevation - beta));
  INFO("sun " << elevation / degree << " deg high; luminance facing " << facing << ", flat " << flat << ", away "
              << away << "; expected ratio " << expected);
  REQUIRE(std::abs(elevation / degree - 30.0) < 0.5);
  REQUIRE(flat - away > 0.0);
  CHECK((facing - flat) / (flat - away) == Approx(expected).epsilon(0.01));
}

namespace {

// A cover of `size` texels a face whose coverage is a smooth field with cloud-like edges:
// six plane waves of 600 to 1300 km wavelength in fixed oblique directions, summed and pushed
// through a steep ramp. Isotropic on average, so its edges have no preferred direction.
render::CoverCube wave_cover(int size) {
  const glm::dvec3 directions[6] = {{0.3, 0.8, 0.5},  {-0.7, 0.2, 0.7}, {0.6, -0.5, 0.6},
                                    {0.1, 0.6, -0.8}, {0.9, 0.3, -0.3}, {-0.4, -0.8, 0.45}};
  const double wavenumbers[6] = {31, 37, 43, 53, 61, 67};  // radians per Earth radius
  render::CoverCube cover{size, {}};
  cover.texels.reserve(6 * static_cast<size_t>(size) * size);
  for (int face = 0; face < 6; ++face)
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i) {
        const glm::dvec3 d = glm::dvec3(glsl::texel_direction(face, i, j, size));
        double sum = 0;
        for (int k = 0; k < 6; ++k) sum += std::sin(wavenumbers[k] * glm::dot(d, glm::normalize(directions[k])) + k);
        const double x = std::clamp((sum / 2.0 + 0.3) / 0.6, 0.0, 1.0);
        cover.texels.push_back(static_cast<float>(x * x * (3 - 2 * x)));
      }
  return cover;
}

// The share of a frame's strong edges (the tenth of its pixels with the largest luminance
// gradient, Sobel) whose gradient lies within 7.5 degrees of an image axis: 1/6 for edges of
// every direction alike, more where the texel grid of a cube face (aligned with the image at
// the face's centre) shows as straight steps.
double axis_aligned_edge_share(const render::RenderResult& r) {
  const int w = r.radiance.width, h = r.radiance.height;
  const auto lum = [&](int x, int y) { return luminance(pixel(r, x, y)); };
  std::vector<std::pair<double, double>> gradients;  // (magnitude, angle)
  for (int y = 1; y + 1 < h; ++y)
    for (int x = 1; x + 1 < w; ++x) {
      const double gx = lum(x + 1, y - 1) + 2 * lum(x + 1, y) + lum(x + 1, y + 1) - lum(x - 1, y - 1) -
                        2 * lum(x - 1, y) - lum(x - 1, y + 1);
      const double gy = lum(x - 1, y + 1) + 2 * lum(x, y + 1) + lum(x + 1, y + 1) - lum(x - 1, y - 1) -
                        2 * lum(x, y - 1) - lum(x + 1, y - 1);
      gradients.push_back({std::hypot(gx, gy), std::atan2(gy, gx)});
    }
  std::sort(gradients.begin(), gradients.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  const size_t strong = gradients.size() / 10;
  size_t aligned = 0;
  for (size_t k = 0; k < strong; ++k) {
    const double folded = std::fmod(std::abs(gradients[k].second) / degree, 90.0);
    if (std::min(folded, 90.0 - folded) < 7.5) ++aligned;
  }
  return double(aligned) / double(strong);
}

}  // namespace

TEST_CASE("orbit: a 64-texel cover shows no more of its texel grid than a 1024-texel one of the same field",
          "[orbit]") {
  test::test_context();
  // Straight down on the centre of face +X at 2000 km, where a 64 cover's texel (156 km) spans
  // about 12 of the frame's pixels and the face's grid runs along the image axes; the sun near
  // overhead. The 64 cover is the 1024 one's area means, as generate's smaller sizes are.
  // Also at 400 km (the height; the 64 cover's texel spans 60 pixels there, the detail
  // noise is resolved): the B-spline keeps the grid out all the same.
  const render::CoverCube fine = wave_cover(1024);
  const render::CoverCube coarse{64, io::reduced_faces(1024, fine.texels, 64)};
  const double equinox_noon = core::parse_utc_time("2026-03-20T12:00Z");
  const auto planet = uniform_planet(0.06);
  for (double altitude : {2.0e6, 4.0e5}) {
    const auto camera = nadir_camera(0, 0, altitude, 192, 108, 60);
    const double share_fine = axis_aligned_edge_share(render::render_orbit(camera, equinox_noon, planet, fine));
    const double share_coarse = axis_aligned_edge_share(render::render_orbit(camera, equinox_noon, planet, coarse));
    INFO(altitude / 1000 << " km: axis-aligned share of strong edges: 1024 cover " << share_fine << ", 64 cover "
                         << share_coarse);
    // Within 5 points of the fine render's share or of edges of every direction alike (1/6,
    // whichever is larger): the grid of a bilinear lookup puts a third of the strong edges on the
    // axes. The 64 cover's sub-texel cloud (its texels span 12 pixels at 2000 km) has fractal
    // edges of every direction, whose brightness varies with their optical thickness (0.16 of
    // them on the axes), where the 1024 cover's smooth oblique waves put fewer there (0.10).
    CHECK(share_coarse <= std::max(share_fine, 1.0 / 6.0) + 0.05);
  }
}

namespace {

// Whether the ray of pixel (i, j) meets the sphere of `radius` about the planet's centre, in
// double, with the shader's ray (orbit_tiles.hpp's TileView).
bool pixel_meets_sphere(const render::TileView& v, int i, int j, double radius) {
  const double x = (2.0 * (i + 0.5) / v.width - 1.0) * v.tan_half_fov;
  const double y = (1.0 - 2.0 * (j + 0.5) / v.height) * (double(v.height) / v.width) * v.tan_half_fov;
  const glm::dvec3 d = glm::normalize(v.forward + x * v.right + y * v.up);
  const double b = glm::dot(v.position, d), q = glm::dot(v.position, v.position) - radius * radius;
  return b * b - q >= 0 && (q < 0 || b < 0);  // a root ahead of the camera
}

render::TileView tile_view(const render::OrbitCamera& camera) {
  const double R = render::OrbitSettings{}.planet_radius_m;
  const render::OrbitFrame f = render::orbit_frame(camera, R);
  return {f.position, f.forward, f.right, f.up, std::tan(camera.fov_deg * degree / 2), camera.width, camera.height};
}

}  // namespace

TEST_CASE("orbit tiles: every pixel whose ray meets the air lies in a listed tile, and no tile far from one is listed",
          "[fast][orbit]") {
  const double R = render::OrbitSettings{}.planet_radius_m, air = R + render::atmosphere_top_km() * 1000;
  struct Case {
    const char* name;
    render::OrbitCamera camera;
  };
  render::OrbitCamera disk = nadir_camera(0, 10, 3.6e7, 320, 180, 40);
  render::OrbitCamera bern = nadir_camera(46.95, 7.44, 2.0e6, 320, 180, 70);
  render::OrbitCamera horizon = nadir_camera(46.95, 7.44, 4.0e5, 333, 181, 60);
  horizon.pitch_deg = -10;
  horizon.heading_deg = 200;
  render::OrbitCamera off_centre = nadir_camera(-30, 120, 1.0e7, 250, 250, 30);
  off_centre.pitch_deg = -60;  // the disc's edge crosses the frame obliquely
  for (const Case& c : {Case{"full disk", disk}, Case{"2000 km", bern}, Case{"400 km, horizon", horizon},
                        Case{"10000 km, oblique", off_centre}}) {
    INFO(c.name);
    const render::TileView view = tile_view(c.camera);
    const std::vector<glm::uvec2> listed = render::tiles_meeting_sphere(view, air);
    const glm::ivec2 grid = render::tile_grid(view.width, view.height);
    const int columns = grid.x, rows = grid.y, tile = render::ORBIT_TILE;
    std::vector<char> in_list(size_t(columns) * rows, 0), meets(size_t(columns) * rows, 0);
    for (glm::uvec2 t : listed) in_list[t.y * columns + t.x] = 1;
    int missing = 0;
    for (int j = 0; j < view.height; ++j)
      for (int i = 0; i < view.width; ++i)
        if (pixel_meets_sphere(view, i, j, air)) {
          meets[(j / tile) * columns + i / tile] = 1;
          missing += in_list[(j / tile) * columns + i / tile] ? 0 : 1;
        }
    CHECK(missing == 0);
    // A listed tile's central ray is within the sphere's angle plus its own half-diagonal and
    // a 2e-4 rad margin: it borders a tile with a pixel in the air.
    int far = 0, listed_count = 0, meeting = 0;
    for (int ty = 0; ty < rows; ++ty)
      for (int tx = 0; tx < columns; ++tx) {
        meeting += meets[ty * columns + tx];
        if (!in_list[ty * columns + tx]) continue;
        ++listed_count;
        bool near = false;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int x = tx + dx, y = ty + dy;
            near = near || (x >= 0 && y >= 0 && x < columns && y < rows && meets[y * columns + x]);
          }
        far += near ? 0 : 1;
      }
    CHECK(far == 0);
    CHECK(listed_count == int(listed.size()));
    CHECK(listed_count >= meeting);
  }
  SECTION("inside the air every tile is drawn") {
    render::OrbitCamera low = nadir_camera(46.95, 7.44, 5.0e4, 100, 60, 60);
    low.pitch_deg = 10;  // looking up: most rays leave the air without meeting the ground
    CHECK(render::tiles_meeting_sphere(tile_view(low), air).size() == render::all_tiles(100, 60).size());
  }
  SECTION("the full disk from 36000 km leaves most of a 40-degree frame to space") {
    const auto listed = render::tiles_meeting_sphere(tile_view(disk), air);
    // The disc (with the air) spans 2 asin((R + 100 km) / D) = 17.6 deg of the 40: pi r^2 of
    // the frame's 320 x 180 pixels with r = 320 tan(8.8 deg) / (2 tan(20 deg)) = 68 pixels, 25 %
    // of the frame; the tiles along its edge add about its perimeter times a tile.
    const double r = 160 * std::tan(std::asin(air / (R + 3.6e7))) / std::tan(20 * degree);
    const double disc_tiles = M_PI * r * r / 64, edge_tiles = 2 * M_PI * r / 8;
    CHECK(listed.size() >= disc_tiles);
    CHECK(listed.size() <= disc_tiles + 1.5 * edge_tiles);
  }
}

TEST_CASE("orbit: the tiles it leaves out are black clear space, the frame the same as drawing every tile", "[orbit]") {
  test::test_context();
  // 20000 km up over the subsolar point with a cloud patch: planet, limb and space in one frame.
  const glm::dvec3 sun = render::sun_direction_ecef(june_morning);
  const double lat = std::asin(sun.z) / degree, lon = std::atan2(sun.y, sun.x) / degree;
  const auto camera = nadir_camera(lat, lon, 2.0e7, 96, 54, 50);
  render::OrbitRenderer renderer(uniform_planet(0.1), patch_cover(16, lat, lon, 10.0));
  auto frame = [&](const std::vector<glm::uvec2>& tiles) {
    gpu::Texture image = gpu::Texture::plane(camera.width, camera.height, GL_RGBA32F);
    renderer.render_tiles(camera, june_morning, image.id(), tiles);
    return image.read();
  };
  const std::vector<glm::uvec2> in_air = renderer.tiles_in_air(camera), every = render::all_tiles(96, 54);
  REQUIRE(in_air.size() < every.size() * 3 / 4);  // the view has space to leave out
  const std::vector<float> culled = frame(in_air), whole = frame(every);
  // The shader's work group is the host's tile.
  const gpu::ComputeProgram program("render/orbit.comp");
  GLint group[3] = {0, 0, 0};
  glGetProgramiv(program.id(), GL_COMPUTE_WORK_GROUP_SIZE, group);
  CHECK(group[0] == render::ORBIT_TILE);
  CHECK(group[1] == render::ORBIT_TILE);
  CHECK(group[2] == 1);
  REQUIRE(culled.size() == whole.size());
  size_t differing = 0;
  for (size_t k = 0; k < whole.size(); ++k) differing += culled[k] == whole[k] ? 0 : 1;
  CHECK(differing == 0);
  // And the frame has both: lit planet and black space.
  CHECK(*std::max_element(whole.begin(), whole.end()) > 0.0f);
  CHECK(std::count(whole.begin(), whole.end(), 0.0f) > 0);
  // A band of rows (the viewer's refinement), 19 to 36: those rows are the whole frame's to the
  // bit, the rows of tiles beyond it are left at 0.
  const render::RenderResult band = renderer.render(camera, june_morning, 19, 18);
  REQUIRE(band.radiance.pixels.size() == whole.size());
  const size_t row = 96 * 4;
  size_t band_differing = 0, drawn_outside = 0;
  for (size_t k = 0; k < whole.size(); ++k) {
    const int y = int(k / row);
    if (y >= 19 && y < 37) band_differing += band.radiance.pixels[k] == whole[k] ? 0 : 1;
    if (y < 16 || y >= 40) drawn_outside += band.radiance.pixels[k] == 0.0f ? 0 : 1;
  }
  CHECK(band_differing == 0);
  CHECK(drawn_outside == 0);
}

TEST_CASE("orbit tiles: a band of rows keeps the tiles that hold one of its rows and no other", "[fast][orbit]") {
  const std::vector<glm::uvec2> every = render::all_tiles(40, 30);  // 5 x 4 tiles of 8 pixels
  CHECK(render::tiles_in_rows(every, 0, 0) == every);
  // Rows 7 to 8 touch the first two tile rows; rows 8 to 15 only the second; 29 only the last.
  auto rows_of = [](const std::vector<glm::uvec2>& tiles) {
    std::vector<unsigned> rows;
    for (const glm::uvec2& t : tiles)
      if (rows.empty() || rows.back() != t.y) rows.push_back(t.y);
    return rows;
  };
  CHECK(rows_of(render::tiles_in_rows(every, 7, 2)) == std::vector<unsigned>{0, 1});
  CHECK(rows_of(render::tiles_in_rows(every, 8, 8)) == std::vector<unsigned>{1});
  CHECK(rows_of(render::tiles_in_rows(every, 29, 1)) == std::vector<unsigned>{3});
  CHECK(render::tiles_in_rows(every, 8, 8).size() == 5);
}

TEST_CASE("orbit textures: every level holds the nearest half floats of the CPU's mip chain, whatever the driver",
          "[orbit]") {
  test::test_context();
  // 1024 x 512 texels: two bands of rows in the upload, and a chain of 11 levels. The values are
  // random, with exact ties between two halves (1 + 2^-11 lies halfway between 1 and 1 + 2^-10):
  // a driver that truncated or rounded ties away from even would hold other bits.
  const int width = 1024, height = 512;
  core::ImageData colour{width, height, 3, {}}, slopes{width, height, 2, {}}, grey{width, height, 1, {}};
  std::uint32_t state = 12345;
  auto next = [&] {
    state = state * 1664525u + 1013904223u;
    return float(state >> 8) / float(1u << 24);
  };
  for (int k = 0; k < width * height; ++k) {
    for (int c = 0; c < 3; ++c) colour.pixels.push_back(k % 7 == 0 ? 1.0f + std::ldexp(1.0f, -11) : next());
    for (int c = 0; c < 2; ++c) slopes.pixels.push_back(0.3f * (next() - 0.5f));
    grey.pixels.push_back(next());
  }
  // The texture's level read back as halves, against the CPU's chain rounded to nearest even.
  auto check_level = [&](unsigned id, const core::ImageData& image, int out_channels, int level) {
    const int w = std::max(1, width >> level), h = std::max(1, height >> level);
    const std::vector<float> texels =
        level == 0 ? image.pixels : core::mip_levels(image.pixels, width, height, image.channels, level + 1).back();
    std::vector<std::uint16_t> held(size_t(w) * h * out_channels);
    glPixelStorei(GL_PACK_ALIGNMENT, 2);
    glGetTextureImage(id, level, out_channels == 2 ? GL_RG : GL_RGBA, GL_HALF_FLOAT, GLsizei(held.size() * 2),
                      held.data());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    size_t wrong = 0;
    for (size_t k = 0; k < size_t(w) * h; ++k)
      for (int c = 0; c < out_channels; ++c) {
        const float expected = c == 3 ? 1.0f : texels[k * image.channels + std::min(c, image.channels - 1)];
        if (held[k * out_channels + c] != core::half_from_float(expected)) ++wrong;
      }
    INFO("level " << level << " of a " << image.channels << "-channel map");
    CHECK(wrong == 0);
  };
  const unsigned colour_id = render::colour_map_texture(colour), slope_id = render::slope_texture(slopes),
                 grey_id = render::colour_map_texture(grey);
  for (int level : {0, 1, 5, 10}) {
    check_level(colour_id, colour, 4, level);
    check_level(slope_id, slopes, 2, level);
    check_level(grey_id, grey, 4, level);
  }
  for (GLuint id : {colour_id, slope_id, grey_id}) glDeleteTextures(1, &id);
}

TEST_CASE("orbit metering: the lit pixels' 99th luminance percentile goes to the filmic curve's x = 1",
          "[fast][orbit]") {
  // 1000 lit pixels of luminance 0.001 k (grey: R = G = B) and 500 black ones (space).
  core::ImageData image{1500, 1, 4, std::vector<float>(6000, 0.0f)};
  for (int k = 1; k <= 1000; ++k)
    for (int c = 0; c < 3; ++c) image.pixels[size_t(k - 1) * 4 + c] = 0.001f * float(k);
  // The element at 0.99 (n - 1) = 989 of the sorted lit luminances: 0.990 (weights sum to 1).
  CHECK(render::highlight_exposure(image, 2.5) == Approx(1.0 / 0.990).epsilon(1e-6));
  // Clamped to a factor 4 around the usual: a dim frame (night, a few faint clouds) ...
  for (float& v : image.pixels) v *= 0.01f;
  CHECK(render::highlight_exposure(image, 2.5) == Approx(10.0));
  // ... and a bright one.
  for (float& v : image.pixels) v *= 1e4f;
  CHECK(render::highlight_exposure(image, 2.5) == Approx(0.625));
  // Nothing lit: the usual.
  const core::ImageData space{4, 4, 4, std::vector<float>(64, 0.0f)};
  CHECK(render::highlight_exposure(space, 2.5) == 2.5);
}

TEST_CASE("orbit metering never exposes brighter than a white surface under the frame's highest sun needs",
          "[fast][orbit]") {
  // The first case's frame (highlight exposure 1 / 0.990) under a white surface of luminance
  // 1.25: the bound 1 / 1.25 is lower and wins; under one of 0.5 (a low sun) the highlights do.
  core::ImageData image{1000, 1, 4, std::vector<float>(4000, 0.0f)};
  for (int k = 1; k <= 1000; ++k)
    for (int c = 0; c < 3; ++c) image.pixels[size_t(k - 1) * 4 + c] = 0.001f * float(k);
  CHECK(render::highlight_exposure(image, 2.5, 1.25) == Approx(0.8).epsilon(1e-12));
  CHECK(render::highlight_exposure(image, 2.5, 0.5) == Approx(1.0 / 0.990).epsilon(1e-6));
  CHECK(render::highlight_exposure(image, 2.5, 0.0) == Approx(1.0 / 0.990).epsilon(1e-6));

  // The reading: a narrow view straight down on the point below the sun reads the white surface
  // under the zenith sun, seen through the air; a view of the night side reads nothing.
  const double R = 6371000.0, time = core::parse_utc_time("2026-06-21T12:00Z");
  const glm::dvec3 sun = render::sun_direction_ecef(time);
  const auto looking_down_at = [&](double latitude, double longitude) {
    render::OrbitCamera camera;
    camera.latitude_deg = latitude;
    camera.longitude_deg = longitude;
    camera.altitude_m = 2e6;
    camera.fov_deg = 0.5;  // +-9 km of ground: the sun's cosine there is 1 to 1e-6
    camera.width = 64;
    camera.height = 36;
    return render::sunlit_white_luminance(camera, time, R);
  };
  const double below_sun_lat = std::asin(sun.z) * 180 / M_PI, below_sun_lon = std::atan2(sun.y, sun.x) * 180 / M_PI;
  const auto white_under = [&](double mu) {
    // A point whose sun has cosine mu (the sun's direction tilted away from it; the reading
    // depends on mu alone).
    const glsl::vec3 s(sun),
        n = normalize(glsl::vec3(sun) + float(std::sqrt(1 - mu * mu) / mu) * normalize(cross(s, glsl::vec3(0, 0, 1))));
    // Seen from straight above: through the air's transmittance towards the zenith.
    const glsl::vec3 w =
        (glsl::solar_irradiance() * glsl::transmittance_to_space(n * float(R + 1), s, float(R)) * float(mu / M_PI) +
         glsl::sky_ambient(n, s)) *
        glsl::transmittance_to_space(n * float(R + 1), n, float(R));
    return 0.2126 * w.x + 0.7152 * w.y + 0.0722 * w.z;
  };
  const double zenith = looking_down_at(below_sun_lat, below_sun_lon);
  INFO("white under the zenith sun " << zenith);
  CHECK(zenith == Approx(white_under(1.0)).epsilon(1e-4));
  // About the sun's irradiance over pi times the air's transmittance twice (0.7-0.9 each).
  CHECK(zenith > 0.4 * 1.85 / M_PI);
  CHECK(zenith < 1.85 / M_PI + 0.1);
  CHECK(looking_down_at(-below_sun_lat, below_sun_lon + 180) == 0.0);
  // 60 degrees of arc from the point below the sun (along its meridian), the sun 30 degrees
  // high: the reading of mu = 0.5, within the view's +-9 km (1.4e-3 rad of arc: 0.25 % of mu).
  const double sixty = looking_down_at(below_sun_lat - 60, below_sun_lon);
  CHECK(sixty == Approx(white_under(0.5)).epsilon(0.01));
  CHECK(sixty < 0.6 * zenith);
}
