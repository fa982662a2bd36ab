// The built-in clouds (docs/model.md, "Examples"); scenes/*.cloud.json hold the same models as
// files. Shapes follow the usual descriptions of the genera (WMO International Cloud Atlas):
// a flat-based, wider-than-tall cumulus humilis; a cumulus congestus taller than wide; a
// cumulonimbus whose anvil spreads downwind (+x) at the tropopause; a row of stratocumulus.
#include "model/cloud_model.hpp"

namespace nephele::model {
namespace {

Primitive point(glsl::vec3 at, float radius, float influence, std::uint32_t seed, float fraction = 0.5f) {
  Primitive p;
  p.from = p.to = at;
  p.radius = radius;
  p.influence = influence;
  p.noise.seed = seed;
  p.noise.fraction = fraction;
  return p;
}

Primitive segment(glsl::vec3 from, glsl::vec3 to, float radius, float influence, std::uint32_t seed,
                  float fraction = 0.5f) {
  Primitive p = point(from, radius, influence, seed, fraction);
  p.segment = true;
  p.to = to;
  return p;
}

CloudModel fair_weather() {
  CloudModel m;
  m.description = "fair-weather cumulus (humilis): a flat base near 0.3, wider than tall";
  m.extent_m = 2000;
  m.base = 0.31f;  // the lowest radius edge: the condensation level
  m.primitives = {point({0.50f, 0.50f, 0.38f}, 0.07f, 0.10f, 1), point({0.38f, 0.48f, 0.35f}, 0.05f, 0.08f, 2),
                  point({0.62f, 0.53f, 0.36f}, 0.05f, 0.09f, 3), point({0.47f, 0.58f, 0.37f}, 0.04f, 0.08f, 4),
                  point({0.55f, 0.46f, 0.44f}, 0.04f, 0.07f, 5)};
  return m;
}

CloudModel towering() {
  CloudModel m;
  m.description = "towering cumulus (congestus): a column taller than wide with bulging towers";
  m.extent_m = 6000;
  m.base = 0.18f;
  m.primitives = {segment({0.50f, 0.50f, 0.22f}, {0.50f, 0.52f, 0.62f}, 0.08f, 0.10f, 11),
                  point({0.42f, 0.50f, 0.24f}, 0.07f, 0.09f, 12),
                  point({0.58f, 0.49f, 0.25f}, 0.07f, 0.09f, 13),
                  point({0.48f, 0.55f, 0.70f}, 0.06f, 0.08f, 14),
                  point({0.56f, 0.48f, 0.55f}, 0.05f, 0.08f, 15),
                  point({0.44f, 0.46f, 0.45f}, 0.05f, 0.08f, 16)};
  return m;
}

CloudModel cumulonimbus() {
  CloudModel m;
  m.description = "cumulonimbus (incus): a wide column under an anvil spread downwind (+x) at the tropopause";
  m.extent_m = 15000;
  m.base = 0.07f;
  m.top = 0.85f;  // the tropopause: the anvil and the overshooting top flatten under it
  m.primitives = {segment({0.40f, 0.50f, 0.10f}, {0.44f, 0.50f, 0.70f}, 0.09f, 0.10f, 21),
                  point({0.33f, 0.50f, 0.14f}, 0.07f, 0.08f, 22), point({0.48f, 0.53f, 0.15f}, 0.07f, 0.08f, 23),
                  point({0.36f, 0.44f, 0.40f}, 0.07f, 0.08f, 28), point({0.47f, 0.56f, 0.50f}, 0.06f, 0.08f, 29),
                  // The anvil: glaciated, so smoother (a smaller noise fraction and erosion), a fan
                  // of thick arms much longer downwind than upwind, its top cut flat by the
                  // tropopause.
                  segment({0.25f, 0.50f, 0.80f}, {0.95f, 0.50f, 0.80f}, 0.045f, 0.06f, 24, 0.3f),
                  segment({0.42f, 0.50f, 0.80f}, {0.92f, 0.30f, 0.80f}, 0.04f, 0.06f, 25, 0.3f),
                  segment({0.42f, 0.50f, 0.80f}, {0.92f, 0.70f, 0.80f}, 0.04f, 0.06f, 26, 0.3f),
                  segment({0.30f, 0.40f, 0.80f}, {0.80f, 0.18f, 0.79f}, 0.035f, 0.06f, 30, 0.3f),
                  segment({0.30f, 0.60f, 0.80f}, {0.80f, 0.82f, 0.79f}, 0.035f, 0.06f, 31, 0.3f),
                  point({0.44f, 0.50f, 0.82f}, 0.05f, 0.06f, 27)};  // the overshooting top
  for (std::size_t i = 5; i < 10; ++i) m.primitives[i].noise.erosion = 0.3f;
  return m;
}

CloudModel stratocumulus() {
  CloudModel m;
  m.description = "stratocumulus: a row of flat, merging cells along x";
  m.extent_m = 5000;
  m.base = 0.27f;
  m.top = 0.37f;  // the inversion that flattens the cells' tops
  for (int i = 0; i < 6; ++i)
    m.primitives.push_back(point({0.18f + 0.13f * float(i), 0.50f + (i % 2 ? 0.03f : -0.03f), 0.30f}, 0.04f, 0.07f,
                                 std::uint32_t(31 + i), 0.6f));
  return m;
}

}  // namespace

const std::vector<std::string>& example_names() {
  static const std::vector<std::string> names = {"fair-weather", "towering", "cumulonimbus", "stratocumulus"};
  return names;
}

CloudModel example(const std::string& name) {
  if (name == "fair-weather") return fair_weather();
  if (name == "towering") return towering();
  if (name == "cumulonimbus") return cumulonimbus();
  if (name == "stratocumulus") return stratocumulus();
  throw ModelError("--example", "'" + name + "'", "fair-weather, towering, cumulonimbus, stratocumulus");
}

}  // namespace nephele::model
