// Weather files, their validation, blending between stations and the layer rules.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include <GeographicLib/Geodesic.hpp>
#include <GeographicLib/GeodesicLine.hpp>

#include "io/scene_files.hpp"
#include "io/weather_files.hpp"
#include "core/time.hpp"
#include "regional/cloud_layers.hpp"
#include "regional/weather.hpp"
#include "regional/weather_field.hpp"
#include "render/sun_position.hpp"
#include "shader_math/shader_math.hpp"

using namespace nephele;
using namespace nephele::regional;

namespace {

// Directions 350 and 10 deg averaged through the wind vector: the angles in radians (6.1 and
// 0.17) are rounded by up to 2^-53 x 6.1 = 6.8e-16, so sin(350 deg) + sin(10 deg) leaves about
// 1e-15, an angle of 1e-15 rad = 6e-14 deg from north. 1e-6 deg is far looser (kept as set).
constexpr double kWindDirectionDeg = 1e-6;
static_assert(kWindDirectionDeg >= 1e-15 * 180 / M_PI);
// Inverse-distance weights of two stations at a point a fraction f along their geodesic are
// exactly 1 - f and f (w_0 = d_1 / (d_0 + d_1)). GeographicLib's geodesics are accurate to 15 nm,
// so the weights (d / L with L = 33 km) are within about 2 x 15 nm / 33 km = 1e-12, and a few
// double roundings; 1e-6 is far looser (kept as set).
constexpr double kStationWeight = 1e-6;
static_assert(kStationWeight >= 2 * 15e-9 / 33000);

std::string open_meteo(const std::string& low = "[10, 20, 30]", const std::string& extra = "") {
  return R"({"latitude": 46.95, "longitude": 7.45, "utc_offset_seconds": 0,
    "hourly_units": {"wind_speed_10m": "km/h"},
    "hourly": {"time": ["2026-06-21T00:00", "2026-06-21T01:00", "2026-06-21T02:00"],
      "cloud_cover": [50, 60, 70], "cloud_cover_low": )" +
         low + R"(,
      "cloud_cover_mid": [0, 0, 0], "cloud_cover_high": [5, 5, 5], "precipitation": [0, 0.5, 1],
      "wind_speed_10m": [36, 36, 36], "wind_direction_10m": [350, 10, 30])" +
         extra + "}}";
}

std::string error_of(const std::string& text) {
  try {
    io::parse_weather(text, "test.json");
  } catch (const WeatherError& e) {
    return e.what();
  }
  return "";
}

WeatherSample sample(double low, double mid, double high, double rain = 0, double wind = 5) {
  WeatherSample s;
  s.cloud_low = low;
  s.cloud_mid = mid;
  s.cloud_high = high;
  s.precipitation = rain;
  s.has_wind = true;
  s.wind_speed = wind;
  return s;
}

bool has(const std::vector<CloudLayer>& layers, CloudType type) {
  for (const auto& l : layers)
    if (l.type == type) return true;
  return false;
}

}  // namespace

TEST_CASE("Open-Meteo hourly data are read with units converted and interpolated in time", "[fast][weather]") {
  const WeatherSeries w = io::parse_weather(open_meteo(), "bern.json");
  CHECK(w.format == "open-meteo");
  REQUIRE(w.hours.size() == 3);
  CHECK(w.hours[1].cloud_low == Approx(0.2));
  CHECK(w.hours[0].wind_speed == Approx(10.0));  // 36 km/h
  const WeatherSample half = w.at(core::parse_utc_time("2026-06-21T00:30Z"));
  CHECK(half.cloud_low == Approx(0.15));
  CHECK(half.precipitation == Approx(0.25));
  // Directions 350 and 10 average to north through the wind vector, not to 180.
  CHECK(std::min(half.wind_direction_deg, 360 - half.wind_direction_deg) < kWindDirectionDeg);
}

TEST_CASE("meteoblue data are read from data_1h with the metadata position", "[fast][weather]") {
  const WeatherSeries w =
      io::read_weather_file(std::string(NEPHELE_SOURCE_DIR) + "/scenes/weather/fribourg-meteoblue.json");
  CHECK(w.format == "meteoblue");
  CHECK(w.latitude_deg == Approx(46.8));
  CHECK(w.hours.front().cloud_mid == Approx(0.7));
  CHECK(w.hours.front().wind_speed == Approx(4.0));
}

TEST_CASE("bad weather input names the file and the field", "[fast][weather]") {
  CHECK_THAT(error_of(open_meteo("[10, null, 30]")),
             Catch::Contains("test.json") && Catch::Contains("cloud_cover_low[1]"));
  CHECK_THAT(error_of(open_meteo("[10, 120, 30]")),
             Catch::Contains("cloud_cover_low[1]") && Catch::Contains("0 to 100"));
  CHECK_THAT(error_of(open_meteo("[10, 20]")), Catch::Contains("cloud_cover_low") && Catch::Contains("'time' has 3"));
  CHECK_THAT(error_of(R"({"latitude": 1, "longitude": 2, "hourly": {"time": ["2026-06-21T00:00"]}})"),
             Catch::Contains("hourly.cloud_cover") && Catch::Contains("missing"));
  CHECK_THAT(error_of("{\"hourly\": 3"), Catch::Contains("not valid JSON"));
  CHECK_THAT(error_of(R"({"a": 1})"), Catch::Contains("neither an Open-Meteo file"));
  const WeatherSeries w = io::parse_weather(open_meteo(), "bern.json");
  try {
    w.at(core::parse_utc_time("2026-06-22T00:00Z"));
    FAIL("no error");
  } catch (const WeatherError& e) {
    CHECK_THAT(e.what(), Catch::Contains("outside the file's range") && Catch::Contains("2026-06-21T02:00Z"));
  }
}

TEST_CASE("UTC offsets beyond 18 hours are refused naming the key, the value and the range", "[fast][weather]") {
  std::string text = open_meteo();
  text.replace(text.find("\"utc_offset_seconds\": 0"), 23, "\"utc_offset_seconds\": 1e300");
  CHECK_THAT(error_of(text),
             Catch::Contains("utc_offset_seconds") && Catch::Contains("1e+300") && Catch::Contains("-64800 to 64800"));
  const std::string meteoblue = R"({"metadata": {"latitude": 0, "longitude": 0, "utc_timeoffset": -19},
    "data_1h": {"time": ["2026-06-21 00:00"], "totalcloudcover": [1], "lowclouds": [1], "midclouds": [1],
    "highclouds": [1]}})";
  CHECK_THAT(error_of(meteoblue),
             Catch::Contains("metadata.utc_timeoffset") && Catch::Contains("-19") && Catch::Contains("-18 to 18"));
}

TEST_CASE("station weights give a station's own data there and the linear blend between two", "[fast][weather]") {
  const std::vector<Station> stations = {{46.94806, 7.44750, {}}, {47.20833, 7.53722, {}}};
  const auto at_first = station_weights(stations, 46.94806, 7.44750);
  CHECK(at_first[0] == 1.0);
  CHECK(at_first[1] == 0.0);
  // Points a quarter and a half of the way along the geodesic from Bern to Solothurn.
  const GeographicLib::GeodesicLine line =
      GeographicLib::Geodesic::WGS84().InverseLine(46.94806, 7.44750, 47.20833, 7.53722);
  for (double fraction : {0.25, 0.5, 0.8}) {
    double lat = 0, lon = 0;
    line.Position(fraction * line.Distance(), lat, lon);
    const auto w = station_weights(stations, lat, lon);
    CHECK(w[0] == Approx(1 - fraction).epsilon(0).margin(kStationWeight));
    CHECK(w[1] == Approx(fraction).epsilon(0).margin(kStationWeight));
  }
}

TEST_CASE("the layer rules pick types from the current and coming weather", "[fast][layers]") {
  CHECK(choose_layers(sample(0, 0, 0), {}).empty());  // clear sky: nothing to march
  CHECK(has(choose_layers(sample(0.3, 0, 0), {}), CloudType::cumulus));
  CHECK(has(choose_layers(sample(0.7, 0, 0), {}), CloudType::stratocumulus));
  CHECK(has(choose_layers(sample(0.95, 0, 0), {}), CloudType::stratus));
  CHECK(has(choose_layers(sample(0, 0, 0.3), {}), CloudType::cirrocumulus));
  CHECK(has(choose_layers(sample(0, 0, 0.8), {}), CloudType::cirrostratus));
  CHECK(has(choose_layers(sample(0.5, 0.5, 0.6), {}), CloudType::cirrus));
  // Calm, dry and fully overcast low: ground fog instead of a low cloud layer.
  const auto foggy = choose_layers(sample(1.0, 0, 0, 0, 1.0), {});
  CHECK(has(foggy, CloudType::fog));
  CHECK_FALSE(has(foggy, CloudType::stratus));
  // Mid cover rising within 12 h turns cirrus into a warm-front veil.
  WeatherSample later = sample(0, 0.9, 0.4);
  later.time = 6 * 3600;
  const auto veil = choose_layers(sample(0, 0.1, 0.4), {later});
  CHECK(has(veil, CloudType::cirrostratus));
  // Altocumulus for broken mid cover, altostratus for overcast; rain ahead halves k.
  const auto broken = choose_layers(sample(0, 0.3, 0), {});
  const auto overcast = choose_layers(sample(0, 0.95, 0), {});
  REQUIRE(broken.size() == 1);
  REQUIRE(overcast.size() == 1);
  CHECK(broken[0].morph == Approx(1.0));
  CHECK(overcast[0].morph == Approx(0.0));
  WeatherSample rain_soon = sample(0, 0.3, 0, 1.0);
  rain_soon.time = 3 * 3600;
  CHECK(choose_layers(sample(0, 0.3, 0), {rain_soon})[0].morph == Approx(0.5));
}

TEST_CASE("rain under thick mid cloud gives the nimbostratus substitute, and showers convection but no layer",
          "[fast][layers]") {
  const auto ns = choose_layers(sample(0.3, 0.9, 0, 2.0), {});
  const CloudLayer* alto = nullptr;
  for (const auto& l : ns)
    if (l.type == CloudType::alto) alto = &l;
  REQUIRE(alto);
  CHECK(alto->darkness > 0.0f);
  CHECK(alto->top_m - alto->base_m > 2000.0f);
  CHECK(has(ns, CloudType::stratus));
  CHECK(has(ns, CloudType::fog));
  // Cumulonimbus is no layer any more (the convective models, docs/convection.md): showers of
  // 2 mm/h or more within 6 h, in a file without instability indices, put the full strength of
  // a cumulonimbus into the convective channel; 1.9 mm/h none.
  WeatherSample storm = sample(0.2, 0, 0, 6.0);
  storm.time = 4 * 3600;
  CHECK(station_coverage(sample(0.2, 0, 0), {storm}).channel[int(CoverageChannel::convective)] == 1.0);
  CHECK(station_coverage(sample(0.2, 0, 0, 2.0), {}).channel[int(CoverageChannel::convective)] == 1.0);
  CHECK(station_coverage(sample(0.2, 0, 0, 1.9), {}).channel[int(CoverageChannel::convective)] == 0.0);
}

TEST_CASE("the cover under a point of the regional field is the cover at its latitude on the sphere",
          "[fast][weather]") {
  // A cover that grows linearly with the latitude of each texel's direction, 20 per radian
  // (0.5 at 46.95 N): the field must read it at the direction (cos lat cos lon, cos lat sin lon,
  // sin lat), as the orbit view draws the cover. The ellipsoid's normal at Bern points 0.19
  // degrees further south, which would read 20 x 0.0033 = 0.066 less. The cubic B-spline filter of
  // 512-texel faces errs by about f'' h^2 / 6 (its kernel's variance h^2 / 3; h = 0.0031 rad, f''
  // of the order of the slope): 3e-5; the floats' rounding is smaller still, so 0.005 separates the two. The field's
  // texels (12.5 km) span more than half a cover texel (19.6 km), where the sub-texel field draws the cover's own
  // value, and cloud of this cover (tops at 3 km, tau 2-9) has its base below 2.5 km: all of it is in the low channel.
  const int n = 512;
  const double phi0 = 46.95 * M_PI / 180, slope = 20.0;
  std::vector<float> cover(std::size_t(6) * n * n);
  for (int face = 0; face < 6; ++face)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const glsl::vec3 r =
            glsl::normalize(glsl::cube_face_point(face, 2.0f * (i + 0.5f) / n - 1.0f, 2.0f * (j + 0.5f) / n - 1.0f));
        cover[(std::size_t(face) * n + j) * n + i] = float(0.5 + slope * (std::asin(double(r.z)) - phi0));
      }
  const GeographicLib::LocalCartesian frame(46.95, 7.44, 0.0);
  CoverChannels channels;
  channels.size = n;
  channels.cover = &cover;
  channels.tau_median = 4.0f;
  channels.tau_spread = 1.2f;
  channels.planet_radius_m = 6371000.0;
  const WeatherField field = field_from_cover(channels, frame, 16, 100000.0);
  int checked = 0;
  for (int row = 0; row < field.size; ++row)
    for (int column = 0; column < field.size; ++column) {
      double lat = 0, lon = 0;
      ground_position(frame, field.east_of(column), field.north_of(row), lat, lon);
      const double expected = 0.5 + slope * (lat * M_PI / 180 - phi0);
      INFO("row " << row << " column " << column);
      CHECK(field.at(int(CoverageChannel::low), column, row) == Approx(expected).margin(0.005));
      ++checked;
    }
  CHECK(checked == 256);
}

TEST_CASE("a cloud of the cover goes wholly into the channel of its base's level", "[fast][weather]") {
  // cloud_thickness_km: tau 4 (below 3.6 + a little) keeps about 0.3 of the depth above 0.5 km.
  for (const auto& [top, tau] : {std::pair{2.0f, 4.0f}, {3.5f, 4.0f}, {6.0f, 30.0f}, {12.0f, 2.0f}, {9.5f, 80.0f}}) {
    const float base = top - glsl::cloud_thickness_km(top, tau);
    const LevelShares s = level_shares(top, tau);
    INFO("top " << top << " tau " << tau << " base " << base);
    CHECK(s.low + s.mid + s.high == 1.0f);
    CHECK(s.low == (base < 3.0f ? 1.0f : 0.0f));
    CHECK(s.high == (base >= 8.0f ? 1.0f : 0.0f));
  }
}

TEST_CASE("an overcast of the global cover is a stratus deck, not fog round the camera", "[fast][weather]") {
  // A field overcast in the low channel everywhere: a station's sample like it (calm air, no wind
  // given) would be radiation fog; the cover cannot tell fog from low cloud.
  WeatherField field{8, 20000.0, std::vector<float>(std::size_t(coverage_channels) * 64, 0.0f)};
  for (int k = 0; k < 64; ++k) field.values[std::size_t(CoverageChannel::low) * 64 + k] = 1.0f;
  const WeatherSample s = sample_for_layers(field, 0);
  CHECK(s.cloud_low == 1.0);
  CHECK_FALSE(s.may_be_fog);
  const auto layers = choose_layers(s, {}, LayerRules{});
  REQUIRE(layers.size() == 1);
  CHECK(layers[0].type == CloudType::stratus);
  WeatherSample station = s;
  station.may_be_fog = true;
  CHECK(choose_layers(station, {}, LayerRules{}).at(0).type == CloudType::fog);
}
