#include "regional/scene.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "core/file_names.hpp"
#include "regional/sites.hpp"
#include "core/number_text.hpp"
#include "core/time.hpp"
#include "params/render_quality.hpp"

namespace nephele::regional {
namespace {

// The name an error about `key` starts with: the option that set it, else the source and key.
std::string label(const std::string& source, const KeyOptions& options, const std::string& key) {
  const std::string head = key.substr(0, key.find('.'));  // at.latitude was set by --at
  if (const auto o = options.find(head); o != options.end()) return o->second;
  return source + ": '" + key + "'";
}

void check_range(const std::string& where, double value, double lo, double hi, const std::string& what = "") {
  if (!(value >= lo && value <= hi)) {
    std::ostringstream m;
    m << where << ": " << what << value << " is outside the allowed range " << lo << " to " << hi;
    throw SceneError(m.str());
  }
}

// The range the table declares for a parameter.
void check_range(const std::string& where, double value, const params::Parameter& p, const std::string& what = "") {
  check_range(where, value, p.min, p.max, what);
}

}  // namespace

std::vector<params::FieldBinding> field_bindings(Scene& s) {
  namespace sc = params::scene;
  return {{&sc::latitude, &s.latitude_deg},
          {&sc::longitude, &s.longitude_deg},
          {&sc::height, &s.height_m},
          {&sc::heading, &s.heading_deg},
          {&sc::pitch, &s.pitch_deg},
          {&sc::fov, &s.fov_deg},
          {&sc::time, &s.time},
          {&sc::seed, &s.seed},
          {&sc::quality, &s.quality},
          {&sc::view_steps, &s.view_steps},
          {&sc::light_steps, &s.light_steps},
          {&sc::sky_steps, &s.sky_steps},
          {&sc::powder, &s.powder},
          {&sc::shadow_map_size, &s.shadow_map_size},
          {&sc::frames, &s.frames},
          {&sc::resolution_divisor, &s.resolution_divisor},
          {&sc::terrain, &s.terrain},
          {&sc::land_cover, &s.land_cover},
          {&sc::terrain_detail, &s.terrain_detail},
          {&sc::fog_top, &s.fog_top_m},
          {&sc::exposure, &s.exposure},
          {&sc::cover_size, &s.cover_size},
          {&params::cover::flow, &s.cover_flow},
          {&params::cover::surface, &s.cover_surface}};
}

void give_step(Scene& s, const params::Parameter& step, int value) {
  int field = value;
  if (params::copy_bound_fields({{&step, &field}}, field_bindings(s)) != 1 ||
      std::find(quality_step_keys().begin(), quality_step_keys().end(), step.key) == quality_step_keys().end())
    throw std::logic_error("give_step: '" + std::string(step.key) + "' is not a step setting of a quality");
  s.steps_given.insert(std::string(step.key));
}

const std::vector<std::string>& quality_step_keys() {
  static const std::vector<std::string> keys = {
      std::string(params::scene::view_steps.key), std::string(params::scene::light_steps.key),
      std::string(params::scene::frames.key), std::string(params::scene::resolution_divisor.key)};
  return keys;
}

void apply_render_quality(Scene& s, const std::string& source, const KeyOptions& options) {
  const params::RenderQuality* q = params::find_render_quality(s.quality);
  if (q == nullptr)
    throw SceneError(label(source, options, "quality") + ": '" + s.quality +
                     "' is not a quality (allowed: " + params::render_quality_names() + ")");
  const auto set = [&](const params::Parameter& p, int& field, int value) {
    if (!s.steps_given.count(std::string(p.key))) field = value;
  };
  set(params::scene::view_steps, s.view_steps, q->view_steps);
  set(params::scene::light_steps, s.light_steps, q->light_steps);
  set(params::scene::frames, s.frames, q->frames);
  set(params::scene::resolution_divisor, s.resolution_divisor, q->resolution_divisor);
}

void make_panorama(Scene& s, bool size_given) {
  s.panorama = true;
  if (size_given) return;
  s.width = panorama_width;
  s.height = panorama_height;
}

void parse_size(const std::string& text, int& width, int& height, const std::string& name) {
  const std::string form = "is not WIDTHxHEIGHT, e.g. 1280x720 (each 1 to " + std::to_string(max_image_side) + ")";
  const size_t x = text.find('x');
  if (x == std::string::npos) throw SceneError(name + ": '" + text + "' " + form);
  // Digits only: sscanf's %d skipped spaces, took signs and wrapped 4294967297 to 1.
  const auto w = core::parse_integer(text.substr(0, x));
  const auto h = core::parse_integer(text.substr(x + 1));
  if (!w || !h || *w < 0 || *h < 0) throw SceneError(name + ": '" + text + "' " + form);
  for (const auto& [what, value] : {std::pair<const char*, long long>{"width", *w}, {"height", *h}})
    if (value < 1 || value > max_image_side)
      throw SceneError(name + ": " + what + " " + std::to_string(value) + " is outside the allowed range 1 to " +
                       std::to_string(max_image_side));
  width = static_cast<int>(*w);
  height = static_cast<int>(*h);
}

void validate_scene(const Scene& s, const std::string& source, const KeyOptions& options) {
  auto where = [&](const std::string& key) { return label(source, options, key); };
  if (!s.view.empty() && !find_viewpoint(s.view))
    throw SceneError(where("view") + ": '" + s.view + "' is not a known viewpoint (allowed: gurten, bantiger)");
  if (s.view.empty() && !s.latitude_deg) throw SceneError(source + ": give a view or a position (at)");
  if (s.weather.size() > max_weather_files)
    throw SceneError(where("weather") + ": " + std::to_string(s.weather.size()) + " files (allowed: at most " +
                     std::to_string(max_weather_files) + ")");
  if (s.latitude_deg) check_range(where("at.latitude"), *s.latitude_deg, params::scene::latitude, "latitude ");
  if (s.longitude_deg) check_range(where("at.longitude"), *s.longitude_deg, params::scene::longitude, "longitude ");
  if (s.height_m) check_range(where("at.height"), *s.height_m, params::scene::height, "height ");
  if (s.heading_deg) check_range(where("heading"), *s.heading_deg, params::scene::heading);
  check_range(where("pitch"), s.pitch_deg, params::scene::pitch);
  check_range(where("fov"), s.fov_deg, params::scene::fov);
  check_range(where("size"), s.width, 1, max_image_side, "width ");
  check_range(where("size"), s.height, 1, max_image_side, "height ");
  check_range(where("view_steps"), s.view_steps, params::scene::view_steps);
  check_range(where("light_steps"), s.light_steps, params::scene::light_steps);
  check_range(where("frames"), s.frames, params::scene::frames);
  check_range(where("resolution_divisor"), s.resolution_divisor, params::scene::resolution_divisor);
  check_range(where("sky_steps"), s.sky_steps, params::scene::sky_steps);
  check_range(where("shadow_map_size"), s.shadow_map_size, params::scene::shadow_map_size);
  check_range(where("exposure"), s.exposure, params::scene::exposure);
  check_range(where("fog_top"), s.fog_top_m, params::scene::fog_top);
  check_range(where("terrain_detail"), s.terrain_detail, params::scene::terrain_detail);
  check_range(where("powder"), s.powder, params::scene::powder);
  check_range(where("cover_size"), s.cover_size, params::scene::cover_size);
  const std::vector<std::string> flows = params::cover::flow.words();
  if (std::find(flows.begin(), flows.end(), s.cover_flow) == flows.end())
    throw SceneError(where("flow") + ": '" + s.cover_flow +
                     "' is not a flow (allowed: " + params::cover::flow.range_text() + ")");
  try {
    core::parse_utc_time(s.time);
  } catch (const std::invalid_argument& e) {
    throw SceneError(where("time") + ": " + e.what());
  }
  std::vector<std::string> seen;
  for (const auto& o : s.outputs) {
    const std::string ext = core::lowercase_extension(o);
    if (ext != ".png" && ext != ".exr") throw SceneError(source + ": 'outputs': '" + o + "' must end in .png or .exr");
    // Outputs are one set inside --out (docs/formats.md): nothing may land outside it.
    const std::filesystem::path path(o);
    if (path.is_absolute() || path.has_root_name() || path.has_root_directory())
      throw SceneError(source + ": 'outputs': '" + o + "' is an absolute path (allowed: a relative path inside --out)");
    for (const auto& part : path)
      if (part == "..")
        throw SceneError(source + ": 'outputs': '" + o + "' contains '..' (allowed: a relative path inside --out)");
    const std::string normal = path.lexically_normal().string();
    if (std::find(seen.begin(), seen.end(), normal) != seen.end())
      throw SceneError(source + ": 'outputs': '" + o + "' is named twice (each output needs its own name)");
    seen.push_back(normal);
  }
}

}  // namespace nephele::regional
