#include "apps/viewer/modeller.hpp"

#include <algorithm>
#include <cmath>

#include "io/model_files.hpp"

namespace nephele::viewer {
namespace {

namespace cm = params::cloud_model;

glsl::ModelView view_of(const ViewState& state, int width, int height) {
  return render::preview_view(state.model, preview_settings(state, width, height));
}

glm::dvec3 dvec(glsl::vec3 v) { return glm::dvec3(v); }

// The entry distance of the ray into the sphere of radius r about c: 0 from inside, negative
// when it misses or the sphere is behind.
double sphere_entry(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& c, double r) {
  const glm::dvec3 oc = o - c;
  const double b = glm::dot(oc, d), q = glm::dot(oc, oc) - r * r;
  if (q <= 0) return 0;  // inside
  const double disc = b * b - q;
  if (disc < 0) return -1;
  const double t = -b - std::sqrt(disc);
  return t >= 0 ? t : -1;
}

}  // namespace

ViewState modeller_state(const model::CloudModel& m) {
  ViewState state;
  const render::PreviewSettings preview;
  state.modeller = true;
  state.model = m;
  state.camera.heading_deg = preview.heading_deg;
  state.camera.pitch_deg = preview.pitch_deg;
  state.camera.fov_deg = preview.fov_deg;
  state.view_steps = preview.view_steps;
  state.light_steps = preview.light_steps;
  state.exposure = io::preview_exposure;
  state.viewpoint.clear();
  return state;
}

render::PreviewSettings preview_settings(const ViewState& state, int width, int height) {
  render::PreviewSettings s;
  s.width = width;
  s.height = height;
  s.view_steps = state.view_steps;
  s.light_steps = state.light_steps;
  s.fov_deg = state.camera.fov_deg;
  s.heading_deg = state.camera.heading_deg;
  s.pitch_deg = state.camera.pitch_deg;
  return s;
}

Ray cursor_ray(const ViewState& state, double x, double y, int width, int height) {
  const glsl::ModelView v = view_of(state, width, height);
  return {v.origin / v.extent, glsl::model_ray(glsl::vec2(float(x), float(y)), glsl::ivec2(width, height), v)};
}

glsl::vec3 project(const ViewState& state, glsl::vec3 point, int width, int height) {
  const glsl::ModelView v = view_of(state, width, height);
  const glm::dvec3 relative = dvec(point) - dvec(v.origin) / double(v.extent);
  const double depth = glm::dot(relative, dvec(v.forward));
  // model_ray: direction forward + x right + y up with x = (2 u - 1) t, y = (1 - 2 v) aspect t.
  const double t = v.tan_half_fov, aspect = double(height) / width;
  const double x = glm::dot(relative, dvec(v.right)) / depth, y = glm::dot(relative, dvec(v.up)) / depth;
  return glsl::vec3(float((x / t + 1) / 2 * width), float((1 - y / (aspect * t)) / 2 * height), float(depth));
}

double entry_distance(const model::Primitive& p, const Ray& ray) {
  const glm::dvec3 o = dvec(ray.origin), d = glm::normalize(dvec(ray.direction)), a = dvec(p.from);
  const double r = p.radius;
  if (!p.segment) return sphere_entry(o, d, a, r);
  // A capsule: the nearest of its end spheres and its cylinder's side between them.
  const glm::dvec3 axis = dvec(p.to) - a;
  const double length2 = glm::dot(axis, axis);
  double best = -1;
  for (const glm::dvec3& end : {a, a + axis}) {
    const double t = sphere_entry(o, d, end, r);
    if (t >= 0 && (best < 0 || t < best)) best = t;
  }
  if (best == 0 || length2 == 0) return best;
  // Inside the side: the origin within r of the axis between the ends.
  const double s0 = glm::dot(o - a, axis) / length2;
  const glm::dvec3 across0 = (o - a) - s0 * axis;
  if (s0 >= 0 && s0 <= 1 && glm::dot(across0, across0) <= r * r) return 0;
  // The side: |(o - a) + t d| across the axis = r, where the point lies between the ends.
  const glm::dvec3 d_across = d - (glm::dot(d, axis) / length2) * axis;
  const double qa = glm::dot(d_across, d_across), qb = glm::dot(across0, d_across),
               qc = glm::dot(across0, across0) - r * r;
  const double disc = qb * qb - qa * qc;
  if (qa > 0 && disc >= 0) {
    const double t = (-qb - std::sqrt(disc)) / qa;
    const double s = glm::dot(o + t * d - a, axis) / length2;
    if (t >= 0 && s >= 0 && s <= 1 && (best < 0 || t < best)) best = t;
  }
  return best;
}

int pick_primitive(const model::CloudModel& m, const Ray& ray) {
  int nearest = -1;
  double nearest_t = 0;
  for (std::size_t i = 0; i < m.primitives.size(); ++i) {
    const double t = entry_distance(m.primitives[i], ray);
    if (t >= 0 && (nearest < 0 || t < nearest_t)) {
      nearest = int(i);
      nearest_t = t;
    }
  }
  return nearest;
}

glsl::vec3 centre(const model::Primitive& p) { return p.segment ? 0.5f * (p.from + p.to) : p.from; }

glsl::vec3 on_facing_plane(const ViewState& state, const Ray& ray, glsl::vec3 anchor) {
  // The plane's normal is the view's axis: the orbit's forward does not depend on the size.
  const glm::dvec3 n = dvec(view_of(state, 1, 1).forward), o = dvec(ray.origin), d = dvec(ray.direction);
  const double t = glm::dot(dvec(anchor) - o, n) / glm::dot(d, n);
  return glsl::vec3(o + t * d);
}

model::Primitive moved(const model::Primitive& p, glsl::vec3 offset) {
  model::Primitive out = p;
  for (int a = 0; a < 3; ++a) {
    out.from[a] = float(std::clamp(double(p.from[a]) + offset[a], cm::coordinate.min, cm::coordinate.max));
    out.to[a] = float(std::clamp(double(p.to[a]) + offset[a], cm::coordinate.min, cm::coordinate.max));
  }
  return out;
}

model::Primitive resized(const model::Primitive& p, double notches) {
  model::Primitive out = p;
  const double factor = std::pow(resize_per_notch, notches);
  out.radius = float(std::clamp(p.radius * factor, cm::radius.min, cm::radius.max));
  out.influence = float(std::clamp(p.influence * factor, cm::influence.min, cm::influence.max));
  return out;
}

void orbit(ViewState& state, double dx, double dy, int width) {
  const double degrees_per_pixel = 180.0 / std::max(width, 1);
  turn(state, dx * degrees_per_pixel, -dy * degrees_per_pixel);
}

void add_primitive(ViewState& state, int width, int height) {
  auto& primitives = state.model.primitives;
  const bool copy = state.selected >= 0 && state.selected < int(primitives.size());
  model::Primitive added;
  if (copy) {
    const model::Primitive& source = primitives[std::size_t(state.selected)];
    const glm::dvec3 right = glm::normalize(dvec(view_of(state, width, height).right));
    added = moved(source, glsl::vec3(right * double(2 * source.radius + source.influence)));
  } else if (!primitives.empty()) {
    added.weight = primitives.front().weight;  // Lipus's blends need one weight for all
    added.noise = primitives.front().noise;
  }
  std::uint32_t largest = 0;
  for (const auto& p : primitives) largest = std::max(largest, p.noise.seed);
  const auto seeds = std::uint32_t(cm::seed.max) + 1;  // the seed's range is 0 .. max
  added.noise.seed = (largest + 1) % seeds;
  primitives.push_back(added);
  state.selected = int(primitives.size()) - 1;
}

bool remove_selected(ViewState& state) {
  auto& primitives = state.model.primitives;
  if (state.selected < 0 || state.selected >= int(primitives.size()) || primitives.size() < 2) return false;
  primitives.erase(primitives.begin() + state.selected);
  state.selected = -1;
  return true;
}

}  // namespace nephele::viewer
