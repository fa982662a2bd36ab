// Convective clouds of the regional scene (docs/convection.md): the rules that call for towering
// cumulus and cumulonimbus, their placement, the weather fields behind them, and their volumes
// in the render (computed only when placed).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/time.hpp"
#include "gl_support.hpp"
#include "io/render_files.hpp"
#include "io/weather_files.hpp"
#include "regional/cloud_layers.hpp"
#include "regional/convection.hpp"
#include "regional/scene.hpp"
#include "render/cloud_renderer.hpp"
#include "render/convective_volumes.hpp"
#include "render/scene_renderer.hpp"

using namespace nephele;
using namespace nephele::regional;

namespace {

WeatherSample unstable(double cape = -1, double lifted_index = 99, int code = -1) {
  WeatherSample s;
  s.cloud_low = 0.3;
  if (cape >= 0) {
    s.has_cape = true;
    s.cape = cape;
  }
  if (lifted_index != 99) {
    s.has_lifted_index = true;
    s.lifted_index = lifted_index;
  }
  if (code >= 0) {
    s.has_weather_code = true;
    s.weather_code = code;
  }
  return s;
}

ConvectiveKind kind(const WeatherSample& s) { return convection_from_weather(s, {}).kind; }

WeatherField uniform_convective_field(float strength) {
  WeatherField f{8, 160000.0, std::vector<float>(static_cast<size_t>(coverage_channels) * 64, 0.0f)};
  std::fill(f.values.begin() + int(CoverageChannel::convective) * 64,
            f.values.begin() + (int(CoverageChannel::convective) + 1) * 64, strength);
  return f;
}

// An Open-Meteo file of one hour at Bern with the given extra hourly fields.
std::string open_meteo(const std::string& extra) {
  return R"({"latitude": 46.948, "longitude": 7.4475, "hourly": {"time": ["2026-06-21T14:00", "2026-06-21T15:00"],
    "cloud_cover": [40, 40], "cloud_cover_low": [30, 30], "cloud_cover_mid": [0, 0], "cloud_cover_high": [0, 0],
    "wind_speed_10m": [10, 10], "wind_direction_10m": [240, 240])" +
         extra + "}}";
}

}  // namespace

TEST_CASE("CAPE, lifted index and thunderstorm codes call for cumulonimbus or towering cumulus on their thresholds",
          "[fast][convection]") {
  // Cumulonimbus: CAPE >= 1000 J/kg, LI <= -2 K, codes 95-99; just below each: towering or none.
  CHECK(kind(unstable(1000)) == ConvectiveKind::cumulonimbus);
  CHECK(kind(unstable(999.9)) == ConvectiveKind::towering);
  CHECK(kind(unstable(250)) == ConvectiveKind::towering);
  CHECK(kind(unstable(249.9)) == ConvectiveKind::none);
  CHECK(kind(unstable(-1, -2.0)) == ConvectiveKind::cumulonimbus);
  CHECK(kind(unstable(-1, -1.9)) == ConvectiveKind::towering);
  CHECK(kind(unstable(-1, 0.0)) == ConvectiveKind::towering);
  CHECK(kind(unstable(-1, 0.1)) == ConvectiveKind::none);
  for (int code : {95, 96, 99}) CHECK(kind(unstable(-1, 99, code)) == ConvectiveKind::cumulonimbus);
  for (int code : {0, 3, 82, 94}) CHECK(kind(unstable(-1, 99, code)) == ConvectiveKind::none);
  // Any one index is enough; with the indices present, rain alone (frontal) calls for nothing.
  CHECK(kind(unstable(0, 5.0, 95)) == ConvectiveKind::cumulonimbus);
  WeatherSample frontal = unstable(0);
  frontal.precipitation = 8;
  CHECK(kind(frontal) == ConvectiveKind::none);
  CHECK(convection_from_weather(unstable(1500), {}).reason.find("cape") != std::string::npos);
}

TEST_CASE("without weather, convection comes from the low cover in the afternoon of local solar time only",
          "[fast][convection]") {
  // 7.5 degrees east: solar time = UTC + 30 min. 11:29 UTC is 11:59 solar, 11:30 UTC 12:00.
  const double day = core::parse_utc_time("2026-06-21T00:00Z");
  auto at = [&](double low, double utc_hours) { return convection_from_cover(low, day + utc_hours * 3600, 7.5).kind; };
  CHECK(at(0.9, 11.0 + 29.0 / 60) == ConvectiveKind::none);
  CHECK(at(0.9, 11.5) == ConvectiveKind::cumulonimbus);
  CHECK(at(0.9, 18.0 + 29.0 / 60) == ConvectiveKind::cumulonimbus);
  CHECK(at(0.9, 18.5) == ConvectiveKind::none);
  CHECK(at(0.75, 15) == ConvectiveKind::cumulonimbus);
  CHECK(at(0.74, 15) == ConvectiveKind::towering);
  CHECK(at(0.5, 15) == ConvectiveKind::towering);
  CHECK(at(0.49, 15) == ConvectiveKind::none);
  // The convective channel of a cover field follows the low channel texel by texel.
  WeatherField f = uniform_convective_field(0.0f);
  for (int k = 0; k < 64; ++k) f.values[int(CoverageChannel::low) * 64 + k] = k < 32 ? 0.8f : 0.2f;
  add_cover_convection(f, day + 15 * 3600, 7.5);
  CHECK(f.at(int(CoverageChannel::convective), 0, 0) == 1.0f);
  CHECK(f.at(int(CoverageChannel::convective), 0, 7) == 0.0f);
  add_cover_convection(f, day + 9 * 3600, 7.5);
  CHECK(f.max_of(int(CoverageChannel::convective)) == 0.0f);
}

TEST_CASE("blended convective strengths place cumulonimbus from 0.75 and towering cumulus from 0.25",
          "[fast][convection]") {
  CHECK(kind_of_strength(convective_strength(ConvectiveKind::cumulonimbus)) == ConvectiveKind::cumulonimbus);
  CHECK(kind_of_strength(convective_strength(ConvectiveKind::towering)) == ConvectiveKind::towering);
  CHECK(kind_of_strength(0.75) == ConvectiveKind::cumulonimbus);
  CHECK(kind_of_strength(0.7499) == ConvectiveKind::towering);
  CHECK(kind_of_strength(0.25) == ConvectiveKind::towering);
  CHECK(kind_of_strength(0.2499) == ConvectiveKind::none);
  // Halfway between a cumulonimbus station and a quiet one: towering cumulus.
  CHECK(kind_of_strength(0.5 * (convective_strength(ConvectiveKind::cumulonimbus) + 0.0)) == ConvectiveKind::towering);
}

TEST_CASE(
    "placement is deterministic from the seed, in the sector of the anchor, clear of each other, and empty without "
    "convection",
    "[fast][convection]") {
  CHECK(place_convective_clouds(uniform_convective_field(0.0f), 12, 60, 1, 540).empty());
  CHECK(place_convective_clouds(uniform_convective_field(0.2f), 12, 60, 1, 540).empty());
  const auto a = place_convective_clouds(uniform_convective_field(1.0f), 12, 60, 7, 540);
  const auto b = place_convective_clouds(uniform_convective_field(1.0f), 12, 60, 7, 540);
  const auto other = place_convective_clouds(uniform_convective_field(1.0f), 12, 60, 8, 540);
  REQUIRE(!a.empty());
  CHECK(static_cast<int>(a.size()) <= convection::max_clouds);
  REQUIRE(a.size() == b.size());
  bool differs = other.size() != a.size();
  for (size_t i = 0; i < a.size(); ++i) {
    CHECK(a[i].east_m == b[i].east_m);
    CHECK(a[i].north_m == b[i].north_m);
    CHECK(a[i].extent_m == b[i].extent_m);
    if (i < other.size() && other[i].east_m != a[i].east_m) differs = true;
  }
  CHECK(differs);
  for (size_t i = 0; i < a.size(); ++i) {
    const ConvectiveCloud& c = a[i];
    INFO("cloud " << i);
    CHECK(c.kind == ConvectiveKind::cumulonimbus);
    const double distance = std::hypot(c.east_m, c.north_m);
    CHECK(distance >= convection::nearest_m);
    CHECK(distance <= convection::farthest_m);
    double bearing = std::atan2(c.east_m, c.north_m) * 180 / M_PI - 12;
    CHECK(std::abs(bearing) <= convection::spread_deg + 1e-9);
    // The scaled example reaches from the cumulonimbus base to the tropopause (+-10 %).
    CHECK(c.cloud_base_m == Approx(540 + convection::cumulonimbus_base_above_ground));
    CHECK(c.cloud_top_m >= 0.9 * convection::cumulonimbus_top - 1e-6);
    CHECK(c.cloud_top_m <= 1.1 * convection::cumulonimbus_top + 1e-6);
    CHECK(c.model.extent_m == c.extent_m);
    CHECK(c.axis_deg == 60);
    for (size_t j = 0; j < i; ++j)
      CHECK(std::hypot(a[j].east_m - c.east_m, a[j].north_m - c.north_m) >=
            0.5 * (a[j].extent_m + c.extent_m) * std::sqrt(2.0));
  }
  // Half strength: towering cumulus, based at the cumulus base of the layer rules.
  const auto towers = place_convective_clouds(uniform_convective_field(0.5f), 12, 60, 7, 540);
  REQUIRE(!towers.empty());
  for (const auto& c : towers) {
    CHECK(c.kind == ConvectiveKind::towering);
    CHECK(c.cloud_base_m == Approx(540 + convection::towering_base_above_ground));
  }
}

TEST_CASE("weather files give cape, lifted_index and weather_code when present and refuse bad values naming the field",
          "[fast][convection][weather][bad-input]") {
  const WeatherSeries w = io::parse_weather(
      open_meteo(R"(, "cape": [400, 1600], "lifted_index": [1, -3], "weather_code": [3, 95])"), "bern.json");
  const double t = core::parse_utc_time("2026-06-21T14:30Z");
  const WeatherSample half = w.at(t);
  CHECK(half.has_cape);
  CHECK(half.cape == Approx(1000));
  CHECK(half.lifted_index == Approx(-1));
  CHECK(half.weather_code == 3);  // the earlier hour's at half past
  CHECK(w.at(t + 60).weather_code == 95);
  const WeatherSample plain = io::parse_weather(open_meteo(""), "plain.json").hours[0];
  CHECK_FALSE(plain.has_cape);
  CHECK_FALSE(plain.has_lifted_index);
  CHECK_FALSE(plain.has_weather_code);
  const std::pair<std::string, std::string> bad[] = {
      {R"(, "cape": [-1, 0])", "hourly.cape[0]: -1 is outside the allowed range 0 to 10000"},
      {R"(, "cape": [0, 10001])", "hourly.cape[1]"},
      {R"(, "cape": [0, null])", "hourly.cape[1]: missing value"},
      {R"(, "cape": [0])", "hourly.cape: has 1 values"},
      {R"(, "lifted_index": [-31, 0])", "hourly.lifted_index[0]: -31 is outside the allowed range -30 to 50"},
      {R"(, "weather_code": [100, 0])", "hourly.weather_code[0]: 100 is outside the allowed range 0 to 99"},
      {R"(, "weather_code": [95.5, 0])", "hourly.weather_code[0]: must be an integer code of WMO table 4677"},
      {R"(, "weather_code": "95")", "hourly.weather_code: must be an array"},
  };
  for (const auto& [extra, expected] : bad) {
    INFO(extra);
    std::string message;
    try {
      io::parse_weather(open_meteo(extra), "bern.json");
    } catch (const WeatherError& e) {
      message = e.what();
    }
    CHECK_THAT(message, Catch::StartsWith("bern.json: ") && Catch::Contains(expected));
  }
}

TEST_CASE("a scene without convection computes no convective volume and one with convection computes them",
          "[convection][render]") {
  test::test_context();
  Scene scene;
  scene.width = 16;
  scene.height = 8;
  scene.view_steps = 4;
  scene.light_steps = 2;
  scene.sky_steps = 4;
  scene.time = "2026-06-21T14:00Z";
  scene.weather = {"bern.json"};
  auto passes_with = [&](const std::string& cape) {
    const WeatherSeries w = io::parse_weather(open_meteo(R"(, "cape": )" + cape), "bern.json");
    render::PreparedScene prepared = render::prepare_scene(scene, {w}, nullptr);
    const render::SceneRender r = render::render_prepared(prepared, scene);
    return std::make_pair(r, prepared.convective != nullptr);
  };
  auto count = [](const std::vector<std::string>& passes, const std::string& prefix) {
    return std::count_if(passes.begin(), passes.end(), [&](const std::string& p) { return p.rfind(prefix, 0) == 0; });
  };
  const auto [quiet, quiet_volumes] = passes_with("[100, 100]");
  CHECK_FALSE(quiet_volumes);
  CHECK(quiet.convective_clouds.empty());
  CHECK(count(quiet.passes, "convective_volume") == 0);
  CHECK(count(quiet.passes, "march convective") == 0);
  const auto [storm, storm_volumes] = passes_with("[2000, 2000]");
  CHECK(storm_volumes);
  REQUIRE(!storm.convective_clouds.empty());
  CHECK(count(storm.passes, "convective_volume cumulonimbus 128^3") ==
        static_cast<long>(storm.convective_clouds.size()));
  CHECK(count(storm.passes, "march convective cumulonimbus") == static_cast<long>(storm.convective_clouds.size()));
  CHECK(storm.convection_reason.find("cape >= 1000") != std::string::npos);
  // The render sidecar says why and where: one entry per placed cloud, none without convection.
  const nephele::json::Value storm_sidecar = io::scene_sidecar(storm, scene);
  const auto& listed = storm_sidecar.at("convection").at("clouds").as_array();
  REQUIRE(listed.size() == storm.convective_clouds.size());
  CHECK(listed.front().at("kind").as_string() == "cumulonimbus");
  CHECK(listed.front().at("cloud_top_m").as_number() == storm.convective_clouds.front().cloud_top_m);
  CHECK(storm_sidecar.at("convection").at("reason").as_string() == storm.convection_reason);
  CHECK(io::scene_sidecar(quiet, scene).at("convection").at("clouds").as_array().empty());
}

TEST_CASE("a pixel towards a placed cumulonimbus's column is opaque, and clear sky without it",
          "[convection][render]") {
  test::test_context();
  // One cumulonimbus (the scaled example) 25 km north of a camera at 860 m, its x axis north.
  auto clouds = place_convective_clouds(uniform_convective_field(1.0f), 0, 0, 3, 540);
  REQUIRE(!clouds.empty());
  ConvectiveCloud cb = clouds.front();
  cb.east_m = 0;
  cb.north_m = 25000;
  cb.axis_deg = 0;
  // The column: the segment (0.45, 0.5, 0.10)-(0.48, 0.5, 0.70) of radius 0.10 in model units.
  // Aim at its axis at z = 0.4 (x = 0.465): north 25000 + (0.465 - 0.5) extent, up from the
  // camera to bottom + 0.4 extent, less the Earth's curvature d^2 / 2R.
  const double north = cb.north_m + (0.465 - 0.5) * cb.extent_m;
  const double rise = cb.bottom_m + 0.4 * cb.extent_m - 860 + north * north / (2 * 6371000.0);
  render::Camera camera;
  camera.latitude_deg = 46.91722;
  camera.longitude_deg = 7.44361;
  camera.height_m = 860;
  camera.heading_deg = 0;
  camera.pitch_deg = std::atan2(rise, north) * 180 / M_PI;
  camera.fov_deg = 2;
  camera.width = camera.height = 9;  // the centre pixel looks along the axis
  render::RenderSettings settings;
  settings.view_steps = 48;
  settings.light_steps = 4;
  settings.sky_steps = 4;
  settings.noise_size = 16;
  const WeatherField clear{4, 160000.0, std::vector<float>(static_cast<size_t>(coverage_channels) * 16, 0.0f)};
  const double noon = core::parse_utc_time("2026-06-21T11:30Z");
  const render::ConvectiveVolumes volumes({cb});
  const auto with = render::render_clouds(camera, {}, clear, noon, settings, {0, 1}, 0, nullptr, &volumes);
  const auto without = render::render_clouds(camera, {}, clear, noon, settings);
  const size_t centre = (4 * 9 + 4) * 4;
  // Within the column's radius the field is 1 and per-primitive turbulence keeps at least
  // (1 - np) = 0.5 of it (N >= 0); Lipus's blend never lowers a density. Extinction
  // 0.075 x 0.5 /m over a chord of at least 2 (0.10 extent - a voxel diagonal) = 1.8 km:
  // optical depth >= 68, and the marcher stops at T <= 0.01: alpha >= 0.99.
  CHECK(with.radiance.pixels[centre + 3] >= 0.99f);
  CHECK(without.radiance.pixels[centre + 3] == 0.0f);
  // The cloud, not the sky behind it, gives the pixel its colour.
  CHECK(with.radiance.pixels[centre] != without.radiance.pixels[centre]);
  CHECK(std::find(with.passes.begin(), with.passes.end(), "march convective cumulonimbus") != with.passes.end());
}
