// Cloud model files (scenes/*.cloud.json), strict like the regional scene files: every key is
// known, typed and inside the table's range, and errors name the file and the key's path.
#include "io/cloud_model_files.hpp"

#include <cmath>
#include <filesystem>
#include <sstream>
#include <type_traits>

#include "core/input_file.hpp"
#include "core/json.hpp"
#include "core/json_keys.hpp"
#include "params/values.hpp"

namespace nephele::io {

using namespace model;

namespace {

namespace cm = params::cloud_model;

class Reader {
 public:
  explicit Reader(const std::string& source)
      : source_(source), k_([source](const std::string& key, const std::string& message) {
          throw ModelError(source + ": '" + key + "': " + message);
        }) {}

  // A number within the table's range for `p` (checked before it is narrowed to float).
  double number(const params::Parameter& p, const json::Value& v, const std::string& key) const {
    const double d = k_.number(v, key);
    params::check_number(p, d, source_ + ": '" + key + "'");
    return d;
  }

  glsl::vec3 point(const json::Value& v, const std::string& key) const {
    if (!v.is_array() || v.as_array().size() != 3) k_.fail(key, "must be an array of 3 numbers [x, y, z]");
    glsl::vec3 p;
    for (int i = 0; i < 3; ++i)
      p[i] = float(number(cm::coordinate, v.as_array()[i], key + "[" + std::to_string(i) + "]"));
    return p;
  }

  Turbulence turbulence(const json::Value& v, const std::string& path, Turbulence t) const {
    if (!v.is_object()) k_.fail(path, "must be an object");
    // Named references, not structured bindings: lambdas below capture them, which C++17
    // (clang 14) does not allow for bindings.
    for (const auto& entry : v.as_object()) {
      const std::string& key = entry.first;
      const json::Value& w = entry.second;
      const std::string name = path + "." + key;
      bool known = false;
      visit_turbulence(t, [&](const params::Parameter& p, auto& field) {
        if (p.key != key) return;
        field = static_cast<std::decay_t<decltype(field)>>(number(p, w, name));
        known = true;
      });
      if (!known) {
        std::string allowed;
        visit_turbulence(t, [&](const params::Parameter& p, auto&) {
          allowed += (allowed.empty() ? "" : ", ") + std::string(p.key);
        });
        k_.fail(name, "unknown key (allowed: " + allowed + ")");
      }
    }
    return t;
  }

  // One primitive of the file; a polyline becomes its consecutive segments, each with the
  // polyline's radius, influence, weight and noise.
  std::vector<Primitive> primitives(const json::Value& v, const std::string& path, const Turbulence& noise) const {
    if (!v.is_object()) k_.fail(path, "must be an object");
    Primitive p;
    p.noise = noise;
    const json::Value* type = v.find("type");
    if (!type) k_.fail(path + ".type", "missing (allowed: point, segment, polyline)");
    const std::string kind = k_.string(*type, path + ".type");
    params::check_word(cm::kind, kind, source_ + ": '" + path + ".type'");
    p.segment = kind != "point";
    const bool polyline = kind == "polyline";
    const std::string skeleton = polyline ? "points" : p.segment ? "from, to" : "position";
    std::vector<glsl::vec3> points;
    bool has_from = false, has_to = false;
    // Named references, not structured bindings: lambdas below capture them, which C++17
    // (clang 14) does not allow for bindings.
    for (const auto& entry : v.as_object()) {
      const std::string& key = entry.first;
      const json::Value& w = entry.second;
      const std::string name = path + "." + key;
      if (key == "type") continue;
      if (!polyline && key == (p.segment ? "from" : "position")) {
        p.from = point(w, name);
        has_from = true;
      } else if (!polyline && key == "to" && p.segment) {
        p.to = point(w, name);
        has_to = true;
      } else if (polyline && key == "points") {
        if (!w.is_array() || w.as_array().size() < 2 || w.as_array().size() > 64)
          k_.fail(name, "must be an array of 2 to 64 points [x, y, z]");
        for (size_t i = 0; i < w.as_array().size(); ++i)
          points.push_back(point(w.as_array()[i], name + "[" + std::to_string(i) + "]"));
      } else if (key == "noise") {
        p.noise = turbulence(w, name, noise);
      } else {
        bool known = false;
        visit_primitive(p, [&](const params::Parameter& parameter, auto& field) {
          if (parameter.key != key) return;
          field = static_cast<std::decay_t<decltype(field)>>(number(parameter, w, name));
          known = true;
        });
        if (!known)
          k_.fail(name,
                  "unknown key (allowed for a " + kind + ": type, " + skeleton + ", radius, influence, weight, noise)");
      }
    }
    if (polyline) {
      if (points.empty()) k_.fail(path + ".points", "missing");
      std::vector<Primitive> segments;
      for (size_t i = 0; i + 1 < points.size(); ++i) {
        p.from = points[i];
        p.to = points[i + 1];
        segments.push_back(p);
      }
      return segments;
    }
    if (!has_from) k_.fail(path + (p.segment ? ".from" : ".position"), "missing");
    if (p.segment && !has_to) k_.fail(path + ".to", "missing");
    return {p};
  }

  const json::KeyReader& keys() const { return k_; }

 private:
  std::string source_;
  json::KeyReader k_;
};

json::Value noise_json(const Turbulence& t) {
  json::Value v(json::Value::Object{});
  visit_turbulence(t, [&](const params::Parameter& p, auto value) { v.set(std::string(p.key), value); });
  return v;
}

json::Value point_json(glsl::vec3 p) { return json::Value(json::Value::Array{p.x, p.y, p.z}); }

}  // namespace

CloudModel parse_cloud_model(const std::string& text, const std::string& source) {
  json::Value root;
  try {
    root = json::parse(text);
  } catch (const json::ParseError& e) {
    throw ModelError(source + ": not valid JSON: " + e.what());
  }
  if (!root.is_object()) throw ModelError(source + ": the top level must be a JSON object");
  const Reader r(source);
  const json::KeyReader& k = r.keys();
  CloudModel m;
  // The global noise first: it is every primitive's default.
  if (const json::Value* noise = root.find("noise")) m.noise = r.turbulence(*noise, "noise", m.noise);
  const json::Value* primitives = nullptr;
  for (const auto& [key, v] : root.as_object()) {
    if (key == "description")
      m.description = k.string(v, key);
    else if (key == "blend") {
      const std::string word = k.string(v, key);
      params::check_word(cm::blend, word, source + ": 'blend'");
      m.blend = parse_blend(word, source + ": 'blend'");
    } else if (key == "scale")
      m.scale = float(r.number(cm::scale, v, key));
    else if (key == "extent")
      m.extent_m = r.number(cm::extent, v, key);
    else if (key == "base")
      m.base = float(r.number(cm::base, v, key));
    else if (key == "top")
      m.top = float(r.number(cm::top, v, key));
    else if (key == "noise")
      continue;
    else if (key == "primitives")
      primitives = &v;
    else
      k.fail(key, "unknown key (allowed: description, blend, scale, extent, base, top, noise, primitives)");
  }
  if (!primitives) k.fail("primitives", "missing (an array of primitives)");
  if (!primitives->is_array()) k.fail("primitives", "must be an array of primitives");
  const auto& list = primitives->as_array();
  // Counted as they are read, so a huge polyline is refused before the density pass sees it.
  auto too_many = [&](std::size_t count) {
    k.fail("primitives", std::to_string(count) + " or more primitives (allowed: at most " +
                             std::to_string(model::max_primitives) + "; a polyline counts its segments)");
  };
  if (list.size() > model::max_primitives) too_many(list.size());
  for (size_t i = 0; i < list.size(); ++i) {
    const std::string path = "primitives[" + std::to_string(i) + "]";
    if (const json::Value* points = list[i].is_object() ? list[i].find("points") : nullptr)
      if (points->is_array() && m.primitives.size() + points->as_array().size() > model::max_primitives + 1)
        too_many(m.primitives.size() + points->as_array().size() - 1);
    for (const Primitive& p : r.primitives(list[i], path, m.noise)) m.primitives.push_back(p);
    if (m.primitives.size() > model::max_primitives) too_many(m.primitives.size());
  }
  validate(m, source);
  return m;
}

CloudModel read_cloud_model(const std::string& path, const std::string& option) {
  std::string text;
  try {
    text = core::read_input_file(path);
  } catch (const core::InputFileError& e) {
    throw ModelError(option + ": " + e.what());  // bad input, as the scene files' (exit 2)
  }
  return parse_cloud_model(text, path);
}

std::string write_cloud_model(const CloudModel& m) {
  json::Value root(json::Value::Object{});
  if (!m.description.empty()) root.set("description", m.description);
  root.set("blend", blend_name(m.blend));
  root.set("scale", m.scale);
  root.set("extent", m.extent_m);
  root.set("base", m.base);
  root.set("top", m.top);
  root.set("noise", noise_json(m.noise));
  json::Value::Array list;
  for (const Primitive& p : m.primitives) {
    json::Value v(json::Value::Object{});
    v.set("type", p.segment ? "segment" : "point");
    v.set(p.segment ? "from" : "position", point_json(p.from));
    if (p.segment) v.set("to", point_json(p.to));
    visit_primitive(p,
                    [&](const params::Parameter& parameter, auto value) { v.set(std::string(parameter.key), value); });
    v.set("noise", noise_json(p.noise));
    list.push_back(std::move(v));
  }
  root.set("primitives", json::Value(std::move(list)));
  return json::write(root);
}

}  // namespace nephele::io
