#pragma once
// A cloud made of implicit primitives (Montenegro et al.; docs/model.md): points and segment
// skeletons in the unit cube (z up), Wyvill-1 fields blended with Lipus's operator and
// detailed by turbulence, per primitive (eq. 6) or once after blending (eq. 5).
#include <cstdint>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "params/table.hpp"
#include "shader_math/shader_math.hpp"

namespace nephele::model {

// Extinction per metre of density 1: a cumulus's liquid water content 0.5 g/m^3 with droplets
// of effective radius 10 um gives beta = 3 LWC / (2 rho_w r_e) = 0.075 / m (docs/model.md).
constexpr double density_to_extinction_per_m = 0.075;

// Bad model input (an option, a file key, a value): exit code 2.
using ModelError = core::InputError;

enum class Blend { sum, lipus, global, per_primitive };
Blend parse_blend(const std::string& word, const std::string& where);
const char* blend_name(Blend blend);
int blend_code(Blend blend);  // MODEL_BLEND_* of implicit_field.glsl

struct Turbulence {
  int octaves = params::cloud_model::octaves.default_int();
  float frequency = params::cloud_model::frequency.default_float();
  float amplitude = params::cloud_model::amplitude.default_float();
  float gain = params::cloud_model::gain.default_float();
  float lacunarity = params::cloud_model::lacunarity.default_float();
  float fraction = params::cloud_model::fraction.default_float();  // np
  float erosion = params::cloud_model::erosion.default_float();    // e of model_erode
  std::uint32_t seed = params::cloud_model::seed.default_uint32();
};

struct Primitive {
  bool segment = false;
  glsl::vec3 from{0.5f};  // the point, or the segment's start
  glsl::vec3 to{0.5f};    // the segment's end
  float radius = params::cloud_model::radius.default_float();
  float influence = params::cloud_model::influence.default_float();
  float weight = params::cloud_model::weight.default_float();
  Turbulence noise;
};

// A turbulence's and a primitive's numbers with the table's declarations that rule them, in
// table order: f(const params::Parameter&, field&). The checks, the model files and nephele
// view's sliders all go through these, so a value added here reaches each of them. (The
// skeleton's points are vectors of params::cloud_model::coordinate, visited by nobody.)
template <class T, class F>  // T: Turbulence or const Turbulence
void visit_turbulence(T& t, F&& f) {
  namespace cm = params::cloud_model;
  f(cm::octaves, t.octaves);
  f(cm::frequency, t.frequency);
  f(cm::amplitude, t.amplitude);
  f(cm::gain, t.gain);
  f(cm::lacunarity, t.lacunarity);
  f(cm::fraction, t.fraction);
  f(cm::erosion, t.erosion);
  f(cm::seed, t.seed);
}
template <class P, class F>  // P: Primitive or const Primitive
void visit_primitive(P& p, F&& f) {
  namespace cm = params::cloud_model;
  f(cm::radius, p.radius);
  f(cm::influence, p.influence);
  f(cm::weight, p.weight);
}

bool operator==(const Turbulence& a, const Turbulence& b);
bool operator==(const Primitive& a, const Primitive& b);
inline bool operator!=(const Turbulence& a, const Turbulence& b) { return !(a == b); }
inline bool operator!=(const Primitive& a, const Primitive& b) { return !(a == b); }

// The most primitives of one model, polylines counted by their segments: the density pass
// evaluates every primitive of a brick, so a model of 756000 segments took 52 s and 2 GB even
// at --size 8. The examples have 1 to 50 (docs/formats.md, "Input limits").
constexpr std::size_t max_primitives = 4096;

struct CloudModel {
  std::string description;
  Blend blend = Blend::per_primitive;
  float scale = params::cloud_model::scale.default_float();
  double extent_m = params::cloud_model::extent.default_number;
  // The flat base (condensation level) and top (tropopause) in model units of z; 0 and 1 cut
  // nothing (model_levels of implicit_field.glsl).
  float base = params::cloud_model::base.default_float();
  float top = params::cloud_model::top.default_float();
  Turbulence noise;  // eq. 5's global turbulence, and the default of each primitive's
  std::vector<Primitive> primitives;
};

// Whether two models agree in everything but their primitives' values (blend, scale, extent,
// levels, global noise and the number of primitives): then a density volume of one becomes the
// other's by recomputing only the primitives that differ (DensityVolume::edit).
bool same_but_primitives(const CloudModel& a, const CloudModel& b);

// Checks every value against the table and the rule of eq. 3 (one weight for all primitives
// in the Lipus blends); throws ModelError naming `source` and the primitive.
void validate(const CloudModel& model, const std::string& source);

glsl::ModelNoise pack(const Turbulence& t);
glsl::ModelPrimitive pack(const Primitive& p);

// The distance from a skeleton beyond which the field is exactly 0: R + I.
inline float reach(const Primitive& p) { return p.radius + p.influence; }

// The turbulence's highest frequency (cycles per unit of noise coordinates) in a volume of
// `size` voxels an edge: a quarter of the voxels per model unit, so no octave is finer than
// 4 voxels a cycle (model_turbulence fades it from 8 voxels on). 0 for size 0: every octave.
float max_noise_frequency(const CloudModel& model, int size);
// The (base, top) levels that model_finish takes.
glsl::vec2 levels(const CloudModel& model);

// The density at model point p (unit cube) on the CPU, through the shared functions, as the
// density volume of `size` voxels an edge holds it (0: with every octave of the turbulence).
float density_at(const CloudModel& model, glsl::vec3 p, int size = 0);

// The built-in examples (docs/model.md): names and models.
const std::vector<std::string>& example_names();
CloudModel example(const std::string& name);

// Cloud model files are read and written by src/io/cloud_model_files.hpp.

}  // namespace nephele::model
