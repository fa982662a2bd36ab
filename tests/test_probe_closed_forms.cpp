// Functions of the GLSL library (shaders/lib), run on the GPU through their files' probes
// (tests/probes/NAME.glsl, the harness of library_probes.hpp), against values known in closed
// form: worked out by hand from the mathematics, not from the C++ twin (test_library_probes.cpp
// compares with that). Dependencies are stubbed with inputs whose results are known (constant
// data, axis-aligned rays, lattice points). One dispatch per probe file.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "cover/curl_spline.hpp"
#include "gl_support.hpp"
#include "library_probes.hpp"
#include "shader_math/shader_math.hpp"

// The probes' function codes (their PROBE_... constants); the C++ functions are not called here.
namespace nephele::glsl {
namespace {
#include "probes/atmosphere.glsl"
#include "probes/cloud_density.glsl"
#include "probes/cover_density.glsl"
#include "probes/cube_faces.glsl"
#include "probes/cube_sampling.glsl"
#include "probes/curl_spline.glsl"
#include "probes/equirect_mapping.glsl"
#include "probes/implicit_field.glsl"
#include "probes/latitude_bands.glsl"
#include "probes/perlin.glsl"
#include "probes/portable_math.glsl"
#include "probes/ray_sphere.glsl"
#include "probes/tileable_noise.glsl"
#include "probes/webanck_forms.glsl"
#include "probes/worley.glsl"
}  // namespace
}  // namespace nephele::glsl

using namespace nephele;
using namespace nephele::glsl;
using test::arguments;
using test::kArithmetic;
using test::kExact;
using test::kTranscendental;
using test::kUlp;

namespace {

// A component that is not asserted (left undefined by the function there, or without a closed
// form).
const float kAny = std::numeric_limits<float>::quiet_NaN();

const double kPi = 3.14159265358979323846;

struct ClosedForm {
  const char* identity;  // what the mathematics says, for the failure message
  mat4 input;            // test::arguments: the probe's PROBE_... code and the function's arguments
  vec4 expected;         // kAny: not asserted
  float tolerance;       // absolute, per component
};

// Runs all cases of one probe file in one dispatch and compares each asserted component.
void check_closed_forms(const std::string& name, const std::vector<ClosedForm>& cases,
                        const std::vector<vec4>& data = {}, gpu::ProbeData kind = gpu::ProbeData::buffer) {
  std::vector<mat4> inputs;
  for (const auto& c : cases) inputs.push_back(c.input);
  const auto gpu = test::run_library_probe(name, inputs, data, kind);
  REQUIRE(gpu.size() == cases.size());
  const auto functions = test::probe_function_names(test::probe_text(name));
  for (size_t k = 0; k < cases.size(); ++k) {
    const int code = int(cases[k].input[0].x);
    INFO("tests/probes/" << name << ".glsl " << (functions.count(code) ? functions.at(code) : "function") << " (code "
                         << code << "): " << cases[k].identity);
    for (int i = 0; i < 4; ++i) {
      if (std::isnan(cases[k].expected[i])) continue;
      INFO("component " << i << ": GPU " << gpu[k][i] << ", closed form " << cases[k].expected[i]);
      CHECK(std::abs(gpu[k][i] - cases[k].expected[i]) <= cases[k].tolerance);
    }
  }
}

// The standard normal CDF from the C library's erfc (double), independent of the library's
// Abramowitz and Stegun approximation.
float normal_cdf_exact(double z) { return float(0.5 * std::erfc(-z / std::sqrt(2.0))); }

}  // namespace

TEST_CASE("portable_asin on the GPU gives 0, +-pi/2, +-pi/6 and pi/4 at 0, +-1, +-1/2 and sqrt(2)/2",
          "[probe][closed-form]") {
  // Abramowitz and Stegun 4.4.46 errs by 2e-8; the float evaluation (8 multiply-adds and a sqrt
  // of values below 1.6) by kArithmetic, as in the twin probe.
  const auto asin_case = [](const char* identity, float x, double expected) {
    return ClosedForm{identity, arguments(PROBE_PORTABLE_ASIN, vec4(x, 0, 0, 0)), vec4(float(expected), 0, 0, 0),
                      kArithmetic};
  };
  check_closed_forms("portable_math", {
                                          asin_case("asin 0 = 0", 0.0f, 0.0),
                                          asin_case("asin 1 = pi/2", 1.0f, kPi / 2),
                                          asin_case("asin -1 = -pi/2", -1.0f, -kPi / 2),
                                          asin_case("asin 1/2 = pi/6", 0.5f, kPi / 6),
                                          asin_case("asin -1/2 = -pi/6", -0.5f, -kPi / 6),
                                          asin_case("asin sqrt(2)/2 = pi/4", 0.70710678f, kPi / 4),
                                      });
}

TEST_CASE("ray_sphere and ray_shell on the GPU give the known distances of axis-aligned rays", "[probe][closed-form]") {
  // Small integers: dot products, the discriminant and its square root's argument are exact; the
  // square root (GLSL: 1/inversesqrt, 2 + 2.5 ulp) and the final sum round by at most 8 ulp of
  // results below 16.
  const float tolerance = 8 * 16 * kUlp;
  const vec4 z(0, 0, 1, 0), x(1, 0, 0, 0), origin(0.0f);
  const auto sphere = [&](const char* identity, vec4 o, vec4 d, vec4 c, float r, vec2 expected) {
    return ClosedForm{identity, arguments(PROBE_RAY_SPHERE, vec4(r, 0, 0, 0), o, d, c), vec4(expected, 0.0f, 0.0f),
                      tolerance};
  };
  const auto shell = [&](const char* identity, vec4 o, vec4 d, float limit, vec4 expected) {
    return ClosedForm{identity, arguments(PROBE_RAY_SHELL, vec4(1.0f, 2.0f, limit, 0), o, d, origin), expected,
                      tolerance};
  };
  check_closed_forms(
      "ray_sphere",
      {
          sphere("from z = -5 along +z, radius 2: enters at 3, leaves at 7", vec4(0, 0, -5, 0), z, origin, 2.0f,
                 vec2(3, 7)),
          sphere("from the centre: -r and r", origin, x, origin, 2.0f, vec2(-2, 2)),
          sphere("1 off the axis beyond the radius: the miss (1, -1)", vec4(0, 3, -5, 0), z, origin, 2.0f, vec2(1, -1)),
          sphere("tangent: both roots at 5", vec4(0, 2, -5, 0), z, origin, 2.0f, vec2(5, 5)),
          sphere("sphere of radius 3 about (10, 0, 0) from the origin: 7 and 13", origin, x, vec4(10, 0, 0, 0), 3.0f,
                 vec2(7, 13)),
          shell("through the shell 1..2 from z = -5: [3, 4] and [6, 7]", vec4(0, 0, -5, 0), z, 100.0f,
                vec4(3, 4, 6, 7)),
          shell("the limit 3.5 cuts the first interval: [3, 3.5]", vec4(0, 0, -5, 0), z, 3.5f, vec4(3, 3.5f, 0, 0)),
          shell("from the centre: [0, 0] empty, then [1, 2]", origin, x, 100.0f, vec4(0, 0, 1, 2)),
          shell("from inside the shell outwards: [0, 0.5]", vec4(1.5f, 0, 0, 0), x, 100.0f, vec4(0, 0.5f, 0, 0)),
          shell("a ray that misses: all 0", vec4(0, 3, -5, 0), z, 100.0f, vec4(0.0f)),
      });
}

TEST_CASE("cube_faces on the GPU maps the six axes to faces 0 to 5, their face centres and centre texels",
          "[probe][closed-form]") {
  // GL's table 8.19: +X, -X, +Y, -Y, +Z, -Z.
  const vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  // A unit vector through inversesqrt (2 ulp) and a product: 4 ulp of values below 1. A division
  // by 2 of values below 1: GLSL's 2.5 ulp.
  const float unit = 4 * kUlp;
  std::vector<ClosedForm> cases;
  for (int face = 0; face < 6; ++face) {
    const vec4 axis(axes[face], 0.0f);
    // Selection, negation and a zero over 1 are exact.
    cases.push_back({"an axis selects its face", arguments(PROBE_CUBE_FACE_OF, vec4(0.0f), axis),
                     vec4(float(face), 0, 0, 0), kExact});
    cases.push_back({"the face centre (0, 0) is the axis", arguments(PROBE_CUBE_FACE_POINT, vec4(float(face), 0, 0, 0)),
                     axis, kExact});
    cases.push_back({"the axis has face coordinates (0, 0)",
                     arguments(PROBE_CUBE_FACE_COORDS, vec4(float(face), 0, 0, 0), axis), vec4(0.0f), kExact});
    cases.push_back({"the one texel of a 1 x 1 face points along the axis",
                     arguments(PROBE_TEXEL_DIRECTION, vec4(float(face), 0, 0, 0), vec4(1, 0, 0, 0)), axis, unit});
  }
  // Texel (0, 0) of a 2 x 2 +X face: sc = tc = -1/2, the point (1, 1/2, 1/2), over sqrt(3/2).
  const float s = float(1 / std::sqrt(1.5));
  cases.push_back({"texel (0, 0) of a 2 x 2 +X face: (2, 1, 1) / sqrt 6",
                   arguments(PROBE_TEXEL_DIRECTION, vec4(0, 0, 0, 0), vec4(2, 0, 0, 0)),
                   vec4(s, 0.5f * s, 0.5f * s, 0.0f), 2 * unit});
  cases.push_back({"(2, 1, -1) on +X: (-z, -y) / |x| = (1/2, -1/2)",
                   arguments(PROBE_CUBE_FACE_COORDS, vec4(0, 0, 0, 0), vec4(2, 1, -1, 0)), vec4(0.5f, -0.5f, 0, 0),
                   2.5f * kUlp});
  check_closed_forms("cube_faces", cases);
}

TEST_CASE("equirect_mapping on the GPU puts known longitudes and latitudes where the map's formulas say",
          "[probe][closed-form]") {
  // Longitudes: a division, a product and a difference of values below 2 pi < 8: 3 x 3.5 ulp of 8,
  // within kArithmetic (8 x 3.5 ulp of 4). Directions and texture coordinates: a few operations
  // around the driver's cos, sin or atan and portable_asin: kTranscendental, as in the twin probe.
  const auto longitude = [](const char* identity, int column, int width, double expected) {
    return ClosedForm{identity, arguments(PROBE_EQUIRECT_LONGITUDE, vec4(float(column), float(width), 0, 0)),
                      vec4(float(expected), 0, 0, 0), kArithmetic};
  };
  const auto uv = [](const char* identity, vec3 n, float u, float v) {
    return ClosedForm{identity, arguments(PROBE_EQUIRECT_UV, vec4(0.0f), vec4(n, 0.0f)), vec4(u, v, 0, 0),
                      kTranscendental};
  };
  const float h = float(std::sqrt(0.5)), c3 = float(std::sqrt(0.75));
  check_closed_forms(
      "equirect_mapping",
      {
          longitude("column 0 of 2 is centred at -90 degrees", 0, 2, -kPi / 2),
          longitude("column 1 of 2 is centred at 90 degrees", 1, 2, kPi / 2),
          longitude("the one column of 1 is centred at 0", 0, 1, 0.0),
          longitude("column 3 of 4 is centred at 135 degrees", 3, 4, 3 * kPi / 4),
          {"column 1 of 2 on the equator points along +y",
           arguments(PROBE_EQUIRECT_DIRECTION, vec4(1, 2, 0, 0), vec4(1, 0, 0, 0)), vec4(0, 1, 0, 0), kTranscendental},
          {"column 0 of 4 at latitude 60 degrees: longitude -135 degrees",
           arguments(PROBE_EQUIRECT_DIRECTION, vec4(0, 4, 0, 0), vec4(0.5f, c3, 0, 0)),
           vec4(float(0.5 * std::cos(-0.75 * kPi)), float(0.5 * std::sin(-0.75 * kPi)), c3, 0), kTranscendental},
          uv("+x (0, 0) is the map's centre", vec3(1, 0, 0), 0.5f, 0.5f),
          uv("+y (90 E) is at u = 3/4", vec3(0, 1, 0), 0.75f, 0.5f),
          uv("-y (90 W) is at u = 1/4", vec3(0, -1, 0), 0.25f, 0.5f),
          uv("latitude 45 degrees on the prime meridian is at v = 1/4", vec3(h, 0, h), 0.5f, 0.25f),
          // atan(0, 0) is undefined in GLSL: the poles' u is not asserted.
          uv("the north pole is the top row, v = 0", vec3(0, 0, 1), kAny, 0.0f),
          uv("the south pole is the bottom row, v = 1", vec3(0, 0, -1), kAny, 1.0f),
      });
}

TEST_CASE("latitude_bands on the GPU gives -1/2, bands/2 - 1/2 and bands - 1/2 at the poles and the equator",
          "[probe][closed-form]") {
  // The coordinate (asin z + pi/2) bands/pi - 1/2: portable_asin within kArithmetic (the
  // portable_math case) times 90/pi < 32 (the twin probe's bound).
  const float coordinate = 32.0f * kArithmetic;
  const auto at = [&](const char* identity, vec3 direction, int bands, float expected) {
    return ClosedForm{identity, arguments(PROBE_BAND_COORDINATE, vec4(float(bands), 0, 0, 0), vec4(direction, 0)),
                      vec4(expected, 0, 0, 0), coordinate};
  };
  // Bands, fractions and neighbours: floor, subtraction of it and integer arithmetic on
  // coordinates with few bits: exact.
  const auto band = [](const char* identity, float c, vec4 expected) {
    return ClosedForm{identity, arguments(PROBE_BAND_OF, vec4(90, c, 0, 0)), expected, kExact};
  };
  const auto neighbours = [](const char* identity, float c, vec4 expected) {
    return ClosedForm{identity, arguments(PROBE_BAND_NEIGHBOURS, vec4(90, c, 0, 0)), expected, kExact};
  };
  // Catmull-Rom at t = 0, 1/2, 1: every product and sum of these dyadic numbers is exact.
  const auto weights = [](const char* identity, float t, vec4 expected) {
    return ClosedForm{identity, arguments(PROBE_CATMULL_ROM_WEIGHTS, vec4(0, t, 0, 0)), expected, kExact};
  };
  check_closed_forms("latitude_bands",
                     {
                         at("the north pole of 90 bands: 89.5", vec3(0, 0, 1), 90, 89.5f),
                         at("the south pole: -0.5", vec3(0, 0, -1), 90, -0.5f),
                         at("the equator of 90 bands: 44.5", vec3(1, 0, 0), 90, 44.5f),
                         at("the equator of 2 bands: 0.5", vec3(0, 1, 0), 2, 0.5f),
                         band("-0.5 (the south pole) lies in band 0, fraction 1/2", -0.5f, vec4(0, 0.5f, 0, 0)),
                         band("89.5 (the north pole) lies in band 89, fraction 1/2", 89.5f, vec4(89, 0.5f, 0, 0)),
                         band("44.25 lies in band 44, fraction 1/4", 44.25f, vec4(44, 0.25f, 0, 0)),
                         neighbours("mirrored at the south pole: 1, 0, 0, 1", -0.25f, vec4(1, 0, 0, 1)),
                         neighbours("mirrored at the north pole: 88, 89, 89, 88", 89.25f, vec4(88, 89, 89, 88)),
                         neighbours("inside: 43 to 46 around 44.5", 44.5f, vec4(43, 44, 45, 46)),
                         weights("t = 0: the value at k", 0.0f, vec4(0, 1, 0, 0)),
                         weights("t = 1: the value at k + 1", 1.0f, vec4(0, 0, 1, 0)),
                         weights("t = 1/2: (-1, 9, 9, -1) / 16", 0.5f, vec4(-1.0f, 9.0f, 9.0f, -1.0f) / 16.0f),
                     });
}

TEST_CASE("cloud_density on the GPU gives its steps' end values, the isotropic phase 1/(4 pi) and no density outside",
          "[probe][closed-form]") {
  // Clamped Hermite steps give exactly 0 and 1 (t is clamped before the cubic), and so do the
  // products of such steps and of exact constants. Inside a step, t comes from a division
  // (2.5 ulp) and the cubic adds a few roundings: kArithmetic, as in the twin probe.
  const auto density = [](const char* identity, int function, vec4 a, vec4 b, vec4 expected, float tolerance) {
    return ClosedForm{identity, arguments(function, a, b), expected, tolerance};
  };
  const float inverse_4pi = float(1 / (4 * kPi));
  // Henyey-Greenstein at nu = -1: (1 - g) / (1 + g)^2 for the forward lobe g = 0.8 and
  // (1 + |g|) / (1 - |g|)^2 for the back lobe g = -0.3, mixed 70:30 (cloud_phase).
  const float backward = float((0.7 * 0.2 / (1.8 * 1.8) + 0.3 * 1.3 / (0.7 * 0.7)) / (4 * kPi));
  // light_sample's distances, below 100 m: kArithmetic's 28 ulp relative.
  const float metres = 100.0f * 28 * kUlp;
  const vec4 none(0.0f);
  check_closed_forms(
      "cloud_density",
      {
          density("H(0, 1, 0) = 0", PROBE_HERMITE_STEP, vec4(0, 1, 0, 0), none, vec4(0.0f), kExact),
          density("H(0, 1, 1) = 1", PROBE_HERMITE_STEP, vec4(0, 1, 1, 0), none, vec4(1, 0, 0, 0), kExact),
          density("H(0, 1, -3) = 0 below the step", PROBE_HERMITE_STEP, vec4(0, 1, -3, 0), none, vec4(0.0f), kExact),
          density("H(0, 1, 7) = 1 above it", PROBE_HERMITE_STEP, vec4(0, 1, 7, 0), none, vec4(1, 0, 0, 0), kExact),
          density("H(0, 1, 1/2) = 1/2", PROBE_HERMITE_STEP, vec4(0, 1, 0.5f, 0), none, vec4(0.5f, 0, 0, 0),
                  kArithmetic),
          density("H(2, 4, 3) = 1/2 at the midpoint", PROBE_HERMITE_STEP, vec4(2, 4, 3, 0), none, vec4(0.5f, 0, 0, 0),
                  kArithmetic),
          density("H(0, 1, 1/4) = 3/16 - 2/64 = 5/32", PROBE_HERMITE_STEP, vec4(0, 1, 0.25f, 0), none,
                  vec4(0.15625f, 0, 0, 0), kArithmetic),
          density("a sheet's profile is 0 at its base", PROBE_SHEET_PROFILE, vec4(0, 0.25f, 0, 0), none, vec4(0.0f),
                  kExact),
          density("a sheet's profile is 1 in its middle", PROBE_SHEET_PROFILE, vec4(0.5f, 0.25f, 0, 0), none,
                  vec4(1, 0, 0, 0), kExact),
          density("a sheet's profile is 0 at its top", PROBE_SHEET_PROFILE, vec4(1, 0.25f, 0, 0), none, vec4(0.0f),
                  kArithmetic),
          // cloud_density(type x[1].z, h, c, shape, detail x[1].x).
          density("no cover, no cloud", PROBE_CLOUD_DENSITY, vec4(0.5f, 0, 0.7f, 0), vec4(1, 0, CLOUD_STRATUS, 0),
                  vec4(0.0f), kExact),
          density("no cloud below the layer", PROBE_CLOUD_DENSITY, vec4(-0.1f, 0.9f, 0.7f, 0),
                  vec4(1, 0, CLOUD_STRATUS, 0), vec4(0.0f), kExact),
          density("no cloud above the layer", PROBE_CLOUD_DENSITY, vec4(1.5f, 0.9f, 0.7f, 0),
                  vec4(1, 0, CLOUD_CIRRUS, 0), vec4(0.0f), kExact),
          density("cumulus has no density of this kind (Webanck's forms)", PROBE_CLOUD_DENSITY,
                  vec4(0.5f, 0.9f, 0.7f, 0), vec4(1, 0, CLOUD_CUMULUS, 0), vec4(0.0f), kExact),
          density("cirrostratus in mid-layer with full detail: c", PROBE_CLOUD_DENSITY, vec4(0.5f, 0.8f, 0.3f, 0),
                  vec4(1, 0, CLOUD_CIRROSTRATUS, 0), vec4(0.8f, 0, 0, 0), kExact),
          density("fog below its top: c", PROBE_FOG_DENSITY, vec4(0.2f, 0.6f, 0, 0), vec4(1, 0, 0, 0),
                  vec4(0.6f, 0, 0, 0), kArithmetic),
          density("fog above its lowered top: 0", PROBE_FOG_DENSITY, vec4(1, 0.6f, 1, 0), vec4(1, 0, 0, 0), vec4(0.0f),
                  kExact),
          density("uniform_from_mix keeps 0", PROBE_UNIFORM_FROM_MIX, vec4(0, 0.25f, 0, 0), none, vec4(0.0f), kExact),
          density("uniform_from_mix keeps 1", PROBE_UNIFORM_FROM_MIX, vec4(1, 0.25f, 0, 0), none, vec4(1, 0, 0, 0),
                  kExact),
          density("uniform_from_mix keeps the median 1/2", PROBE_UNIFORM_FROM_MIX, vec4(0.5f, 0.25f, 0, 0), none,
                  vec4(0.5f, 0, 0, 0), kArithmetic),
          density("uniform_from_mix on the first ramp: x^2 / (2ab) = 1/24", PROBE_UNIFORM_FROM_MIX,
                  vec4(0.125f, 0.25f, 0, 0), none, vec4(1.0f / 24.0f, 0, 0, 0), kArithmetic),
          density("scale 0: isotropic, 1/(4 pi)", PROBE_CLOUD_PHASE, vec4(0.3f, 0, 0, 0), none,
                  vec4(inverse_4pi, 0, 0, 0), kTranscendental),
          density("backwards: 0.7 (1 - g)/(1 + g)^2 + 0.3 (1 + |g'|)/(1 - |g'|)^2 over 4 pi", PROBE_CLOUD_PHASE,
                  vec4(-1, 1, 0, 0), none, vec4(backward, 0, 0, 0), kTranscendental),
          density("sample 0 of 2 over 100 m: midpoint 6.25 m, step 25 m", PROBE_LIGHT_SAMPLE, vec4(0, 2, 100, 0), none,
                  vec4(6.25f, 25, 0, 0), metres),
          density("sample 1 of 2 over 100 m: midpoint 56.25 m, step 75 m", PROBE_LIGHT_SAMPLE, vec4(1, 2, 100, 0), none,
                  vec4(56.25f, 75, 0, 0), metres),
          density("powder of strength 0: 1", PROBE_POWDER_FACTOR, vec4(0.3f, -1, 0, 0), none, vec4(1, 0, 0, 0), kExact),
          density("powder towards the sun (nu = 1): 1", PROBE_POWDER_FACTOR, vec4(0.3f, 1, 1, 0), none,
                  vec4(1, 0, 0, 0), kExact),
          density("full powder at the surface, sun behind: 0", PROBE_POWDER_FACTOR, vec4(0, -1, 1, 0), none, vec4(0.0f),
                  kTranscendental),
          density("behind an optical depth of 2000 no sun is left", PROBE_SUN_SCATTERING, vec4(2000, 0.3f, 0, 0), none,
                  vec4(0.0f), kTranscendental),
      });
}

TEST_CASE("atmosphere on the GPU: the phase functions in closed form, and a zero-length path transmits all",
          "[probe][closed-form]") {
  const float R = 6360000.0f;
  // Phases: a few products, a division and a sqrt of values below 4: kArithmetic. Extinction,
  // transmittance: exp within kTranscendental.
  const auto phase = [&](const char* identity, int function, float nu, float g, double expected) {
    return ClosedForm{identity, arguments(function, vec4(R, nu, g, 0)), vec4(kAny, kAny, kAny, float(expected)),
                      kArithmetic};
  };
  // Extinction scaled by 1e5 (the probe's scale): Rayleigh scattering plus Mie extinction at sea
  // level, where both exponentials are 1.
  const vec3 sea_level = (rayleigh_scattering() + vec3(MIE_EXTINCTION)) * 1.0e5f;
  const auto extinction = [&](const char* identity, float h, vec3 expected) {
    return ClosedForm{identity, arguments(PROBE_AIR_EXTINCTION, vec4(R, h, 0, 0)), vec4(expected, 0.0f),
                      kTranscendental};
  };
  const auto transmittance = [&](const char* identity, vec3 p, vec3 d, float expected) {
    return ClosedForm{identity, arguments(PROBE_TRANSMITTANCE_TO_SPACE, vec4(R, 0, 0, 0), vec4(p, 0), vec4(d, 0)),
                      vec4(vec3(expected), 0.0f), kTranscendental};
  };
  // A path of length 0 along +x at sea level, the sun overhead (nu = 0), 8 steps: each step's
  // transmittance is exp(0), within 3 ulp of 1 (GLSL 4.50, 4.7.1), so each adds at most 3 ulp
  // of source / extinction <= phase x irradiance < 0.06 x 1.92 (both phases are below 3/(16 pi)
  // at nu = 0 and scattering is below extinction), scaled by 1e3; the transmittance is a product
  // of 8 such factors: 24 ulp.
  const float scattered = 8 * 3 * kUlp * 0.12f * 1.0e3f;
  const auto zero_path = [&](const char* identity, int part, vec4 expected, float tolerance) {
    return ClosedForm{identity,
                      arguments(PROBE_SKY_SINGLE_SCATTERING, vec4(R, float(part), 0, 0), vec4(0, 0, R, 0),
                                vec4(1, 0, 0, 0), vec4(0, 0, 1, 8)),
                      expected, tolerance};
  };
  check_closed_forms(
      "atmosphere",
      {
          phase("Rayleigh at 90 degrees: 3/(16 pi)", PROBE_RAYLEIGH, 0.0f, 0.0f, 3 / (16 * kPi)),
          phase("Rayleigh forwards: 3/(8 pi)", PROBE_RAYLEIGH, 1.0f, 0.0f, 3 / (8 * kPi)),
          phase("Rayleigh backwards: 3/(8 pi)", PROBE_RAYLEIGH, -1.0f, 0.0f, 3 / (8 * kPi)),
          phase("Henyey-Greenstein with g = 0: isotropic, 1/(4 pi)", PROBE_SUN_AND_HENYEY_GREENSTEIN, 0.3f, 0.0f,
                1 / (4 * kPi)),
          phase("Henyey-Greenstein forwards, g = 1/2: (1 + g)/(1 - g)^2/(4 pi) = 1.5/pi",
                PROBE_SUN_AND_HENYEY_GREENSTEIN, 1.0f, 0.5f, 1.5 / kPi),
          phase("Henyey-Greenstein backwards, g = 1/2: (1 - g)/(1 + g)^2/(4 pi)", PROBE_SUN_AND_HENYEY_GREENSTEIN,
                -1.0f, 0.5f, 0.5 / (2.25 * 4 * kPi)),
          extinction("at sea level: Rayleigh scattering plus Mie extinction", 0.0f, sea_level),
          extinction("below sea level: as at sea level", -100.0f, sea_level),
          extinction("at 1000 km: none (e^-125 underflows)", 1.0e6f, vec3(0.0f)),
          transmittance("from 200 km up: nothing to cross, 1", vec3(0, 0, R + 200000.0f), vec3(0, 0, 1), 1.0f),
          transmittance("horizontally from 200 km: the ray misses the atmosphere, 1", vec3(0, 0, R + 200000.0f),
                        vec3(1, 0, 0), 1.0f),
          transmittance("straight down from 10 m: the ground, 0", vec3(0, 0, R + 10.0f), vec3(0, 0, -1), 0.0f),
          zero_path("a zero-length path scatters no light in", 0, vec4(0.0f), scattered),
          zero_path("a zero-length path transmits everything", 2, vec4(1, 1, 1, 0), 24 * kUlp),
      });
}

TEST_CASE("cover_density on the GPU maps the threshold to 0 and the densest texel to 1, and shapes by given factors",
          "[probe][closed-form]") {
  // (d - t) / (d_max - t): a division (2.5 ulp) of values below 1, clamped; 0 exactly at or below
  // the threshold. The shaping: 4 products and sums of values below 2 (the existing hand check).
  const auto cover = [](const char* identity, float d, float t, float d_max, float expected, float tolerance) {
    return ClosedForm{identity, arguments(PROBE_COVER_FROM_DENSITY, vec4(d, t, d_max, 0)), vec4(expected, 0, 0, 0),
                      tolerance};
  };
  const auto shaped = [](const char* identity, float d, float cyclonic, float k, float b, float k_s, float expected,
                         float tolerance) {
    return ClosedForm{
        identity, arguments(PROBE_SHAPED_DENSITY, vec4(d, cyclonic, k, 0), vec4(0.0f), vec4(0.0f), vec4(0, b, k_s, 0)),
        vec4(expected, 0, 0, 0), tolerance};
  };
  check_closed_forms(
      "cover_density",
      {
          cover("below the threshold: 0", 0.3f, 0.5f, 1.0f, 0.0f, kExact),
          cover("at the threshold: 0", 0.5f, 0.5f, 1.0f, 0.0f, kExact),
          cover("the densest texel: 1", 1.0f, 0.5f, 1.0f, 1.0f, 2.5f * kUlp),
          cover("halfway: 1/2", 0.75f, 0.5f, 1.0f, 0.5f, 2.5f * kUlp),
          cover("no span above the threshold: 0", 0.7f, 0.8f, 0.6f, 0.0f, kExact),
          shaped("0.8 (1 + 0.5 x 0.6)(1 - 0.5 x 0.4) = 0.832", 0.8f, 0.6f, 0.5f, -0.4f, 0.5f, 0.832f, 4 * kUlp),
          shaped("zero weights leave the density", 0.8f, 0.6f, 0.0f, -0.4f, 0.0f, 0.8f, kExact),
          shaped("a full desert bias clears it: 0", 1.0f, 0.5f, 1.0f, -1.0f, 1.0f, 0.0f, kExact),
      });
}

TEST_CASE("perlin on the GPU: the quintic fade's 0, 1/2 and 1, bilinear weights, and zero noise on lattice points",
          "[probe][closed-form]") {
  // Dyadic arguments with few bits: every product and sum of the fade and the weights is exact;
  // wraps are integer arithmetic; on a lattice point every corner term is 0 or weighted by 0.
  const auto fade = [](const char* identity, float c, float period, float t, vec4 expected) {
    return ClosedForm{identity, arguments(PROBE_WRAP_AXIS_AND_FADE, vec4(c, period, t, 0)), expected, kExact};
  };
  const auto weights = [](const char* identity, float fy, float fz, vec4 expected) {
    return ClosedForm{identity, arguments(PROBE_PERLIN_YZ_WEIGHTS, vec4(fy, fz, 0, 0)), expected, kExact};
  };
  const vec4 key(12345, 678, 9, 0);
  const auto lattice = [&](const char* identity, vec4 p, vec4 period) {
    return ClosedForm{identity, arguments(PROBE_PERLIN_NOISE, vec4(0.0f), p, period, key), vec4(0.0f), kExact};
  };
  check_closed_forms(
      "perlin", {
                    fade("-1 wraps to 4 in period 5; fade(0) = 0", -1, 5, 0.0f, vec4(4, 0, 0, 0)),
                    fade("7 wraps to 2 in period 5; fade(1) = 1", 7, 5, 1.0f, vec4(2, 1, 0, 0)),
                    fade("period 0 leaves 3; fade(1/2) = 1/2", 3, 0, 0.5f, vec4(3, 0.5f, 0, 0)),
                    fade("-5 wraps to 0; fade(1/4) = 53/512", -5, 5, 0.25f, vec4(0, 53.0f / 512.0f, 0, 0)),
                    weights("at (0, 0): all on corner 00", 0, 0, vec4(1, 0, 0, 0)),
                    weights("at (1, 0): all on corner 10", 1, 0, vec4(0, 1, 0, 0)),
                    weights("at (1, 1): all on corner 11", 1, 1, vec4(0, 0, 0, 1)),
                    weights("at (1/2, 1/2): a quarter each", 0.5f, 0.5f, vec4(0.25f)),
                    lattice("0 at the origin", vec4(0.0f), vec4(0.0f)),
                    lattice("0 at the lattice point (3, -2, 7)", vec4(3, -2, 7, 0), vec4(0.0f)),
                    lattice("0 at the lattice point (5, 7, 3) of period (5, 7, 3)", vec4(5, 7, 3, 0), vec4(5, 7, 3, 0)),
                });
}

TEST_CASE("implicit_field on the GPU: Wyvill's field 1, 1/2 and 0, blends with 0 and w, and distances to skeletons",
          "[probe][closed-form]") {
  // wyvill1(x) = 1 - 22/9 x^2 + 17/9 x^4 - 4/9 x^6: at x = 1/2, 1 - 22/36 + 17/144 - 4/576 = 1/2.
  // Its float evaluation: 3 multiply-adds of values below 2.5 with rounded ninths; lengths: a sqrt
  // of an exact integer sum below 32; Lipus's blend and the turbulence: a few products and sums
  // below 2. All within kArithmetic.
  const auto parts = [](const char* identity, vec4 a, vec4 b, vec4 expected) {
    return ClosedForm{identity, arguments(PROBE_FIELD_PARTS, a, b), expected, kArithmetic};
  };
  // arguments: the point, (skeleton start, R), (skeleton end, I), (weight, kind).
  const auto primitive = [](const char* identity, vec3 p, vec4 a, vec4 b, vec4 kind, vec4 expected) {
    return ClosedForm{identity, arguments(PROBE_PRIMITIVE_FIELD, vec4(p, 0), a, b, kind), expected, kArithmetic};
  };
  const float segment = float(MODEL_SEGMENT), point = float(MODEL_POINT);
  check_closed_forms(
      "implicit_field",
      {
          // (wyvill1(x), lipus_blend(rho, g, w), apply_turbulence(f, N, np)).
          parts("b(0) = 1; rho + 0 = rho; no noise fraction leaves f", vec4(0, 0.3f, 0, 0), vec4(1, 0.7f, 5, 0),
                vec4(1, 0.3f, 0.7f, 0)),
          parts("b(1) = 0; rho = w stays w; N = 1 leaves f", vec4(1, 1, 0.4f, 0), vec4(1, 0.6f, 1, 0.3f),
                vec4(0, 1, 0.6f, 0)),
          parts("b(1/2) = 1/2; 1/2 blended with 1/2 at w = 1: 3/4; full noise of 0: 0", vec4(0.5f, 0.5f, 0.5f, 0),
                vec4(1, 2, 0, 1), vec4(0.5f, 0.75f, 0, 0)),
          parts("b(-0.2) = 1 inside the radius; 0 blended with 0: 0; noise 1/2 at fraction 1/2 on 1/2: 3/8",
                vec4(-0.2f, 0, 0, 0), vec4(1, 0.5f, 0.5f, 0.5f), vec4(1, 0, 0.375f, 0)),
          // (segment_distance, primitive_distance, primitive_field).
          primitive("1.5 from the middle of a segment of radius 1, influence 1: b(1/2) = 1/2, weight 0.8",
                    vec3(1, 1.5f, 0), vec4(0, 0, 0, 1), vec4(2, 0, 0, 1), vec4(0.8f, segment, 0, 0),
                    vec4(1.5f, 1.5f, 0.4f, 0)),
          primitive("(3, 4) beyond a segment's end: distance 5", vec3(4, 4, 0), vec4(0, 0, 0, 0), vec4(1, 0, 0, 10),
                    vec4(1, segment, 0, 0), vec4(5, 5, 0.5f, 0)),
          primitive("3 from a point primitive, beyond R + I: field 0", vec3(1, 1, 4), vec4(1, 1, 1, 0.5f),
                    vec4(1, 1, 1, 2), vec4(1, point, 0, 0), vec4(3, 3, 0, 0)),
          primitive("inside the radius: the weight", vec3(1, 0, 0), vec4(0, 0, 0, 2), vec4(0, 0, 0, 1),
                    vec4(0.7f, point, 0, 0), vec4(1, 1, 0.7f, 0)),
      });
}

TEST_CASE("tileable_noise on the GPU: octave steps and the unit maps' ends", "[probe][closed-form]") {
  // Octave steps: products and a rounding of exact dyadic values and small integers: exact. The
  // unit maps: a product by a rounded reciprocal, a sum and a division: kArithmetic.
  const auto octave = [](const char* identity, float lacunarity, float gain, float period, vec4 expected) {
    return ClosedForm{identity,
                      arguments(PROBE_NEXT_OCTAVE, vec4(0, 1, 0.25f, 0), vec4(0.0f), vec4(0.25f, 3, lacunarity, gain),
                                vec4(1, period, period, period)),
                      expected, kExact};
  };
  const auto unit = [](const char* identity, float a, float b, vec4 expected) {
    return ClosedForm{identity, arguments(PROBE_UNIT_MAPS, vec4(0, a, b, 0)), expected, kArithmetic};
  };
  const float third = float(0.3 / std::sqrt(3.0));
  check_closed_forms(
      "tileable_noise",
      {
          octave("lacunarity 2, gain 1/2: (1/2, 1/2), period 8 -> 16", 2, 0.5f, 8, vec4(0.5f, 0.5f, 16, 16)),
          octave("lacunarity 3, gain 1/4: (1/4, 3/4), period 5 -> 15", 3, 0.25f, 5, vec4(0.25f, 0.75f, 15, 15)),
          octave("period 0 stays 0", 2, 0.5f, 0, vec4(0.5f, 0.5f, 0, 0)),
          // (worley_unit(a), inverted, perlin_unit(b), perlin_worley(a, b)).
          unit("F1 = 0: 0 and 1; Perlin 0: 1/2; perlin_worley(0, 0) = 1/2", 0, 0, vec4(0, 1, 0.5f, 0.5f)),
          unit("F1 = sqrt 3 (its bound): 1 and 0; perlin_worley(p, 1) = p", WORLEY_F1_BOUND, 1,
               vec4(1, 0, kAny, WORLEY_F1_BOUND)),
          unit("F1 = 0.3: 0.3/sqrt 3; perlin_worley(0.3, 1) = 0.3", 0.3f, 1, vec4(third, 1 - third, kAny, 0.3f)),
          unit("Perlin at +PERLIN_BOUND: 1", 0, PERLIN_BOUND, vec4(kAny, kAny, 1, kAny)),
          unit("Perlin at -PERLIN_BOUND: 0", 0, -PERLIN_BOUND, vec4(kAny, kAny, 0, kAny)),
      });
}

TEST_CASE("webanck_forms on the GPU: the normal CDF within Abramowitz and Stegun's error of erfc",
          "[probe][closed-form]") {
  // A&S 7.1.26 errs by 1.5e-7 in erf (7.5e-8 in Phi); its float evaluation (a division, 5
  // multiply-adds and an exp) and the octave deviation's sqrt and division: kTranscendental.
  // The octave deviation sigma sqrt(sum a^2) / sum a of persistence a over n octaves.
  const auto sigma = [](int octaves, double persistence, double s) {
    double sum = 0, squares = 0, a = 1;
    for (int k = 0; k < octaves; ++k, a *= persistence) sum += a, squares += a * a;
    return s * std::sqrt(squares) / sum;
  };
  const auto cdf = [&](const char* identity, float z, int octaves, float persistence, float s) {
    return ClosedForm{identity, arguments(PROBE_NORMAL_CDF, vec4(z, float(octaves), persistence, 0), vec4(s, 0, 0, 0)),
                      vec4(normal_cdf_exact(z), float(sigma(octaves, persistence, s)),
                           normal_cdf_exact(z / sigma(octaves, persistence, double(PERLIN_OCTAVE_SIGMA))), 0),
                      kTranscendental};
  };
  check_closed_forms("webanck_forms", {
                                          cdf("Phi(0) = 1/2; one octave keeps sigma", 0.0f, 1, 0.5f, 0.3f),
                                          cdf("Phi(1); two equal octaves: sigma / sqrt 2", 1.0f, 2, 1.0f, 1.0f),
                                          cdf("Phi(-2); three octaves of persistence 1/2", -2.0f, 3, 0.5f, 0.2f),
                                          cdf("Phi(0.5)", 0.5f, 4, 0.52f, 0.27f),
                                      });
}

TEST_CASE("worley on the GPU wraps negative and large lattice indices into the period", "[probe][closed-form]") {
  // Integer arithmetic: exact.
  const vec4 key(0.0f);
  const auto wrap = [&](const char* identity, vec4 cell, vec4 period, vec4 expected) {
    return ClosedForm{identity, arguments(PROBE_WRAP_CELL, vec4(0.0f), cell, period, key), expected, kExact};
  };
  const auto neighbours = [&](const char* identity, vec4 cells, vec4 period, float step, vec4 expected) {
    return ClosedForm{identity, arguments(PROBE_WRAPPED_NEIGHBOURS, vec4(0, step, 0, 0), cells, period, key), expected,
                      kExact};
  };
  // wrap_cell(x[1].xyz) and the remainder of x[1].x by 7 from the quotient x[1].y.
  check_closed_forms(
      "worley", {
                    wrap("(-1, -1, 12) in (5, 7, 3): (4, 6, 0); -1 - 7 (-1) = 6", vec4(-1, -1, 12, 0), vec4(5, 7, 3, 0),
                         vec4(4, 6, 0, 6)),
                    wrap("(21, 2, -6) in 7: (0, 2, 1); a quotient one low, 21 - 14 = 7, corrected to 0",
                         vec4(21, 2, -6, 0), vec4(7, 7, 7, 0), vec4(0, 2, 1, 0)),
                    wrap("period 0 leaves (21, 4, 30); a quotient one high, 21 - 28 = -7, corrected to 0",
                         vec4(21, 4, 30, 0), vec4(0.0f), vec4(21, 4, 30, 0)),
                    neighbours("around 0 in period 5: 4, 0, 1; 6 + 1 in period 7: 0", vec4(0, 6, 0, 0),
                               vec4(5, 7, 0, 0), 1, vec4(4, 0, 1, 0)),
                    neighbours("around -6 in period 5: 3, 4, 0; -1 (6) - 1 in period 7: 5", vec4(-6, -1, 0, 0),
                               vec4(5, 7, 0, 0), -1, vec4(3, 4, 0, 5)),
                    neighbours("no period: 8, 9, 10; 3 + 1 = 4", vec4(9, 3, 0, 0), vec4(0.0f), 1, vec4(8, 9, 10, 4)),
                });
}

TEST_CASE("cube_sampling on the GPU reads the neighbouring face beyond an edge and averages 4 texels at an axis",
          "[probe][closed-form]") {
  // Texel (i, j) of face f holds (its direction, f).
  const int size = CUBE_PROBE_SIZE;
  const auto texels = test::cube_of(size, [](vec3 n, int face) { return vec4(n, float(face)); });
  const auto texel = [&](int face, int i, int j) { return texels[size_t((face * size + j) * size + i)]; };
  const auto read = [&](const char* identity, int face, int i, int j, vec4 expected) {
    return ClosedForm{identity, arguments(PROBE_CUBE_TEXEL_EXTENDED, vec4(float(face), float(i), float(j), 0)),
                      expected, kExact};
  };
  std::vector<ClosedForm> cases = {
      read("inside a face: the texel itself", 3, 1, 2, texel(3, 1, 2)),
      // GL's table 8.19: left of +X (sc < -1, so -z < -1) is +Z; right of +Y (x > 1) is +X; below
      // +Z (tc > 1, so -y > 1) is -Y.
      read("left of +X: a texel of +Z", 0, -1, 1, vec4(kAny, kAny, kAny, 4)),
      read("right of +Y: a texel of +X", 2, size, 1, vec4(kAny, kAny, kAny, 0)),
      read("below +Z: a texel of -Y", 4, 2, size, vec4(kAny, kAny, kAny, 3)),
  };
  // At an axis the four centre texels (1, 1) .. (2, 2) of the 4 x 4 face have weight 1/4 each:
  // their directions (1, +-1/4, +-1/4) / sqrt(1.125) average to the axis over sqrt(1.125). The
  // data's rounding, two mixes at 1/2 and the face coordinates: kArithmetic.
  const vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  const float centre = float(1 / std::sqrt(1.125));
  for (int face = 0; face < 6; ++face)
    cases.push_back({"an axis: the mean of the face's 4 centre texels, (axis / sqrt 1.125, face)",
                     arguments(PROBE_SAMPLE_CUBE_BILINEAR, vec4(0.0f), vec4(axes[face], 0.0f)),
                     vec4(centre * axes[face], float(face)), kArithmetic});
  check_closed_forms("cube_sampling", cases, texels, gpu::ProbeData::cube_image);
}

TEST_CASE("curl_spline on the GPU: B-spline weights at 0, 1/2 and 1, and a constant field reproduced",
          "[probe][closed-form]") {
  // Every node holds (1, 2, 3, 4).
  const int extent = cover::spline_coefficient_extent(SPLINE_PROBE_CELLS);
  const vec4 constant(1, 2, 3, 4);
  const std::vector<vec4> nodes(size_t(6 * extent * extent), constant);
  // Weights: sums and products of dyadic numbers (exact), then one product by the rounded 1/6:
  // 2 ulp of values below 1.
  const auto weights = [](const char* identity, float t, vec4 expected) {
    return ClosedForm{identity, arguments(PROBE_CUBIC_BSPLINE_WEIGHTS, vec4(t, 0, 0, 0)), expected, 2 * kUlp};
  };
  // The prefilter of such data: 8c - p - n = 6c exactly (small dyadic numbers), then the product
  // by the rounded 1/6: 2 ulp of values up to 4 (2^-21 each).
  const float prefilter = 2 * 8 * kUlp;
  // The spline of constant coefficients is the constant (the weights sum to 1). Each weight is
  // within kArithmetic (up to 8 operations on values below 4); 8 of them (both axes) scale
  // coefficients below 4, and the 31 products and sums of the 4 x 4 rows add 3.5 ulp of 4 each
  // (about 4 kArithmetic): 40 kArithmetic.
  const float reproduced = 40 * kArithmetic;
  const auto sample = [&](const char* identity, int function, vec3 w, vec4 expected) {
    return ClosedForm{identity, arguments(function, vec4(0.0f), vec4(normalize(w), 0.0f)), expected, reproduced};
  };
  check_closed_forms(
      "curl_spline",
      {
          weights("t = 0: (1, 4, 1, 0) / 6", 0.0f, vec4(1, 4, 1, 0) / 6.0f),
          weights("t = 1: (0, 1, 4, 1) / 6", 1.0f, vec4(0, 1, 4, 1) / 6.0f),
          weights("t = 1/2: (1, 23, 23, 1) / 48", 0.5f, vec4(1, 23, 23, 1) / 48.0f),
          {"the prefilter keeps a constant",
           arguments(PROBE_PREFILTER_CUBIC_BSPLINE, vec4(0.0f), constant, constant, constant), constant, prefilter},
          {"the prefilter keeps linear data: (8c - (c - s) - (c + s)) / 6 = c",
           arguments(PROBE_PREFILTER_CUBIC_BSPLINE, vec4(0.0f), constant - vec4(0.5f), constant, constant + vec4(0.5f)),
           constant, prefilter},
          sample("a constant field at +x", PROBE_SAMPLE_CURL_SPLINE, vec3(1, 0, 0), constant),
          sample("a constant field anywhere", PROBE_SAMPLE_CURL_SPLINE, vec3(0.3f, -0.5f, 0.81f), constant),
          sample("its velocity at +x: the tangent part (0, 2, 3)", PROBE_SPLINE_VELOCITY, vec3(1, 0, 0),
                 vec4(0, 2, 3, 0)),
          sample("its velocity at +z: the tangent part (1, 2, 0)", PROBE_SPLINE_WARP_VELOCITY, vec3(0, 0, 1),
                 vec4(1, 2, 0, 0)),
      },
      nodes, gpu::ProbeData::array_image);
}
