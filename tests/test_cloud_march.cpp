// The ray marcher of shaders/lib/cloud_march.glsl run on the GPU through the renderer agrees,
// pixel by pixel, with its C++ twin (src/shader_math) marching the same rays through the same
// noise volume, read back from the GPU.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "core/time.hpp"
#include "gl_support.hpp"
#include "march_tolerance.hpp"
#include "render/cloud_renderer.hpp"
#include "shader_math/shader_math.hpp"

using namespace nephele;
using namespace nephele::regional;

namespace {

render::Camera camera(bool panorama) {
  render::Camera c;
  c.latitude_deg = 46.91722;
  c.longitude_deg = 7.44361;
  c.height_m = 860;
  c.heading_deg = 20;
  c.pitch_deg = 12;
  c.panorama = panorama;
  c.width = 16;
  c.height = panorama ? 8 : 9;
  return c;
}

// A field whose coverage varies from texel to texel, so that the weather's bilinear filter
// matters: a fixed pattern in [0.2, 0.9] per channel.
WeatherField patterned_field() {
  WeatherField f{4, 40000.0, {}};
  for (int channel = 0; channel < coverage_channels; ++channel)
    for (int j = 0; j < f.size; ++j)
      for (int i = 0; i < f.size; ++i) f.values.push_back(0.2f + 0.7f * float((3 * i + 5 * j + channel) % 7) / 6.0f);
  return f;
}

// Coverage 1 in the given channels and 0 in the others, over 160 km.
WeatherField overcast_field(std::initializer_list<CoverageChannel> channels) {
  WeatherField f{4, 160000.0, {}};
  for (int c = 0; c < coverage_channels; ++c) {
    bool on = false;
    for (CoverageChannel channel : channels) on = on || c == int(channel);
    f.values.insert(f.values.end(), 16, on ? 1.0f : 0.0f);
  }
  return f;
}

// The marcher's C++ twin's textures: the noise volume read back and the field.
glsl::MarchSources host_sources(const render::NoiseVolume& noise, const WeatherField& field) {
  glsl::MarchSources sources;
  sources.noise = noise.host_copy();
  sources.weather = {field.size, coverage_channels, field.values.data()};
  return sources;
}

// The shadow tests' sheets: overcast stratus (sheet amount 1) 600 m thick at extinction 2e-2 /m,
// texture >= 0.7, the profile's six midpoint samples averaging 0.753, so that a vertical path
// through one has optical depth >= 2e-2 x 600 x 0.753 x 0.7 = 6.3 (more along a slanted sun ray).
const double sheet_least_depth = 2e-2 * 600 * 0.753 * 0.7;
CloudLayer overcast_sheet(CoverageChannel channel, float base_m, const char* name) {
  return {CloudType::stratus, channel, base_m, base_m + 600, 2e-2f, 0, 0, 0, name};
}
// Their time: midsummer at 11:30 UTC, the sun about 66 degrees up at the camera.
double shadow_test_time() { return core::parse_utc_time("2026-06-21T11:30Z"); }

// A shadow map (layer -1: the sky's) made on the CPU, size x size texels.
std::vector<float> cpu_shadow_map(int size, int layer, const glsl::MarchParams& params,
                                  const glsl::MarchSources& sources) {
  const glm::vec3 centre(0.0f, 0.0f, -(params.earth_radius + params.camera_altitude));
  std::vector<float> map;
  int loops = 0;
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i)
      map.push_back(glsl::shadow_map_texel(glm::vec2((i + 0.5f) / size, (j + 0.5f) / size), centre, layer, loops,
                                           params, sources.noise, sources.weather, sources.convective));
  return map;
}

}  // namespace

TEST_CASE("the marcher on the GPU agrees with its C++ twin pixel by pixel", "[render][march]") {
  test::test_context();
  const double time = core::parse_utc_time("2026-06-21T15:00Z");
  const std::vector<CloudLayer> layers = {
      {CloudType::cumulus, CoverageChannel::low, 1500, 3000, 1e-2f, 0, 0, 0, "test"},
      {CloudType::alto, CoverageChannel::mid, 3500, 5000, 2e-3f, 0.5f, 0.2f, 0, "test"},
      {CloudType::cirrus, CoverageChannel::high, 8500, 10000, 3e-4f, 0, 0, 0, "test"}};
  const WeatherField field = patterned_field();
  render::RenderSettings settings;
  settings.view_steps = 6;
  settings.light_steps = 3;
  settings.sky_steps = 6;
  settings.noise_size = 16;
  settings.shadow_map_size = 16;
  settings.read_shadow_maps = true;  // the C++ twin reads the GPU's maps (compared below)
  const render::NoiseVolume noise(settings.noise_size, settings.seed);
  glsl::MarchSources sources;
  sources.noise = noise.host_copy();
  sources.weather = {field.size, coverage_channels, field.values.data()};
  const glm::dvec2 wind(1, 2);
  const double wind_speed = 7;
  // The thinnest layers are 1500 m thick; the shortest vertical noise period is alto's 4000 m.
  const double tolerance = test::march_tolerance(1500.0, 4000.0, sources.noise);
  INFO("tolerance " << tolerance << " (largest texel step " << test::max_texel_step(sources.noise) << ")");

  for (bool panorama : {false, true}) {
    INFO("panorama " << panorama);
    const auto cam = camera(panorama);
    const auto gpu = render::render_clouds(cam, layers, field, time, settings, wind, wind_speed, &noise);
    const glsl::MarchParams params = render::march_params(cam, layers, field, time, settings, wind, wind_speed);
    REQUIRE(params.layer_count == 3);
    // The cumulus has the alto and the cirrus above it, the alto the cirrus: two maps; and the
    // sky's from the cumulus's base (crepuscular rays), 4 x 4 texels in a texture of its own.
    REQUIRE(render::shadow_map_count(params) == 2);
    REQUIRE(gpu.shadow_maps.size() == 2u * 16 * 16);
    sources.shadows = {16, 2, gpu.shadow_maps.data()};
    REQUIRE(params.sky_shadow_map == 0);
    REQUIRE(params.sky_shadow_base == 1500.0f);
    REQUIRE(render::sky_shadow_map_size(16) == 4);
    REQUIRE(gpu.sky_shadow_map.size() == 4u * 4);
    sources.sky_shadow = {4, 1, gpu.sky_shadow_map.data()};
    // Each texel against the C++ twin: a shadow march through thin layers (relative tolerance).
    const glm::vec3 centre(0.0f, 0.0f, -(params.earth_radius + params.camera_altitude));
    for (int layer = -1; layer < 2; ++layer) {
      const int size = layer >= 0 ? 16 : 4;
      for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i) {
          int loops = 0;
          const float cpu = glsl::shadow_map_texel(glm::vec2((i + 0.5f) / size, (j + 0.5f) / size), centre, layer,
                                                   loops, params, sources.noise, sources.weather, sources.convective);
          const float g =
              layer >= 0 ? gpu.shadow_maps[(static_cast<size_t>(params.layers[layer].shadow_map) * 16 + j) * 16 + i]
                         : gpu.sky_shadow_map[static_cast<size_t>(j) * 4 + i];
          INFO("map of layer " << layer << " texel " << i << ", " << j << ": GPU " << g << ", CPU " << cpu);
          CHECK(std::abs(g - cpu) <= tolerance * std::max(cpu, 1e-6f));
        }
    }
    int cloudy = 0;
    int limited = 0;
    double worst = 0;
    for (int y = 0; y < cam.height; ++y)
      for (int x = 0; x < cam.width; ++x) {
        int loops = 0;
        float ground_distance = 0;
        const glm::vec4 cpu = glsl::render_pixel(glm::ivec2(x, y), glm::ivec2(cam.width, cam.height), params, loops,
                                                 ground_distance, sources.noise, sources.weather, sources.terrain,
                                                 sources.land, sources.convective, sources.shadows, sources.sky_shadow);
        if (glsl::loop_limited(loops)) ++limited;
        const float* g = &gpu.radiance.pixels[(static_cast<size_t>(y) * cam.width + x) * 4];
        if (cpu.w > 0.5f) ++cloudy;
        const double brightest = std::max({cpu.x, cpu.y, cpu.z});
        for (int c = 0; c < 4; ++c) {
          INFO("pixel " << x << ", " << y << " channel " << c << ": GPU " << g[c] << ", CPU " << cpu[c]);
          // Opacity 1 - T: dT = T dtau with dtau <= tau * tolerance, and T tau <= 1/e.
          const double allowed = c < 3 ? tolerance * brightest : tolerance / M_E;
          CHECK(std::abs(g[c] - cpu[c]) <= allowed);
          worst = std::max(worst, std::abs(g[c] - cpu[c]) / (c < 3 ? brightest : 1.0));
        }
      }
    // The comparison means something: much of the view is cloud (the panorama's lower half is
    // ground).
    CHECK(cloudy > cam.width * cam.height / 4);
    // (Measured: 1.0e-2 perspective, 3.8e-3 panorama, of 0.126.)
    INFO("worst " << worst << " of tolerance " << tolerance);
    CHECK(limited == static_cast<int>(gpu.loop_limited_pixels));
  }
}

TEST_CASE("an overcast layer shades the ground below it and no layer shades what lies above it", "[render][shadow]") {
  test::test_context();
  const double time = shadow_test_time();
  const std::vector<CloudLayer> layers = {overcast_sheet(CoverageChannel::low, 1500, "test")};
  const WeatherField field = overcast_field({CoverageChannel::low});
  render::RenderSettings settings;
  settings.noise_size = 16;
  const render::NoiseVolume noise(settings.noise_size, settings.seed);
  const glsl::MarchSources sources = host_sources(noise, field);
  const glsl::MarchParams params = render::march_params(camera(false), layers, field, time, settings);
  const glm::vec3 centre(0.0f, 0.0f, -(params.earth_radius + params.camera_altitude));
  const glm::vec3 ground(0.0f, 0.0f, -params.camera_altitude);
  int loops = 0;
  // The sheet's depth straight up, more along the slanted sun ray.
  CHECK(glsl::shadow_depth(ground, centre, -1, -1.0e30f, loops, params, sources.noise, sources.weather,
                           sources.convective) >= sheet_least_depth);
  CHECK(loops == params.layer_count + 2 + glsl::SHADOW_STEPS);  // the layer loop, the two intervals, the samples
  // Only layers with a base at or above 2100 m shade a point at the layer's top: none here.
  CHECK(glsl::shadow_depth(ground, centre, -1, 2100.0f, loops, params, sources.noise, sources.weather,
                           sources.convective) == 0.0f);
  CHECK(glsl::shadow_depth(ground, centre, 0, -1.0e30f, loops, params, sources.noise, sources.weather,
                           sources.convective) == 0.0f);
}

TEST_CASE("the ground in a cloud's shadow keeps the sky's light", "[render][shadow]") {
  test::test_context();
  const double time = shadow_test_time();
  const WeatherField field = overcast_field({CoverageChannel::low});
  render::RenderSettings settings;
  settings.noise_size = 16;
  settings.shadow_map_size = 0;  // the sky's light is what is tested, not the crepuscular rays
  const render::NoiseVolume noise(settings.noise_size, settings.seed);
  const glsl::MarchSources sources = host_sources(noise, field);
  render::Camera cam = camera(false);
  cam.pitch_deg = -30;  // the ground 1.7 km ahead, under the sheet, which the view does not cross
  const glsl::MarchParams shaded =
      render::march_params(cam, {overcast_sheet(CoverageChannel::low, 1500, "test")}, field, time, settings);
  const glsl::MarchParams clear = render::march_params(cam, {}, field, time, settings);
  auto pixel = [&](const glsl::MarchParams& params) {
    int loops = 0;
    float ground_distance = 0;
    const glm::vec4 v =
        glsl::render_pixel(glm::ivec2(cam.width / 2, cam.height / 2), glm::ivec2(cam.width, cam.height), params, loops,
                           ground_distance, sources.noise, sources.weather, sources.terrain, sources.land,
                           sources.convective, sources.shadows, sources.sky_shadow);
    REQUIRE(ground_distance > 0.0f);
    return glm::vec3(v);
  };
  // The sheet's optical depth (>= 6.3) leaves the shaded ground at most e^-6.3 of the sun: its
  // light is the sky's. The sky's irradiance at the ground against the direct sun's: at least
  // Rayleigh's downward half of the single scattering of a thin atmosphere, 0.5 tau_R(h) / mu
  // (green, tau_R = 13.558e-6 /m x 8 km x e^(-h / 8 km), mu the sun's sine), less the
  // attenuation e^(-tau / mu) < 20 % on the way.
  const glm::vec3 up(0.0f, 0.0f, shaded.earth_radius + shaded.camera_altitude);
  const float mu = shaded.sun.z;
  const float direct =
      glsl::solar_irradiance().y * glsl::transmittance_to_space(up, shaded.sun, shaded.earth_radius).y * mu;
  const float tau_rayleigh = 13.558e-6f * 8000.0f * std::exp(-shaded.camera_altitude / 8000.0f);
  INFO("sun " << std::asin(mu) * 180 / M_PI << " deg, sky " << shaded.ground_ambient.y << " W m^-2 nm^-1, direct "
              << direct);
  CHECK(shaded.ground_ambient.y / direct >= 0.8f * 0.5f * tau_rayleigh / mu);
  // And at least the measured clear-sky diffuse share (Erbs et al. 1982) of the global irradiance.
  const float f = render::clear_sky_diffuse_fraction;
  CHECK(shaded.ground_ambient.y / (direct + shaded.ground_ambient.y) >= f * (1.0f - 1e-5f));
  // The shaded ground seen from the camera keeps that share of the sunlit ground's radiance
  // (the short path's air adds to both; 10 % for the sheet's remaining sunlight and rounding).
  const glm::vec3 dark = pixel(shaded), lit = pixel(clear);
  const float share = shaded.ground_ambient.y / (direct + shaded.ground_ambient.y);
  INFO("shaded " << dark.y << ", sunlit " << lit.y << ", sky's share " << share);
  CHECK(dark.y >= 0.9f * share * lit.y);
  CHECK(dark.y < lit.y);
}

TEST_CASE("a layer under an overcast layer reads the depth through it from its shadow map and gets less sunlight",
          "[render][shadow]") {
  test::test_context();
  const double time = shadow_test_time();
  // Overcast stratus at 1500-2100 m under an overcast sheet at 3000-3600 m (the mid channel).
  const std::vector<CloudLayer> two = {overcast_sheet(CoverageChannel::low, 1500, "low"),
                                       overcast_sheet(CoverageChannel::mid, 3000, "high")};
  const WeatherField field = overcast_field({CoverageChannel::low, CoverageChannel::mid});
  render::RenderSettings settings;
  settings.noise_size = 16;
  const render::NoiseVolume noise(settings.noise_size, settings.seed);
  glsl::MarchSources sources = host_sources(noise, field);
  const glsl::MarchParams params = render::march_params(camera(false), two, field, time, settings);
  REQUIRE(params.layers[0].shadow_map == 0);
  REQUIRE(params.layers[1].shadow_map == -1);
  REQUIRE(render::shadow_map_count(params) == 1);
  REQUIRE(params.sky_shadow_map == 0);  // and the sky's, in its own texture
  const glm::vec3 centre(0.0f, 0.0f, -(params.earth_radius + params.camera_altitude));
  // The map made on the CPU, 32 x 32 texels over 300 km.
  const int size = 32;
  const std::vector<float> map = cpu_shadow_map(size, 0, params, sources);
  sources.shadows = {size, 1, map.data()};
  const double tolerance = test::march_tolerance(600.0, 12000.0, sources.noise);
  // Points of the lower layer on the sun rays through texel centres of its top: the lookup is
  // the depth through the upper layer marched from the point itself (the same ray beyond the
  // top), and that is at least the overcast sheet's vertical depth (sheet_least_depth).
  for (int k = 0; k < 20; ++k) {
    const glm::vec2 uv((3 + k % 5 * 6 + 0.5f) / size, (4 + k / 5 * 6 + 0.5f) / size);
    const glm::vec3 top =
        glsl::shadow_map_origin((2.0f * uv - 1.0f) * params.shadow_extent, centre, params.layers[0].top, params);
    const glm::vec3 p = top - (100.0f + 25.0f * k) / params.sun.z * params.sun;  // 100 to 575 m below the top
    int n = 0;
    const float marched = glsl::layers_shadow_depth(p, centre, 0, 2100.0f, n, params, sources.noise, sources.weather);
    const float looked_up = glsl::higher_layers_depth(p, centre, 0, params, sources.shadows);
    INFO("point " << k << ": marched " << marched << ", from the map " << looked_up);
    CHECK(looked_up == Approx(marched).epsilon(tolerance));
    CHECK(marched >= sheet_least_depth);
  }
  // Marched along a ray rising through the lower layer, the layer sends less light with its
  // map than without (the same extinction: the transmittance is the same).
  glsl::MarchParams unshaded = params;
  unshaded.layers[0].shadow_map = -1;
  const glm::vec3 d = glm::normalize(glm::vec3(0.2f, 0.5f, 1.0f));
  const glm::vec4 b =
      glsl::ray_shell(glm::vec3(0.0f), d, centre, params.earth_radius + 1500.0f, params.earth_radius + 2100.0f, 1e6f);
  const auto march = [&](const glsl::MarchParams& m) {
    glsl::CloudMarch c{glm::vec3(0.0f), 1.0f, 0.0f, 0.0f, 0};
    glsl::march_interval(b.z, b.w, 0, false, d, centre, 0.5f, glm::dot(d, m.sun), c, m, sources.noise, sources.weather,
                         sources.convective, sources.shadows);  // out of the inner sphere
    return c;
  };
  const glsl::CloudMarch shaded = march(params), open = march(unshaded);
  INFO("radiance with the map " << shaded.radiance.y << ", without " << open.radiance.y);
  CHECK(shaded.transmittance == open.transmittance);
  CHECK(shaded.transmittance < 0.5f);  // the ray did go through cloud
  CHECK(shaded.radiance.x < open.radiance.x);
  CHECK(shaded.radiance.y < open.radiance.y);
  CHECK(shaded.radiance.z < open.radiance.z);
  // The renderer makes a layer's map only where a layer has one above it; the sky's whenever
  // there is cloud and shadow_map_size is not 0.
  render::Camera small = camera(false);
  small.width = 8;
  small.height = 4;
  settings.shadow_map_size = 8;
  const auto passes_of = [](const render::RenderResult& r) {
    std::string all;
    for (const auto& p : r.passes) all += p + "; ";
    return all;
  };
  const std::string both = passes_of(render::render_clouds(small, two, field, time, settings, {0, 1}, 0, &noise));
  CHECK(both.find("layer_shadows (1 of 8^2)") != std::string::npos);
  CHECK(both.find("sky_shadow (2^2)") != std::string::npos);
  const std::string one = passes_of(render::render_clouds(small, {two[0]}, field, time, settings, {0, 1}, 0, &noise));
  CHECK(one.find("layer_shadows") == std::string::npos);
  CHECK(one.find("sky_shadow (2^2)") != std::string::npos);
  render::RenderSettings no_maps = settings;
  no_maps.shadow_map_size = 0;
  const std::string none = passes_of(render::render_clouds(small, two, field, time, no_maps, {0, 1}, 0, &noise));
  CHECK(none.find("layer_shadows") == std::string::npos);
  CHECK(none.find("sky_shadow") == std::string::npos);
  // With a cache (the viewer's bands) the maps are made once while nothing they depend on
  // changes, and the image is the same to the bit; another sun makes them again.
  const auto without_cache = render::render_clouds(small, two, field, time, settings, {0, 1}, 0, &noise);
  settings.shadow_cache = std::make_shared<render::ShadowMapCache>();
  const auto first = render::render_clouds(small, two, field, time, settings, {0, 1}, 0, &noise);
  render::Camera turned = small;
  turned.heading_deg += 40;  // the view's direction: not in the maps
  const auto again = render::render_clouds(turned, two, field, time, settings, {0, 1}, 0, &noise);
  const auto later = render::render_clouds(small, two, field, time + 3600, settings, {0, 1}, 0, &noise);
  CHECK(passes_of(first).find("layer_shadows (1 of 8^2)") != std::string::npos);
  CHECK(passes_of(again).find("layer_shadows (reused)") != std::string::npos);
  CHECK(passes_of(again).find("sky_shadow (reused)") != std::string::npos);
  CHECK(passes_of(later).find("layer_shadows (1 of 8^2)") != std::string::npos);
  CHECK(passes_of(later).find("sky_shadow (2^2)") != std::string::npos);
  CHECK(first.radiance.pixels == without_cache.radiance.pixels);
}

TEST_CASE("the air below an overcast layer scatters no direct sunlight: a pixel loses the clear sky's in-scattering",
          "[render][shadow][crepuscular]") {
  test::test_context();
  const double time = shadow_test_time();
  const std::vector<CloudLayer> layers = {overcast_sheet(CoverageChannel::low, 1500, "test")};
  const WeatherField field = overcast_field({CoverageChannel::low});
  render::RenderSettings settings;
  settings.noise_size = 16;
  const render::NoiseVolume noise(settings.noise_size, settings.seed);
  glsl::MarchSources sources = host_sources(noise, field);
  render::Camera down = camera(false);
  down.pitch_deg = -30;  // every ray meets the flat ground within 4 km, under the layer
  down.width = 8;
  down.height = 4;
  glsl::MarchParams params = render::march_params(down, layers, field, time, settings);
  REQUIRE(params.sky_shadow_map == 0);
  REQUIRE(params.sky_shadow_base == 1500.0f);
  const glm::vec3 centre(0.0f, 0.0f, -(params.earth_radius + params.camera_altitude));
  // The sky's map made on the CPU, 16 x 16 texels over 300 km.
  const int size = 16;
  const std::vector<float> map = cpu_shadow_map(size, -1, params, sources);
  sources.sky_shadow = {size, 1, map.data()};
  // The overcast's optical depth, at least the sheet's vertical 6.3: the air below keeps at
  // most e^-6.3 = 0.0018 of the direct sun.
  const float least_depth = static_cast<float>(sheet_least_depth);
  CHECK(*std::min_element(map.begin(), map.end()) >= least_depth);
  glsl::MarchParams unshaded = params;
  unshaded.sky_shadow_map = -1;
  for (int k = 0; k < 4; ++k) {
    const glm::ivec2 pixel(2 * k + 1, k);
    int n = 0;
    float ground_distance = 0;
    const glm::vec4 with = glsl::render_pixel(pixel, glm::ivec2(down.width, down.height), params, n, ground_distance,
                                              sources.noise, sources.weather, sources.terrain, sources.land,
                                              sources.convective, sources.shadows, sources.sky_shadow);
    const glm::vec4 without = glsl::render_pixel(pixel, glm::ivec2(down.width, down.height), unshaded, n,
                                                 ground_distance, sources.noise, sources.weather, sources.terrain,
                                                 sources.land, sources.convective, sources.shadows, sources.sky_shadow);
    // The ray's clear-sky in-scattering to the ground (no cloud on it: opacity 0).
    const glm::vec3 d = glsl::view_direction(pixel, glm::ivec2(down.width, down.height), params);
    const glm::vec2 ground = glsl::ray_sphere(glm::vec3(0.0f), d, centre, params.earth_radius);
    REQUIRE(ground.x > 0.0f);
    REQUIRE(with.w == 0.0f);
    glm::vec3 total, split, t_total, t_split;
    glsl::sky_single_scattering(-centre, d, ground.x, 0.0f, params.sun, params.earth_radius, params.sky_steps, total,
                                split, t_total, t_split);
    // The loss is that in-scattering times 1 - e^-tau, tau >= least_depth; float rounding of
    // the sums (16 steps) is far below the e^-6.3 margin.
    for (int c = 0; c < 3; ++c) {
      INFO("pixel " << pixel.x << ", " << pixel.y << " channel " << c << ": with " << with[c] << ", without "
                    << without[c] << ", clear-sky in-scattering " << total[c]);
      CHECK(total[c] > 0.0f);
      const float lost = without[c] - with[c];
      CHECK(lost <= total[c] * (1.0f + 1e-5f));
      CHECK(lost >= total[c] * (1.0f - std::exp(-least_depth)) * (1.0f - 1e-5f));
    }
  }
}
