#include "io/render_files.hpp"

#include <filesystem>

#include "core/file_names.hpp"
#include "files/atomic_output.hpp"
#include "files/image_files.hpp"
#include "nephele/version.hpp"
#include "params/table.hpp"
#include "regional/cloud_layers.hpp"
#include "regional/convection.hpp"

namespace nephele::io {

json::Value scene_sidecar(const SceneRender& r, const regional::Scene& scene) {
  json::Value root;
  root.set("program", "nephele");
  root.set("version", version);
  json::Value camera;
  camera.set("latitude", r.camera.latitude_deg);
  camera.set("longitude", r.camera.longitude_deg);
  camera.set("height_m", r.camera.height_m);
  camera.set("heading_deg", r.camera.heading_deg);
  camera.set("pitch_deg", r.camera.pitch_deg);
  camera.set("fov_deg", r.camera.fov_deg);
  camera.set("panorama", r.camera.panorama);
  root.set("camera", camera);
  root.set("time", scene.time);
  root.set("sun_elevation_deg", r.render.sun_elevation_deg);
  root.set("weather_source", r.weather_source);
  if (r.weather_source == "global cover") {
    // The cover the scene made: what `nephele generate` makes again with these options.
    json::Value cover;
    cover.set("size", scene.cover_size);
    cover.set("seed", static_cast<double>(scene.seed));
    cover.set("flow", scene.cover_flow);
    cover.set("surface", scene.cover_surface);
    cover.set("time", scene.time);
    root.set("global_cover", cover);
  }
  json::Value weather;
  weather.set("cloud_cover", r.weather_at_camera.cloud_cover);
  weather.set("cloud_low", r.weather_at_camera.cloud_low);
  weather.set("cloud_mid", r.weather_at_camera.cloud_mid);
  weather.set("cloud_high", r.weather_at_camera.cloud_high);
  weather.set("precipitation", r.weather_at_camera.precipitation);
  root.set("weather_at_camera", weather);
  json::Value::Array layers;
  for (const auto& l : r.layers) {
    json::Value v;
    v.set("type", regional::cloud_type_name(l.type));
    v.set("base_m", l.base_m);
    v.set("top_m", l.top_m);
    v.set("morph", l.morph);
    v.set("reason", l.reason);
    layers.push_back(v);
  }
  root.set("layers", layers);
  // The convective clouds placed from the weather (docs/convection.md): what called for them and
  // where each stands, so that a render says why it has (or has no) towers.
  json::Value convection;
  convection.set("reason", r.convection_reason);
  json::Value::Array clouds;
  for (const auto& c : r.convective_clouds) {
    json::Value v;
    v.set("kind", regional::convective_kind_name(c.kind));
    v.set("east_m", c.east_m);
    v.set("north_m", c.north_m);
    v.set("cloud_base_m", c.cloud_base_m);
    v.set("cloud_top_m", c.cloud_top_m);
    v.set("extent_m", c.extent_m);
    v.set("anvil_towards_deg", c.axis_deg);
    v.set("reason", c.reason);
    clouds.push_back(v);
  }
  convection.set("clouds", clouds);
  root.set("convection", convection);
  json::Value::Array passes;
  for (const auto& p : r.passes) passes.emplace_back(p);
  root.set("passes", passes);
  json::Value timings;
  for (const auto& [name, ms] : r.render.timings_ms) timings.set(name, ms);
  root.set("timings_ms", timings);
  root.set("loop_limited_pixels", static_cast<double>(r.render.loop_limited_pixels));
  json::Value steps;
  steps.set("view", scene.view_steps);
  steps.set("light", scene.light_steps);
  steps.set("frames", scene.frames);
  steps.set("resolution_divisor", scene.resolution_divisor);
  steps.set("sky", scene.sky_steps);
  steps.set("powder", scene.powder);
  steps.set("shadow_map", scene.shadow_map_size);
  root.set("steps", steps);
  // What chose the steps: the quality and its target, and which settings were given by name.
  json::Value quality;
  quality.set("name", scene.quality);
  if (const params::RenderQuality* q = params::find_render_quality(scene.quality)) {
    quality.set("target_display_rms", q->target_display_rms);
    quality.set("why", std::string(q->why));
  }
  json::Value::Array from_quality, given;
  for (const std::string& key : regional::quality_step_keys())
    (scene.steps_given.count(key) ? given : from_quality).emplace_back(key);
  quality.set("from_quality", from_quality);
  quality.set("given", given);
  root.set(std::string(params::scene::quality.key), quality);
  root.set("exposure", scene.exposure);
  root.set(std::string(params::scene::terrain.key), scene.terrain);
  root.set(std::string(params::scene::land_cover.key), scene.land_cover);
  root.set(std::string(params::scene::terrain_detail.key), scene.terrain_detail);
  return root;
}

std::vector<unsigned char> encode_render_image(const core::ImageData& radiance, double exposure,
                                               const std::string& name) {
  if (core::lowercase_extension(name) == ".png") {
    // zlib's fastest level, as the cover's previews: a 1280 x 720 view encodes in a third of the
    // time for 12 % more bytes (level 6: 0.3 s of the orbit command's 3.4 s).
    files::ImageEncoding png = files::png_encoding(8);
    png.png_compression_level = 1;
    return files::encode_image(render::tone_map(radiance, exposure), png, name);
  }
  return files::encode_image(radiance, files::exr_encoding({"R", "G", "B", "A"}), name);
}

void write_scene_outputs(const SceneRender& result, const regional::Scene& scene,
                         const std::filesystem::path& directory, const std::vector<std::string>& names,
                         files::OutputSet::Scope scope) {
  if (names.empty()) return;
  files::OutputSet outputs(directory, scope);
  for (const auto& name : names) outputs.write(name, encode_render_image(result.render.radiance, scene.exposure, name));
  // The sidecar sits beside the first output.
  const std::filesystem::path first(names.front());
  outputs.write((first.parent_path() / (first.stem().string() + ".json")).string(),
                json::write(scene_sidecar(result, scene)));
  outputs.commit();
}

json::Value orbit_sidecar(const render::RenderResult& result, const OrbitRecord& record) {
  json::Value root, camera;
  root.set("view", "orbit");
  camera.set("latitude", record.camera.latitude_deg);
  camera.set("longitude", record.camera.longitude_deg);
  camera.set("altitude_m", record.camera.altitude_m);
  camera.set("heading_deg", record.camera.heading_deg);
  camera.set("pitch_deg", record.camera.pitch_deg);
  camera.set("fov_deg", record.camera.fov_deg);
  camera.set("width", record.camera.width);
  camera.set("height", record.camera.height);
  root.set("camera", camera);
  root.set("time", record.time);
  root.set("sun_elevation_deg", result.sun_elevation_deg);
  root.set("planet_radius_m", record.settings.planet_radius_m);
  root.set("cloud_base_m", record.settings.cloud_base_m);
  root.set("cloud_thickness_m", record.settings.cloud_thickness_m);
  root.set("cloud_detail", record.settings.cloud_detail);
  root.set("cloud_tau_spread", record.settings.cloud_tau_spread);
  root.set("earth_texture", record.earth_texture);
  root.set("night_texture", record.night_texture);
  root.set("water_mask", record.water);
  root.set("relief", record.relief);
  root.set("cover", record.cover);
  root.set("exposure", record.exposure);
  root.set("metering", record.metering);
  return root;
}

void write_orbit_outputs(const render::RenderResult& result, const OrbitRecord& record,
                         const std::filesystem::path& out) {
  std::filesystem::path directory = out.parent_path();
  if (directory.empty()) directory = ".";
  files::OutputSet outputs(directory, files::OutputSet::Scope::files);
  const std::string name = out.filename().string();
  outputs.write(name, encode_render_image(result.radiance, record.exposure, name));
  outputs.write(out.stem().string() + ".json", json::write(orbit_sidecar(result, record)));
  outputs.commit();
}

}  // namespace nephele::io
