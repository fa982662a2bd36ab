#include "regional/scene.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "regional/sites.hpp"
#include "core/time.hpp"
#include "core/json.hpp"
#include "core/json_keys.hpp"

namespace nephele::regional {
namespace {

void check_range(const std::string& source, const std::string& key, double value, double lo, double hi) {
  if (!(value >= lo && value <= hi)) {
    std::ostringstream m;
    m << source << ": '" << key << "': " << value << " is outside the allowed range " << lo << " to " << hi;
    throw SceneError(m.str());
  }
}

}  // namespace

void parse_size(const std::string& text, int& width, int& height, const std::string& name) {
  int w = 0, h = 0, consumed = 0;
  if (std::sscanf(text.c_str(), "%dx%d%n", &w, &h, &consumed) != 2 || consumed != static_cast<int>(text.size()))
    throw SceneError(name + ": '" + text + "' is not WIDTHxHEIGHT, e.g. 1280x720");
  width = w;
  height = h;
}

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
        if (sub == "latitude") s.latitude_deg = k.number(w, "at.latitude");
        else if (sub == "longitude") s.longitude_deg = k.number(w, "at.longitude");
        else if (sub == "height") s.height_m = k.number(w, "at.height");
        else k.fail("at." + sub, "unknown key (allowed: latitude, longitude, height)");
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
      parse_size(k.string(v, key), s.width, s.height, source + ": 'size'");
    } else if (key == "panorama") {
      s.panorama = k.boolean(v, key);
    } else if (key == "weather") {
      for (const auto& f : k.strings(v, key))
        s.weather.push_back(std::filesystem::path(f).is_absolute() ? f : (std::filesystem::path(base_directory) / f).string());
    } else if (key == "seed") {
      const double d = k.number(v, key);
      check_range(source, key, d, 0, 4294967295.0);
      if (d != std::floor(d)) k.fail(key, "must be an integer");
      s.seed = static_cast<std::uint32_t>(d);
    } else if (key == "view_steps") {
      s.view_steps = k.integer(v, key);
    } else if (key == "light_steps") {
      s.light_steps = k.integer(v, key);
    } else if (key == "sky_steps") {
      s.sky_steps = k.integer(v, key);
    } else if (key == "exposure") {
      s.exposure = k.number(v, key);
    } else if (key == "cover_size") {
      s.cover_size = k.integer(v, key);
    } else if (key == "outputs") {
      s.outputs = k.strings(v, key);
    } else if (key == "description") {
      k.string(v, key);  // free text for people
    } else {
      k.fail(key, "unknown key (allowed: view, at, heading, pitch, fov, time, size, panorama, weather, seed, "
                  "view_steps, light_steps, sky_steps, exposure, cover_size, outputs, description)");
    }
  }
  validate_scene(s, source);
  return s;
}

void validate_scene(const Scene& s, const std::string& source) {
  if (!s.view.empty() && !find_viewpoint(s.view))
    throw SceneError(source + ": 'view': '" + s.view + "' is not a known viewpoint (allowed: gurten, bantiger)");
  if (s.view.empty() && !s.latitude_deg) throw SceneError(source + ": give a view or a position (at)");
  if (s.latitude_deg) check_range(source, "at.latitude", *s.latitude_deg, -90, 90);
  if (s.longitude_deg) check_range(source, "at.longitude", *s.longitude_deg, -180, 180);
  if (s.height_m) check_range(source, "at.height", *s.height_m, -400, 20000);
  if (s.heading_deg) check_range(source, "heading", *s.heading_deg, -360, 360);
  check_range(source, "pitch", s.pitch_deg, -90, 90);
  check_range(source, "fov", s.fov_deg, 1, 179);
  check_range(source, "size (width)", s.width, 1, 16384);
  check_range(source, "size (height)", s.height, 1, 16384);
  check_range(source, "view_steps", s.view_steps, 1, 4096);
  check_range(source, "light_steps", s.light_steps, 0, 256);
  check_range(source, "sky_steps", s.sky_steps, 1, 1024);
  check_range(source, "exposure", s.exposure, 1e-6, 1e6);
  check_range(source, "cover_size", s.cover_size, 4, 4096);
  try {
    core::parse_utc_time(s.time);
  } catch (const std::invalid_argument& e) {
    throw SceneError(source + ": 'time': " + e.what());
  }
  std::vector<std::string> seen;
  for (const auto& o : s.outputs) {
    const std::string ext = std::filesystem::path(o).extension().string();
    if (ext != ".png" && ext != ".exr")
      throw SceneError(source + ": 'outputs': '" + o + "' must end in .png or .exr");
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

Scene read_scene_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path + ": cannot be read");
  std::stringstream text;
  text << in.rdbuf();
  return parse_scene(text.str(), path, std::filesystem::path(path).parent_path().string());
}

}  // namespace nephele::regional
