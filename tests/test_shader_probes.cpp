// Each GLSL library function run on the GPU on a small probe agrees with its C++ twin.
#include <catch2/catch.hpp>

#include <cstdio>
#include <random>

#include "cover/cover_parameters.hpp"
#include "curl_bounds.hpp"
#include "gl_support.hpp"
#include "shader_math/shader_math.hpp"

using namespace nephele;
using namespace nephele::glsl;
using nephele::test::probe;

namespace {

std::string literal(float f) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.9g", f);
  std::string s = buffer;
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}
std::string literal(uint32_t u) { return std::to_string(u) + "u"; }
std::string literal(const FbmParams& p) {
  return "FbmParams(" + literal(p.frequency) + ", " + std::to_string(p.octaves) + ", " + literal(p.lacunarity) + ", " +
         literal(p.gain) + ", " + literal(p.seed) + ", ivec3(" + std::to_string(p.period.x) + ", " +
         std::to_string(p.period.y) + ", " + std::to_string(p.period.z) + "))";
}
std::string literal(const CurlParams& c) {
  return "CurlParams(" + literal(c.potential_north) + ", " + literal(c.potential_south) + ", " + literal(c.prevailing) +
         ", " + literal(c.mix_frequency) + ", " + literal(c.strength) + ", " + literal(c.smoothing) + ", " +
         literal(c.storm_tracks) + ", " + std::to_string(c.zonal_cells) + ", " + literal(c.storm_track_shift) + ")";
}

// One float rounding, relative: 2^-24.
constexpr float kUlp = 1.0f / 16777216.0f;
// A texel direction: the face coordinates' division (GLSL: 2.5 ulp), normalize's inversesqrt
// (2 ulp) and multiply, and up to 2 contracted multiply-adds (1 ulp each): 8 ulp per component
// of a unit vector, sqrt(3) x 8 x 2^-24 = 8.3e-7 in length; rounded up to 1e-6.
constexpr float kDirection = 1.0e-6f;
static_assert(kDirection >= 1.7321f * 8 * kUlp);
// Worley F1 < sqrt(3) < 2: the squared distance's 3 products and 2 sums may be contracted into
// multiply-adds (1 ulp each of d^2 < 4, where the ulp is 2^-22), and sqrt halves the relative
// error: about 5 x 2^-22 / 2 = 6e-7; rounded up to 1e-6 (8 ulp of values in [1, 2)).
constexpr float kF1 = 1.0e-6f;
static_assert(kF1 >= 5 * (4 * kUlp) / 2);
// F1's gradient is delta / F1 with delta formed without products (no contraction, the same
// floats on both sides): an error dF1 turns it by dF1 / F1, so kF1 / F1 (floored at F1 = 1e-3).
// Not derivable in full: GLSL's division may add 2.5 ulp (3e-7 on the unit vector), which this
// bound covers only for F1 below about 0.7; llvmpipe's division is measured to be exact here.
constexpr float kF1GradientTimesF1 = kF1;
// An fBm of 5 octaves of F1 (each kF1) is their weighted mean (weights summing to 1) and a
// normalising division: kF1 + 2.5 ulp; 1e-5 leaves a factor of 9 (not tighter: kept as set).
constexpr float kFbmValue = 1.0e-5f;
// The fBm gradient: octave k's unit gradient turns by kF1 / F1_k (above) and is scaled by f_k;
// per unit of the highest frequency 1e-4 covers F1_k >= 0.01 cells everywhere (kF1 / 0.01).
// Not derivable for points nearer a feature point than 0.01 cells (probability about
// 4/3 pi 0.01^3 = 4e-6 per octave and point, none among the 256 random points here).
constexpr float kFbmGradientPerFrequency = 1.0e-4f;

std::vector<vec4> random_points(int n, float extent, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-extent, extent);
  std::vector<vec4> points(n);
  for (auto& p : points) p = vec4(u(rng), u(rng), u(rng), 0.0f);
  return points;
}

std::vector<vec4> random_directions(int n, unsigned seed) {
  auto points = random_points(n, 1.0f, seed);
  for (auto& p : points) p = vec4(normalize(vec3(p) + vec3(1e-3f)), 0.0f);
  return points;
}

}  // namespace

TEST_CASE("pcg3d on the GPU is bit-identical to the CPU", "[probe][hash]") {
  std::mt19937 rng(1);
  std::vector<uvec4> inputs(256);
  for (auto& v : inputs) v = uvec4(rng(), rng(), rng(), 0u);
  inputs[0] = uvec4(0u);
  inputs[1] = uvec4(0xFFFFFFFFu);
  const auto gpu = probe<uvec4>("#include \"../lib/hash.glsl\"", "pcg3d(input_value.xyz), 0u", inputs);
  for (size_t k = 0; k < inputs.size(); ++k) REQUIRE(uvec3(gpu[k]) == pcg3d(uvec3(inputs[k])));
}

TEST_CASE("cube face directions on the GPU agree with the CPU", "[probe][cube]") {
  const int size = 7;
  std::vector<vec4> inputs;
  for (int face = 0; face < 6; ++face)
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i) inputs.emplace_back(float(face), float(i), float(j), 0.0f);
  const auto gpu =
      probe<vec4>("#include \"../lib/cube_faces.glsl\"",
                  "texel_direction(int(input_value.x), int(input_value.y), int(input_value.z), 7), "
                  "float(cube_face_of(texel_direction(int(input_value.x), int(input_value.y), int(input_value.z), 7)))",
                  inputs);
  for (size_t k = 0; k < inputs.size(); ++k) {
    const vec3 cpu = texel_direction(int(inputs[k].x), int(inputs[k].y), int(inputs[k].z), size);
    REQUIRE(length(vec3(gpu[k]) - cpu) < kDirection);
    REQUIRE(gpu[k].w == inputs[k].x);
  }
}

TEST_CASE("Worley F1 and its gradient on the GPU agree with the CPU", "[probe][worley]") {
  const uvec3 key = noise_key(7u, 0u);
  const auto inputs = random_points(512, 20.0f, 2);
  const std::string key_literal = "uvec3(" + literal(key.x) + ", " + literal(key.y) + ", " + literal(key.z) + ")";
  const auto gpu = probe<vec4>("#include \"../lib/worley.glsl\"",
                               "worley_f1(input_value.xyz, ivec3(0), " + key_literal + ")", inputs);
  for (size_t k = 0; k < inputs.size(); ++k) {
    const vec4 cpu = worley_f1(vec3(inputs[k]), ivec3(0), key);
    // Same float operations; the driver may contract a*b+c into fma.
    REQUIRE(gpu[k].w == Approx(cpu.w).epsilon(0).margin(kF1));
    REQUIRE(length(vec3(gpu[k]) - vec3(cpu)) < kF1GradientTimesF1 / std::max(cpu.w, 1e-3f));
  }
}

TEST_CASE("inverted Worley fBm on the GPU agrees with the CPU", "[probe][worley]") {
  const FbmParams params{3.0f, 5, 2.0f, 0.5f, 99u, ivec3(0)};
  const auto inputs = random_points(256, 1.0f, 3);
  const auto gpu = probe<vec4>("#include \"../lib/worley_fbm.glsl\"",
                               "inverted_worley_fbm(input_value.xyz, " + literal(params) + ")", inputs);
  for (size_t k = 0; k < inputs.size(); ++k) {
    const vec4 cpu = inverted_worley_fbm(vec3(inputs[k]), params);
    REQUIRE(gpu[k].w == Approx(cpu.w).epsilon(0).margin(kFbmValue));
    // Gradients scale with the highest frequency: 3 x 2^4 = 48 here.
    REQUIRE(length(vec3(gpu[k]) - vec3(cpu)) < kFbmGradientPerFrequency * 48.0f);
  }
}

TEST_CASE("curl velocities on the GPU agree with the CPU", "[probe][curl]") {
  cover::CoverParameters p;
  p.seed = 12345u;
  const CurlParams c = cover::curl_params(p);
  auto inputs = random_directions(256, 4);
  inputs[0] = vec4(0, 0, 1, 0);   // north pole
  inputs[1] = vec4(0, 0, -1, 0);  // south pole
  const auto gpu = probe<vec4>("#include \"../lib/curl_flow.glsl\"",
                               "curl_velocity(input_value.xyz, " + literal(c) + "), 0.0", inputs);
  for (size_t k = 0; k < inputs.size(); ++k) {
    const vec3 cpu = curl_velocity(vec3(inputs[k]), c);
    REQUIRE(length(vec3(gpu[k]) - cpu) < test::curl_rounding_bound(vec3(inputs[k]), c));
  }
}
