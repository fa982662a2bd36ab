#include "model/cloud_model.hpp"

#include <cmath>
#include <sstream>

#include "params/values.hpp"

namespace nephele::model {
namespace {

namespace cm = params::cloud_model;

std::string text_of(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// The table's range for `p`, the message naming `field`.
void check(const params::Parameter& p, double value, const std::string& field) {
  params::check_number(p, value, field);
}

void check_turbulence(const Turbulence& t, const std::string& where) {
  visit_turbulence(t, [&](const params::Parameter& p, auto value) {
    check(p, double(value), where + "noise." + std::string(p.key));
  });
}

}  // namespace

Blend parse_blend(const std::string& word, const std::string& where) {
  if (word == "sum") return Blend::sum;
  if (word == "lipus") return Blend::lipus;
  if (word == "global") return Blend::global;
  if (word == "per-primitive") return Blend::per_primitive;
  throw ModelError(where, "'" + word + "'", "sum, lipus, global, per-primitive");
}

const char* blend_name(Blend blend) {
  switch (blend) {
    case Blend::sum: return "sum";
    case Blend::lipus: return "lipus";
    case Blend::global: return "global";
    case Blend::per_primitive: return "per-primitive";
  }
  return "";
}

int blend_code(Blend blend) {
  switch (blend) {
    case Blend::sum: return glsl::MODEL_BLEND_SUM;
    case Blend::lipus: return glsl::MODEL_BLEND_LIPUS;
    case Blend::global: return glsl::MODEL_BLEND_GLOBAL;
    case Blend::per_primitive: return glsl::MODEL_BLEND_PER_PRIMITIVE;
  }
  return 0;
}

void validate(const CloudModel& m, const std::string& source) {
  const std::string head = source.empty() ? "" : source + ": ";
  check(cm::scale, m.scale, head + "scale");
  check(cm::extent, m.extent_m, head + "extent");
  check(cm::base, m.base, head + "base");
  check(cm::top, m.top, head + "top");
  // Both cuts need room for their edges (model_levels: MODEL_LEVEL_EDGE each).
  if (m.top - m.base < 2 * glsl::MODEL_LEVEL_EDGE)
    throw ModelError(head + "top", text_of(m.top),
                     "above base + " + text_of(2 * glsl::MODEL_LEVEL_EDGE) + " = " +
                         text_of(m.base + 2 * glsl::MODEL_LEVEL_EDGE) + " (the base and the top each rise over " +
                         text_of(glsl::MODEL_LEVEL_EDGE) + ")",
                     "is too close to the base");
  check_turbulence(m.noise, head);
  if (m.primitives.empty()) throw ModelError(head + "primitives", "[]", "at least one primitive");
  if (m.primitives.size() > max_primitives)
    throw ModelError(head + "primitives", std::to_string(m.primitives.size()) + " primitives",
                     "at most " + std::to_string(max_primitives) + " (a polyline counts its segments)");
  for (size_t i = 0; i < m.primitives.size(); ++i) {
    const Primitive& p = m.primitives[i];
    const std::string where = head + "primitives[" + std::to_string(i) + "].";
    for (int axis = 0; axis < 3; ++axis) {
      check(cm::coordinate, p.from[axis], where + (p.segment ? "from" : "position"));
      if (p.segment) check(cm::coordinate, p.to[axis], where + "to");
    }
    visit_primitive(p, [&](const params::Parameter& parameter, auto value) {
      check(parameter, double(value), where + std::string(parameter.key));
    });
    check_turbulence(p.noise, where);
    // Eq. 3 is Lipus's operator for one weight w: with unequal weights it depends on the order
    // and is no longer bounded by the weights, so it is refused rather than generalised.
    if (m.blend != Blend::sum && p.weight != m.primitives[0].weight)
      throw ModelError(where + "weight", text_of(p.weight),
                       "the weight of primitives[0], " + text_of(m.primitives[0].weight) +
                           " (Lipus's blend needs one weight for all primitives; blend 'sum' allows others)",
                       "differs from the others");
  }
}

bool operator==(const Turbulence& a, const Turbulence& b) {
  return a.octaves == b.octaves && a.frequency == b.frequency && a.amplitude == b.amplitude && a.gain == b.gain &&
         a.lacunarity == b.lacunarity && a.fraction == b.fraction && a.erosion == b.erosion && a.seed == b.seed;
}

bool operator==(const Primitive& a, const Primitive& b) {
  // A point's `to` is not part of it (pack() uses `from` twice).
  return a.segment == b.segment && a.from == b.from && (!a.segment || a.to == b.to) && a.radius == b.radius &&
         a.influence == b.influence && a.weight == b.weight && a.noise == b.noise;
}

glsl::ModelNoise pack(const Turbulence& t) {
  glsl::ModelNoise n;
  n.shape = glsl::vec4(float(t.octaves), t.frequency, t.amplitude, t.gain);
  n.extra = glsl::vec4(t.lacunarity, t.fraction, float(t.seed), t.erosion);
  return n;
}

glsl::ModelPrimitive pack(const Primitive& p) {
  glsl::ModelPrimitive g;
  g.a = glsl::vec4(p.from, p.radius);
  g.b = glsl::vec4(p.segment ? p.to : p.from, p.influence);
  g.kind = glsl::vec4(p.weight, float(p.segment ? glsl::MODEL_SEGMENT : glsl::MODEL_POINT), 0.0f, 0.0f);
  g.noise = pack(p.noise);
  return g;
}

bool same_but_primitives(const CloudModel& a, const CloudModel& b) {
  return a.primitives.size() == b.primitives.size() && a.blend == b.blend && a.scale == b.scale &&
         a.extent_m == b.extent_m && a.base == b.base && a.top == b.top && a.noise == b.noise;
}

float max_noise_frequency(const CloudModel& model, int size) { return 0.25f * float(size) * model.scale; }

glsl::vec2 levels(const CloudModel& model) { return glsl::vec2(model.base, model.top); }

float density_at(const CloudModel& model, glsl::vec3 p, int size) {
  const glsl::vec3 q = p / model.scale;
  const int blend = blend_code(model.blend);
  const float max_frequency = max_noise_frequency(model, size);
  float rho = 0.0f;
  for (const Primitive& prim : model.primitives)
    rho = glsl::model_accumulate(rho, p, q, pack(prim), blend, max_frequency);
  return glsl::model_finish(rho, p.z, q, blend, pack(model.noise), levels(model), max_frequency);
}

}  // namespace nephele::model
