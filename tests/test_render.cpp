// Rendering of the layers: only the needed passes run, and extreme views stay finite.
#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>

#include "io/scene_files.hpp"
#include "io/weather_files.hpp"
#include "core/time.hpp"
#include "gl_support.hpp"
#include "render_scenes.hpp"
#include "regional/scene.hpp"
#include "render/cloud_renderer.hpp"
#include "render/scene_renderer.hpp"
#include "render/upsample.hpp"
#include "render/sun_position.hpp"

using namespace nephele;
using namespace nephele::regional;

namespace {

// The marcher stops a ray once its transmittance is at most 0.01 (shaders/lib/cloud_march.glsl),
// so a ray that enters a cloud of huge optical depth ends with alpha = 1 - T >= 0.99; at
// 1e3 /m one step takes T far below that.
constexpr double kOpaqueAlpha = 0.99;
// Fully overcast stratus (c = 1: the sheet amount is 1 for every shape value) 600 m thick with
// extinction 2e-2 /m, profile (soft 0.25) averaging 0.75 and texture at least 0.7: optical depth
// at least 2e-2 x 600 x 0.75 x 0.7 = 6.3 overhead (more on slanted rays), T <= 0.002, alpha >=
// 0.998. 0.9 (optical depth 2.3) leaves room for the 12-step quadrature, whose error is not
// derived (partly empirical).
constexpr double kOvercastAlpha = 0.9;
static_assert(kOvercastAlpha <= kOpaqueAlpha);
// With the sun below the horizon (19 deg below at 23:00 UTC) the mean radiance is below this share
// of noon's: a check of "far darker", empirical (what the renderer leaves at night is not
// derived).
constexpr double kNightShareOfDay = 0.1;
// Tone mapping of 1e6 x exposure: the curve saturates and clamps to 1, and the sRGB encoding
// 1.055 x 1^(1/2.4) - 0.055 is 1 up to one double rounding (1.1e-16) before the conversion to
// float; 1e-3 is far looser (kept as set).
constexpr double kSaturatedEncoding = 1.0e-3;
static_assert(kSaturatedEncoding >= 1.2e-16);

const double noon = core::parse_utc_time("2026-06-21T11:30Z");
const double midnight = core::parse_utc_time("2026-06-21T23:00Z");

render::Camera small_camera(double pitch = 10) {
  render::Camera c;
  c.latitude_deg = 46.91722;
  c.longitude_deg = 7.44361;
  c.height_m = 860;
  c.heading_deg = 20;
  c.pitch_deg = pitch;
  c.width = 24;
  c.height = 16;
  return c;
}

render::RenderSettings quick() {
  render::RenderSettings s;
  s.view_steps = 12;
  s.light_steps = 3;
  s.sky_steps = 6;
  s.noise_size = 16;
  // Maps of 64^2 over the shadows' extent: these images are 64 pixels wide at most, and no test
  // here looks at the shadows (at the default 512^2 they are two thirds of each render's time).
  s.shadow_map_size = 64;
  return s;
}

WeatherField uniform_field(float low, float mid, float high, float fog = 0, float convective = 0) {
  WeatherField f{4, 160000.0, {}};
  for (float v : {high, mid, low, fog, convective}) f.values.insert(f.values.end(), 16, v);
  return f;
}

struct Stats {
  double mean = 0;
  double alpha_min = 1, alpha_max = 0;
  bool finite = true;
};

Stats stats(const render::RenderResult& r) {
  Stats s;
  const auto& p = r.radiance.pixels;
  for (size_t k = 0; k < p.size(); k += 4) {
    for (int c = 0; c < 4; ++c) s.finite = s.finite && std::isfinite(p[k + c]) && p[k + c] >= 0.0f;
    s.mean += (p[k] + p[k + 1] + p[k + 2]) / 3.0;
    s.alpha_min = std::min<double>(s.alpha_min, p[k + 3]);
    s.alpha_max = std::max<double>(s.alpha_max, p[k + 3]);
  }
  s.mean /= p.size() / 4.0;
  return s;
}

bool contains(const std::vector<std::string>& passes, const std::string& text) {
  for (const auto& p : passes)
    if (p.find(text) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST_CASE("a clear sky marches no layer and builds no noise volume", "[render]") {
  test::test_context();
  const auto layers = choose_layers(WeatherSample{}, {});
  const auto r = render::render_clouds(small_camera(), layers, uniform_field(0, 0, 0), noon, quick());
  CHECK_FALSE(contains(r.passes, "march layer"));
  CHECK_FALSE(contains(r.passes, "noise_volume"));
  const Stats s = stats(r);
  CHECK(s.finite);
  CHECK(s.alpha_max == 0.0);
  CHECK(s.mean > 0.0);  // the sky is still there
}

TEST_CASE("a layer whose coverage is zero everywhere is skipped", "[render]") {
  test::test_context();
  std::vector<CloudLayer> layers = {{CloudType::cumulus, CoverageChannel::low, 1500, 3000, 1e-2f, 0, 0, 0, "test"},
                                    {CloudType::cirrus, CoverageChannel::high, 8500, 10000, 3e-4f, 0, 0, 0, "test"}};
  const auto r = render::render_clouds(small_camera(), layers, uniform_field(0.5f, 0, 0), noon, quick());
  CHECK(contains(r.passes, "march layer cumulus"));
  CHECK(contains(r.passes, "skip layer cirrus (no cloud)"));
  CHECK_FALSE(contains(r.passes, "march layer cirrus"));
}

TEST_CASE("a fully overcast stratus hides the sky overhead", "[render]") {
  test::test_context();
  const auto layers = choose_layers(
      [] {
        WeatherSample s;
        s.cloud_low = 1.0;
        s.precipitation = 0.5;  // drizzle: stratus, not fog
        return s;
      }(),
      {});
  const auto r = render::render_clouds(small_camera(80), layers, uniform_field(1.0f, 0, 0), noon, quick());
  const Stats s = stats(r);
  CHECK(s.finite);
  CHECK(s.alpha_min > kOvercastAlpha);
}

TEST_CASE("extreme views and lights render without NaN or Inf", "[render][extreme]") {
  test::test_context();
  std::vector<CloudLayer> layers = {{CloudType::fog, CoverageChannel::fog, 500, 1200, 2e-3f, 0, 0, 0, "camera inside"},
                                    {CloudType::cumulus, CoverageChannel::low, 1500, 3000, 1e-2f, 0, 0, 0, "test"},
                                    {CloudType::alto, CoverageChannel::mid, 3500, 5000, 2e-3f, 0.5f, 0, 0, "test"},
                                    {CloudType::stratocumulus, CoverageChannel::convective, 1300, 11000, 1.5e-2f, 0,
                                     0.3f, 15000, "tall, from 15 km"}};
  const WeatherField field = uniform_field(0.6f, 0.5f, 0.3f, 1.0f, 0.8f);
  for (double pitch : {-90.0, -30.0, 0.0, 45.0, 90.0}) {
    for (double time : {noon, midnight}) {
      INFO("pitch " << pitch << " time " << time);
      const auto r = render::render_clouds(small_camera(pitch), layers, field, time, quick());
      CHECK(stats(r).finite);
    }
  }
  // Optical depths of zero and huge.
  for (float extinction : {0.0f, 1.0e3f}) {
    auto thick = layers;
    for (auto& l : thick) l.extinction = extinction;
    const auto r = render::render_clouds(small_camera(30), thick, field, noon, quick());
    const Stats s = stats(r);
    CHECK(s.finite);
    if (extinction == 0.0f)
      CHECK(s.alpha_max == 0.0);
    else
      CHECK(s.alpha_min > kOpaqueAlpha);
  }
  auto panorama = small_camera();
  panorama.panorama = true;
  CHECK(stats(render::render_clouds(panorama, layers, field, noon, quick())).finite);
}

TEST_CASE("with the sun below the horizon the scene is far darker than at noon", "[render]") {
  test::test_context();
  const auto layers = choose_layers(
      [] {
        WeatherSample s;
        s.cloud_low = 0.4;
        return s;
      }(),
      {});
  const WeatherField field = uniform_field(0.4f, 0, 0);
  const double day = stats(render::render_clouds(small_camera(), layers, field, noon, quick())).mean;
  const double night = stats(render::render_clouds(small_camera(), layers, field, midnight, quick())).mean;
  CHECK(night < kNightShareOfDay * day);
}

// A 16 x 8 view from the Gurten with few steps, the summer weather of Bern and Solothurn.
using test::small_summer_scene;

TEST_CASE("a resolution divisor renders the smaller image and upsamples it to the full size", "[render]") {
  test::test_context();
  Scene scene = small_summer_scene();
  const auto stations = io::read_scene_weather(scene);
  scene.resolution_divisor = 2;
  const auto divided = render::render_scene(scene, stations, nullptr);
  CHECK(contains(divided.passes, "upsample 1/2 guided by the ground distance"));
  CHECK(divided.render.radiance.width == 16);
  CHECK(divided.render.radiance.height == 8);
  // The same as rendering 8 x 4 pixels with the same field of view and upsampling that (bit for
  // bit: the same marcher on the same pixels, the same interpolation).
  Scene half = scene;
  half.resolution_divisor = 1;
  half.width = 8;
  half.height = 4;
  const auto small = render::render_scene(half, stations, nullptr);
  CHECK_FALSE(contains(small.passes, "upsample 1/2 guided by the ground distance"));
  // The guides: the marched image's ground distance at every pixel, the full size's only near an
  // edge of it (NaN elsewhere), each -1 (sky) or a distance.
  const core::ImageData& guide = divided.render.ground_distance;
  const core::ImageData& full = divided.render.upsampled_ground_distance;
  REQUIRE(guide.width == 8);
  REQUIRE(guide.height == 4);
  REQUIRE(full.width == 16);
  REQUIRE(full.height == 8);
  const auto needed = render::guide_pixels(guide, 16, 8);
  size_t found = 0;
  for (float g : full.pixels) found += std::isnan(g) ? 0 : 1;
  CHECK(found == needed.size());
  for (const auto& p : needed) CHECK((full.pixels[p.y * 16 + p.x] == -1.0f || full.pixels[p.y * 16 + p.x] > 0.0f));
  for (float g : guide.pixels) CHECK((g == -1.0f || g > 0.0f));
  // The image: the 8 x 4 render upsampled with those guides (bit for bit: the same marcher on
  // the same pixels, the same interpolation).
  CHECK(render::upsample_guided(small.render.radiance, guide, full).pixels == divided.render.radiance.pixels);
}

TEST_CASE("a scene with weather files does not generate the global cover and one without does", "[render]") {
  test::test_context();
  Scene scene = small_summer_scene();
  const auto with_weather = render::render_scene(scene, io::read_scene_weather(scene), nullptr);
  CHECK_FALSE(contains(with_weather.passes, "global_cover"));
  CHECK(contains(with_weather.passes, "weather_field (2 stations)"));
  CHECK(contains(with_weather.passes, "march layer cumulus"));
  scene.weather.clear();
  const auto from_cover = render::render_scene(scene, io::read_scene_weather(scene), nullptr);
  CHECK(with_weather.passes.front() != from_cover.passes.front());
  CHECK(from_cover.passes.front() == "global_cover");
  CHECK(contains(from_cover.passes, "weather_field (global cover)"));
}

TEST_CASE("a scene's global cover is that of its time with the moving flow and one map at every time with the steady",
          "[render]") {
  test::test_context();
  Scene scene = small_summer_scene();
  scene.weather.clear();
  scene.cover_size = 16;
  auto cover_at = [&](const std::string& flow, const std::string& time) {
    scene.cover_flow = flow;
    scene.time = time;
    const cover::CoverParameters p = render::scene_cover_parameters(scene, nullptr);
    CHECK(p.time == time);
    CHECK(cover::flow_name(p.flow) == flow);
    return render::make_global_cover(p).texels;
  };
  // Six hours apart: the moving clouds have moved (the cover's RMS change between frames 3 h
  // apart is about half its spread, docs/climate.md), the steady map is the same to the bit.
  const auto moving_noon = cover_at("moving", "2026-06-21T12:00Z"),
             moving_evening = cover_at("moving", "2026-06-21T18:00Z");
  const auto steady_noon = cover_at("steady", "2026-06-21T12:00Z"),
             steady_evening = cover_at("steady", "2026-06-21T18:00Z");
  CHECK(steady_noon == steady_evening);
  int changed = 0;
  for (std::size_t k = 0; k < moving_noon.size(); ++k) changed += moving_noon[k] != moving_evening[k];
  CHECK(changed > int(moving_noon.size()) / 2);
  CHECK(moving_noon != steady_noon);
}

TEST_CASE("tone mapping encodes black as 0 and saturates to 1 without exceeding it", "[fast][render]") {
  core::ImageData hdr{3, 1, 4, {0, 0, 0, 0, 0.1f, 0.1f, 0.1f, 0, 1e6f, 1e6f, 1e6f, 1}};
  const auto ldr = render::tone_map(hdr, 4.0);
  CHECK(ldr.channels == 3);
  CHECK(ldr.pixels[0] == 0.0f);
  CHECK(ldr.pixels[3] > 0.0f);
  CHECK(ldr.pixels[3] < 1.0f);
  CHECK(ldr.pixels[6] == Approx(1.0f).epsilon(0).margin(kSaturatedEncoding));
  CHECK(ldr.pixels[6] <= 1.0f);
}

TEST_CASE("pixels whose loops reach llvmpipe's iteration limit are counted and ordinary settings stay below it",
          "[render][extreme]") {
  test::test_context();
  // A thin veil overhead everywhere keeps the transmittance near 1, so no ray ends early.
  std::vector<CloudLayer> veil = {{CloudType::cirrostratus, CoverageChannel::high, 8500, 9500, 1e-7f, 0, 0, 0, "test"}};
  const WeatherField field = uniform_field(0, 0, 1.0f);
  auto camera = small_camera(45);
  camera.width = 4;
  camera.height = 4;
  const auto ordinary = render::render_clouds(camera, veil, field, noon, quick());  // a few hundred
  CHECK(ordinary.loop_limited_pixels == 0u);
  // 4096 coarse steps, two sub-steps of 1 + 256 + 3 iterations each where the veil is: every
  // pixel needs millions of iterations. llvmpipe counts iterations per SIMD vector of pixels and
  // cuts the whole vector at 65535, so a pixel's own count is a lower bound of the vector's: at
  // least one pixel of each cut vector reaches the limit by its own count, the others may not.
  render::RenderSettings heavy = quick();
  heavy.view_steps = 4096;
  heavy.light_steps = 256;
  const auto r = render::render_clouds(camera, veil, field, noon, heavy);
  CHECK(r.loop_limited_pixels >= 1u);
  CHECK(r.loop_limited_pixels <= static_cast<unsigned>(camera.width * camera.height));  // every pixel
  CHECK(stats(r).finite);
  // The pixels are named too, one bit each (one frame: each counted once).
  unsigned named = 0;
  for (int y = 0; y < camera.height; ++y)
    for (int x = 0; x < camera.width; ++x) named += r.loop_limited(x, y) ? 1u : 0u;
  CHECK(named == r.loop_limited_pixels);
  for (int y = 0; y < camera.height; ++y)
    for (int x = 0; x < camera.width; ++x) CHECK_FALSE(ordinary.loop_limited(x, y));
}

TEST_CASE("renders that share a noise volume give the image of their own volume and build no second one", "[render]") {
  test::test_context();
  std::vector<CloudLayer> layers = {{CloudType::cumulus, CoverageChannel::low, 1500, 3000, 1e-2f, 0, 0, 0, "test"}};
  const WeatherField field = uniform_field(0.6f, 0, 0);
  const render::RenderSettings settings = quick();
  const render::NoiseVolume noise(settings.noise_size, settings.seed);
  const auto own = render::render_clouds(small_camera(), layers, field, noon, settings);
  const auto shared = render::render_clouds(small_camera(), layers, field, noon, settings, {0, 1}, 0, &noise);
  // The same shader on the same deterministic volume: bit for bit.
  CHECK(shared.radiance.pixels == own.radiance.pixels);
  CHECK(contains(own.passes, "noise_volume"));
  CHECK_FALSE(contains(shared.passes, "noise_volume"));
  render::RenderSettings other_seed = settings;
  other_seed.seed = settings.seed + 1;
  CHECK_THROWS_AS(render::render_clouds(small_camera(), layers, field, noon, other_seed, {0, 1}, 0, &noise),
                  std::logic_error);
}

TEST_CASE("averaging frames with shifted march jitter brings the image closer to the converged one",
          "[render][frames]") {
  test::test_context();
  std::vector<CloudLayer> layers = {{CloudType::cumulus, CoverageChannel::low, 1500, 3000, 1e-2f, 0, 0, 0, "test"}};
  render::Camera camera = small_camera(20);
  camera.width = 48;
  camera.height = 27;
  const WeatherField field = uniform_field(0.6f, 0, 0);
  render::RenderSettings coarse = quick();
  coarse.view_steps = 4;
  render::RenderSettings reference = coarse;
  reference.view_steps = 96;
  reference.light_steps = 3;
  const render::NoiseVolume noise(coarse.noise_size, coarse.seed);
  const auto converged =
      render::render_clouds(camera, layers, field, noon, reference, {0, 1}, 0, &noise).radiance.pixels;
  auto rms = [&](int frames) {
    render::RenderSettings s = coarse;
    s.frames = frames;
    const auto r = render::render_clouds(camera, layers, field, noon, s, {0, 1}, 0, &noise);
    if (frames > 1) CHECK(contains(r.passes, "accumulate " + std::to_string(frames) + " frames"));
    double sum = 0;
    for (size_t k = 0; k < converged.size(); ++k)
      if (k % 4 != 3) sum += std::pow(r.radiance.pixels[k] - converged[k], 2);
    return std::sqrt(sum / (converged.size() * 3 / 4));
  };
  // The marcher's 4 coarse steps misplace the cloud edges by up to a step; N frames spread each
  // pixel's sample offsets over [0, 1) (golden-ratio recurrence), so the average approaches the
  // integral over the offsets, which the 96-step reference approximates: error must fall.
  const double one = rms(1), four = rms(4), sixteen = rms(16);
  INFO("RMS radiance error: 1 frame " << one << ", 4 frames " << four << ", 16 frames " << sixteen);
  CHECK(one > 0.0);
  CHECK(four < one);
  CHECK(sixteen < four);
}

TEST_CASE("the powder term darkens clouds seen with the sun behind, and at strength 0 changes nothing", "[render]") {
  // P = 1 - k (1 - nu)/2 exp(-2 tau): 1 at k = 0 (the same bits), 1 - k for a sun-facing
  // surface (tau 0) seen with the sun straight behind (nu = -1), 1 looking into the sun.
  CHECK(glsl::powder_factor(0.7f, -0.3f, 0.0f) == 1.0f);
  CHECK(glsl::powder_factor(0.0f, -1.0f, 0.6f) == Approx(0.4f).margin(1e-6));
  CHECK(glsl::powder_factor(0.0f, 1.0f, 1.0f) == 1.0f);
  CHECK(glsl::powder_factor(5.0f, -1.0f, 1.0f) == Approx(1.0 - std::exp(-10.0)).margin(1e-6));
  test::test_context();
  Scene scene = small_summer_scene(32, 18);
  const auto stations = io::read_scene_weather(scene);
  // Mean radiance of the cloudy pixels (opacity above 1/2) with and without the term.
  auto cloud_radiance = [&](double heading, double powder) {
    Scene s = scene;
    s.heading_deg = heading;
    s.powder = powder;
    const auto r = render::render_scene(s, stations, nullptr).render.radiance;
    double sum = 0;
    int count = 0;
    for (std::size_t k = 0; k < r.pixels.size(); k += 4)
      if (r.pixels[k + 3] > 0.5f) sum += r.pixels[k] + r.pixels[k + 1] + r.pixels[k + 2], ++count;
    REQUIRE(count > 0);
    return sum / count;
  };
  // At 15:00 UTC on 21 June the sun stands in the west-south-west over Bern (azimuth about 255
  // degrees): heading 75 has it behind, heading 255 ahead.
  const double away_off = cloud_radiance(75, 0), away_on = cloud_radiance(75, 1);
  const double into_off = cloud_radiance(255, 0), into_on = cloud_radiance(255, 1);
  INFO("sun behind: " << away_off << " -> " << away_on << "; sun ahead: " << into_off << " -> " << into_on);
  CHECK(away_on < away_off);
  // Looking towards the sun the weight (1 - nu)/2 is small: the clouds lose relatively less.
  CHECK(1 - into_on / into_off < 1 - away_on / away_off);
}
