#include "io/scene_files.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <string_view>

#include "core/input_file.hpp"
#include "core/json.hpp"
#include "core/json_keys.hpp"
#include "params/table.hpp"
#include "params/values.hpp"

namespace nephele::io {

using regional::Scene;
using regional::SceneError;

namespace {

// The allowed scene keys, from the table (for the message about an unknown key).
std::string scene_keys() {
  std::string keys;
  for (const params::Parameter* p : params::all())
    if (p->used_by(params::scene_file) && p != &params::scene::latitude && p != &params::scene::longitude &&
        p != &params::scene::height) {
      keys += (keys.empty() ? "" : ", ") + std::string(p->key);
      if (p == &params::scene::view) keys += ", at";
    }
  return keys;
}

// A setting that is one of the parameter's words or a file ("etopo5|flat|FILE"): a word as it is,
// a path resolved against the scene file's folder.
std::string word_or_path(const params::Parameter& p, const std::string& value, const std::string& base_directory) {
  const std::string_view allowed = p.allowed;
  for (std::size_t begin = 0; begin <= allowed.size();) {
    const std::size_t end = std::min(allowed.find('|', begin), allowed.size());
    const std::string_view word = allowed.substr(begin, end - begin);
    if (word != "FILE" && word == value) return value;
    begin = end + 1;
  }
  return std::filesystem::path(value).is_absolute() ? value : (std::filesystem::path(base_directory) / value).string();
}

}  // namespace

Scene parse_scene(const std::string& text, const std::string& source, const std::string& base_directory) {
  json::Value root;
  try {
    root = json::parse(text);
  } catch (const json::ParseError& e) {
    throw SceneError(source + ": not valid JSON: " + e.what());
  }
  if (!root.is_object()) throw SceneError(source + ": the top level must be a JSON object");
  const json::KeyReader k([&source](const std::string& key, const std::string& message) {
    throw SceneError(source + ": '" + key + "': " + message);
  });
  Scene s;
  for (const auto& [key, v] : root.as_object()) {
    if (key == "view") {
      s.view = k.string(v, key);
    } else if (key == "at") {
      if (!v.is_object()) k.fail(key, "must be an object with latitude, longitude, height");
      for (const auto& [sub, w] : v.as_object()) {
        if (sub == "latitude")
          s.latitude_deg = k.number(w, "at.latitude");
        else if (sub == "longitude")
          s.longitude_deg = k.number(w, "at.longitude");
        else if (sub == "height")
          s.height_m = k.number(w, "at.height");
        else
          k.fail("at." + sub, "unknown key (allowed: latitude, longitude, height)");
      }
      if (!s.latitude_deg || !s.longitude_deg || !s.height_m) k.fail(key, "needs latitude, longitude and height");
      s.view.clear();
    } else if (key == "heading") {
      s.heading_deg = k.number(v, key);
    } else if (key == "pitch") {
      s.pitch_deg = k.number(v, key);
    } else if (key == "fov") {
      s.fov_deg = k.number(v, key);
    } else if (key == "time") {
      s.time = k.string(v, key);
    } else if (key == "size") {
      regional::parse_size(k.string(v, key), s.width, s.height, source + ": '" + key + "'");
    } else if (key == "panorama") {
      s.panorama = k.boolean(v, key);
    } else if (key == "weather") {
      for (const auto& f : k.strings(v, key))
        s.weather.push_back(
            std::filesystem::path(f).is_absolute() ? f : (std::filesystem::path(base_directory) / f).string());
    } else if (key == "seed") {
      const double d = k.number(v, key);
      try {
        params::check_number(params::scene::seed, d, source + ": '" + key + "'");
      } catch (const core::InputError& e) {
        throw SceneError(e.what());
      }
      if (d != std::floor(d)) k.fail(key, "must be an integer");
      s.seed = static_cast<std::uint32_t>(d);
    } else if (key == "quality") {
      s.quality = k.string(v, key);
    } else if (key == "view_steps") {
      regional::give_step(s, params::scene::view_steps, k.integer(v, key));
    } else if (key == "light_steps") {
      regional::give_step(s, params::scene::light_steps, k.integer(v, key));
    } else if (key == "frames") {
      regional::give_step(s, params::scene::frames, k.integer(v, key));
    } else if (key == "resolution_divisor") {
      regional::give_step(s, params::scene::resolution_divisor, k.integer(v, key));
    } else if (key == "sky_steps") {
      s.sky_steps = k.integer(v, key);
    } else if (key == "shadow_map_size") {
      s.shadow_map_size = k.integer(v, key);
    } else if (key == "fog_top") {
      s.fog_top_m = k.number(v, key);
    } else if (key == "powder") {
      s.powder = k.number(v, key);
    } else if (key == "terrain") {
      s.terrain = word_or_path(params::scene::terrain, k.string(v, key), base_directory);
    } else if (key == "terrain_detail") {
      s.terrain_detail = k.number(v, key);
    } else if (key == "land_cover") {
      s.land_cover = word_or_path(params::scene::land_cover, k.string(v, key), base_directory);
    } else if (key == "exposure") {
      s.exposure = k.number(v, key);
    } else if (key == "cover_size") {
      s.cover_size = k.integer(v, key);
    } else if (key == "flow") {
      s.cover_flow = k.string(v, key);
    } else if (key == "surface") {
      s.cover_surface = word_or_path(params::cover::surface, k.string(v, key), base_directory);
    } else if (key == "outputs") {
      s.outputs = k.strings(v, key);
    } else if (key == "description") {
      k.string(v, key);  // free text for people
    } else {
      k.fail(key, "unknown key (allowed: " + scene_keys() + ")");
    }
  }
  if (s.panorama) {
    const auto& keys = root.as_object();
    regional::make_panorama(s,
                            std::any_of(keys.begin(), keys.end(), [](const auto& kv) { return kv.first == "size"; }));
  }
  regional::apply_render_quality(s, source);
  regional::validate_scene(s, source);
  return s;
}

Scene read_scene_file(const std::string& path) {
  std::string text;
  try {
    text = core::read_input_file(path);
  } catch (const core::InputFileError& e) {
    throw SceneError(e.what());
  }
  return parse_scene(text, path, std::filesystem::path(path).parent_path().string());
}

}  // namespace nephele::io
