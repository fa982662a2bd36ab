#include "render/scene_renderer.hpp"

#include "render/upsample.hpp"

#include <GeographicLib/LocalCartesian.hpp>

#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <stdexcept>
#include <utility>

#include "cover/global_cover.hpp"
#include "regional/sites.hpp"
#include "regional/weather_field.hpp"
#include "core/time.hpp"
#include "render/sun_position.hpp"

namespace nephele::render {
namespace {

constexpr int field_size = 64;
constexpr double field_extent_m = 160000.0;
// A field from the global cover is finer: 1.25 km texels carry the orbit view's sub-texel cloud
// (cloud_properties.glsl) down to a few km, so that the layers' clouds stand where the orbit view
// draws its own (the Webanck forms' cells fill in below that); 5 km texels left only the share.
constexpr int cover_field_size = 256;
constexpr double look_ahead_hours = 168.0;  // the original system looked up to 7 days ahead

regional::LayerRules layer_rules(const regional::Scene& scene) {
  regional::LayerRules rules;
  rules.fog_top_m = scene.fog_top_m;
  return rules;
}

}  // namespace

GlobalCoverFaces make_global_cover(const cover::CoverParameters& parameters) {
  cover::GlobalCover cover(parameters);
  cover.run();
  return {parameters.size, cover.cover_field().read(), cover.optical_thickness_field().read(),
          cover.cloud_top_field().read()};
}

cover::CoverParameters view_cover_parameters(int size, std::uint32_t seed, const std::string& flow,
                                             const std::string& time,
                                             std::shared_ptr<const cover::SurfaceMask> surface) {
  cover::CoverParameters parameters;
  parameters.surface = std::move(surface);
  parameters.size = size;
  parameters.seed = seed;
  const std::optional<cover::Flow> kind = cover::parse_flow(flow);
  if (!kind) throw std::invalid_argument("view_cover_parameters: '" + flow + "' is not a flow");
  parameters.flow = *kind;
  parameters.time = time;
  return parameters;
}

cover::CoverParameters scene_cover_parameters(const regional::Scene& scene,
                                              std::shared_ptr<const cover::SurfaceMask> surface) {
  return view_cover_parameters(scene.cover_size, scene.seed, scene.cover_flow, scene.time, std::move(surface));
}

PreparedScene prepare_scene(const regional::Scene& scene, const std::vector<regional::WeatherSeries>& weather,
                            std::shared_ptr<const cover::SurfaceMask> surface) {
  if (!weather.empty()) return prepare_scene(scene, weather, GlobalCoverFaces{});
  PreparedScene prepared =
      prepare_scene(scene, weather, make_global_cover(scene_cover_parameters(scene, std::move(surface))));
  prepared.partial.passes.insert(prepared.partial.passes.begin(), "global_cover");
  return prepared;
}

Camera scene_camera(const regional::Scene& scene) {
  Camera c;
  if (!scene.latitude_deg) {
    // The viewpoint's place, eye height 2 m above the summit, and its heading unless given.
    const auto viewpoint = regional::find_viewpoint(scene.view);
    c.latitude_deg = viewpoint->site.latitude_deg;
    c.longitude_deg = viewpoint->site.longitude_deg;
    c.height_m = viewpoint->site.elevation_m + 2.0;
    c.heading_deg = viewpoint->heading_deg;
  }
  // The position (--at) and heading where given, pitch and fov, through the table.
  regional::Scene source = scene;
  params::copy_bound_fields(regional::field_bindings(source), field_bindings(c));
  c.panorama = scene.panorama;
  c.width = scene.width;
  c.height = scene.height;
  return c;
}

PreparedScene prepare_scene(const regional::Scene& scene, const std::vector<regional::WeatherSeries>& weather,
                            const GlobalCoverFaces& cover) {
  if (weather.size() != scene.weather.size())
    throw std::logic_error("prepare_scene: " + std::to_string(weather.size()) + " weather series for " +
                           std::to_string(scene.weather.size()) + " files");
  PreparedScene prepared;
  SceneRender& out = prepared.partial;
  out.camera = scene_camera(scene);
  double anchor_bearing_deg = out.camera.heading_deg;
  const double time = prepared.time = core::parse_utc_time(scene.time);
  const GeographicLib::LocalCartesian frame(out.camera.latitude_deg, out.camera.longitude_deg, 0.0);
  regional::WeatherField& field = prepared.field;
  glm::dvec2& wind = prepared.wind;
  double& wind_speed = prepared.wind_speed;

  if (!weather.empty()) {
    std::vector<regional::Station> stations;
    std::vector<regional::WeatherSample> now;
    std::vector<std::vector<regional::WeatherSample>> ahead;
    size_t nearest = 0;
    double nearest_distance = std::numeric_limits<double>::max();
    for (const regional::WeatherSeries& series : weather) {
      now.push_back(series.at(time));
      ahead.push_back(series.ahead(time, look_ahead_hours));
      stations.push_back(
          {series.latitude_deg, series.longitude_deg, regional::station_coverage(now.back(), ahead.back())});
      const double d = regional::geodesic_distance_m(out.camera.latitude_deg, out.camera.longitude_deg,
                                                     series.latitude_deg, series.longitude_deg);
      if (d < nearest_distance) {
        nearest_distance = d;
        nearest = stations.size() - 1;
      }
    }
    field = regional::field_from_stations(stations, frame, field_size, field_extent_m);
    out.passes.push_back("weather_field (" + std::to_string(stations.size()) + " stations)");
    out.weather_source = "stations";
    // Layer types follow the weather at the viewpoint: its nearest station.
    out.layers = regional::choose_layers(now[nearest], ahead[nearest], layer_rules(scene));
    out.weather_at_camera = now[nearest];
    if (now[nearest].has_wind) {
      const double from = now[nearest].wind_direction_deg * M_PI / 180;
      wind = -glm::dvec2(std::sin(from), std::cos(from));
      wind_speed = now[nearest].wind_speed;
    }
    out.convection_reason = regional::convection_from_weather(now[nearest], ahead[nearest]).reason;
    // Convective clouds stand towards the farthest station whose weather calls for them (its
    // direction from the camera), or about the view's heading when that station is the camera's.
    double farthest = 10000.0;
    for (size_t i = 0; i < weather.size(); ++i) {
      if (regional::convection_from_weather(now[i], ahead[i]).kind == regional::ConvectiveKind::none) continue;
      const regional::Site camera_site{"camera", out.camera.latitude_deg, out.camera.longitude_deg, 0.0};
      const regional::Site station{"station", weather[i].latitude_deg, weather[i].longitude_deg, 0.0};
      const double d = regional::geodesic_distance_m(camera_site.latitude_deg, camera_site.longitude_deg,
                                                     station.latitude_deg, station.longitude_deg);
      if (d > farthest) {
        farthest = d;
        anchor_bearing_deg = regional::geodesic_azimuth_deg(camera_site, station);
      }
    }
  } else {
    if (cover.texels.size() != std::size_t(6) * cover.size * cover.size || cover.size <= 0)
      throw std::logic_error("prepare_scene: a global cover of " + std::to_string(cover.texels.size()) +
                             " texels is not six faces of " + std::to_string(cover.size) + "^2");
    // The fallbacks' log-normal and the sphere are the table's, as the orbit view's
    // (orbit_renderer.cpp).
    const regional::CoverChannels channels{cover.size,
                                           &cover.texels,
                                           &cover.optical_thickness,
                                           &cover.cloud_top,
                                           params::cover::tau_median.default_float(),
                                           params::cover::tau_spread.default_float(),
                                           params::scene::planet_radius_km.default_number * 1000.0};
    field = regional::field_from_cover(channels, frame, cover_field_size, field_extent_m);
    out.passes.push_back("weather_field (global cover)");
    out.weather_source = "global cover";
    out.weather_at_camera = regional::sample_from_field(field, time);
    out.layers = regional::choose_layers(regional::sample_for_layers(field, time), {}, layer_rules(scene));
    regional::add_cover_convection(field, time, out.camera.longitude_deg);
    out.convection_reason =
        regional::convection_from_cover(out.weather_at_camera.cloud_low, time, out.camera.longitude_deg).reason;
  }

  // Convective clouds where the field's convective channel calls for them; their volumes only
  // then (a scene without convection computes none).
  const double wind_towards_deg = std::atan2(wind.x, wind.y) * 180 / M_PI;
  out.convective_clouds = regional::place_convective_clouds(field, anchor_bearing_deg, wind_towards_deg, scene.seed,
                                                            layer_rules(scene).ground_m);
  if (!out.convective_clouds.empty()) {
    prepared.convective = std::make_shared<ConvectiveVolumes>(out.convective_clouds);
    out.passes.insert(out.passes.end(), prepared.convective->passes().begin(), prepared.convective->passes().end());
  }

  return prepared;
}

RenderSettings render_settings(const regional::Scene& scene) {
  RenderSettings settings;
  regional::Scene source = scene;  // bound through a copy: the bindings point into it
  params::copy_bound_fields(regional::field_bindings(source), field_bindings(settings));
  return settings;
}

SceneRender render_prepared(const PreparedScene& prepared, const regional::Scene& scene, const NoiseVolume* noise) {
  return render_prepared(prepared, render_settings(scene), noise);
}

SceneRender render_prepared(const PreparedScene& prepared, const RenderSettings& settings, const NoiseVolume* noise) {
  SceneRender out = prepared.partial;
  RenderSettings with_terrain = settings;
  with_terrain.terrain = prepared.terrain;
  // With a divisor the camera keeps its field of view at fewer pixels (the pixel angle, and so
  // the noise's level of detail, grows with it), and the image is upsampled to the full size.
  const int divisor = std::max(settings.resolution_divisor, 1);
  if (divisor > 1 && settings.march_stride > 1)
    throw std::logic_error(
        "render_prepared: a march stride leaves pixels for reprojection, which upsampling would blur");
  Camera marched = out.camera;
  marched.width = std::max(1, out.camera.width / divisor);
  marched.height = std::max(1, out.camera.height / divisor);
  const bool upsampled = marched.width != out.camera.width || marched.height != out.camera.height;
  if (upsampled) with_terrain.upsample_size = {out.camera.width, out.camera.height};
  out.render = render_clouds(marched, out.layers, prepared.field, prepared.time, with_terrain, prepared.wind,
                             prepared.wind_speed, noise, prepared.convective.get());
  if (upsampled) {
    // Edge-aware, guided by where the full-size rays meet the ground (render/upsample.hpp).
    out.render.radiance =
        upsample_guided(out.render.radiance, out.render.ground_distance, out.render.upsampled_ground_distance);
    out.render.loop_limited_bits.clear();  // they name the marched pixels; the count stays
    out.render.passes.push_back("upsample 1/" + std::to_string(divisor) + " guided by the ground distance");
  }
  out.passes.insert(out.passes.end(), out.render.passes.begin(), out.render.passes.end());
  return out;
}

SceneRender render_scene(const regional::Scene& scene, const std::vector<regional::WeatherSeries>& stations,
                         std::shared_ptr<const cover::SurfaceMask> surface) {
  return render_prepared(prepare_scene(scene, stations, std::move(surface)), scene);
}

}  // namespace nephele::render
