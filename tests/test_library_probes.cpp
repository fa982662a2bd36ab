// Every function of the GLSL library (shaders/lib), run on the GPU through its file's probe,
// agrees with its C++ twin. A probe (tests/probes/NAME.glsl) is written in the shared GLSL/C++
// subset, so the same text evaluates the functions on both sides: one shader per library file.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <sstream>

#include "gl_support.hpp"
#include "march_tolerance.hpp"
#include "render/cloud_renderer.hpp"
#include "shader_math/shader_math.hpp"

// The probes that call functions with texture hooks need the hook macros again.
#include "shader_math/hook_macros.hpp"

namespace nephele::glsl {
#include "probes/cloud_density.glsl"
#include "probes/cloud_march.glsl"
#include "probes/cover_density.glsl"
#include "probes/cube_faces.glsl"
#include "probes/equirect_mapping.glsl"
#include "probes/hash.glsl"
#include "probes/portable_math.glsl"
#include "probes/ray_sphere.glsl"
#include "probes/worley.glsl"
#include "probes/worley_fbm.glsl"
}  // namespace nephele::glsl

using namespace nephele;
using namespace nephele::glsl;

namespace {

// One float rounding, relative: 2^-24.
constexpr float kUlp = 1.0f / 16777216.0f;
// Integer results (hashes, cell indices, face numbers) and sign flips: no rounding at all.
constexpr float kExact = 0.0f;
// GLSL allows 2.5 ulp for a division and lets the driver fuse a*b + c (1 ulp more per fused
// pair); the arithmetic probed here chains at most 8 such operations on values below 4:
// 8 x 3.5 ulp x 4 = 112 ulp (6.7e-6).
constexpr float kArithmetic = 8 * 3.5f * 4 * kUlp;
// Driver exp, pow, sin and cos: GLSL 4.50 (section 4.7.1) allows exp/exp2 3 + 2|x| ulp and pow
// that of exp2(y log2 x); with |x| <= 8 here that is at most 19 ulp relative, then the few
// arithmetic operations around them: 32 ulp relative, on results below 4 (absolute 2^-17).
constexpr float kTranscendental = 32 * 4 * kUlp;
// Worley F1 is a sqrt of a squared distance below 3 formed from 3 products and sums: a few ulp
// of values below 2 (the probe of test_shader_probes.cpp measures the same): 2^-20.
constexpr float kWorley = 16 * kUlp;
// An fBm of up to 5 octaves of F1 (each kWorley), normalised by a division (2.5 ulp): its
// value and, scaled by the highest frequency f_max, its gradient: 2^-16 per unit of f_max.
constexpr float kFbm = 256 * kUlp;

std::string probe_text(const std::string& name) {
  std::ifstream in(std::string(NEPHELE_SOURCE_DIR) + "/tests/probes/" + name + ".glsl");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

struct Case {
  mat4 input;
  float tolerance;  // absolute, per component
};

mat4 arguments(int function, vec4 a, vec4 b = vec4(0.0f), vec4 c = vec4(0.0f), vec4 d = vec4(0.0f)) {
  mat4 m(0.0f);
  m[0] = vec4(float(function), a.x, a.y, a.z);
  m[1] = b;
  m[2] = c;
  m[3] = d;
  return m;
}

template <class Cpu>
void compare(const std::string& name, Cpu cpu, const std::vector<Case>& cases) {
  std::vector<mat4> inputs;
  for (const auto& c : cases) inputs.push_back(c.input);
  const auto gpu = test::probe<vec4>(probe_text(name), "probe_" + name + "(input_value)", inputs);
  for (size_t k = 0; k < cases.size(); ++k) {
    const vec4 expected = cpu(cases[k].input);
    INFO(name << " function " << cases[k].input[0].x << " case " << k);
    for (int i = 0; i < 4; ++i) {
      INFO("component " << i << ": GPU " << gpu[k][i] << ", CPU " << expected[i]);
      REQUIRE(std::abs(gpu[k][i] - expected[i]) <= cases[k].tolerance);
    }
  }
}

struct Random {
  std::mt19937 rng;
  explicit Random(unsigned seed) : rng(seed) {}
  float operator()(float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); }
  vec4 v(float lo, float hi) { return vec4((*this)(lo, hi), (*this)(lo, hi), (*this)(lo, hi), 0.0f); }
};

}  // namespace

TEST_CASE("every function of each GLSL library file appears in that file's probe", "[probe][coverage]") {
  // Files without a probe yet: cube_sampling, warp_step and noise_rows need the includer's hooks
  // (a cube map source, the row walk's sums); atmosphere, perlin, curl_flow and tileable_noise
  // only lack the work. The GPU passes built on them are compared with the CPU in
  // test_cover_passes.cpp, test_numerics_gpu.cpp, test_noise_gpu.cpp and test_shader_probes.cpp.
  const std::set<std::string> not_probed = {"cube_sampling.glsl", "tileable_noise.glsl", "warp_step.glsl",
                                            "noise_rows.glsl", "atmosphere.glsl", "perlin.glsl",
                                            "curl_flow.glsl"};
  std::ifstream in(NEPHELE_SHADER_FUNCTIONS_FILE);
  REQUIRE(in);
  std::string line;
  int files = 0;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string file, function;
    words >> file;
    std::vector<std::string> functions;
    while (words >> function) functions.push_back(function);
    if (functions.empty() || not_probed.count(file)) continue;
    ++files;
    const std::string name = file.substr(0, file.size() - 5);
    const std::string probe = probe_text(name);
    INFO("tests/probes/" << name << ".glsl");
    REQUIRE(!probe.empty());
    for (const auto& f : functions) {
      INFO("function " << f);
      CHECK(probe.find(f + "(") != std::string::npos);
    }
  }
  CHECK(files >= 10);
}

TEST_CASE("portable_math.glsl on the GPU agrees with the CPU", "[probe]") {
  std::vector<Case> cases;
  for (int k = 0; k <= 64; ++k)
    cases.push_back({arguments(0, vec4(-1.0f + k / 32.0f, 0, 0, 0)), kArithmetic});
  compare("portable_math", probe_portable_math, cases);
}

TEST_CASE("ray_sphere.glsl on the GPU agrees with the CPU", "[probe]") {
  Random r(11);
  std::vector<Case> cases;
  for (int k = 0; k < 64; ++k) {
    // Rays from within 2 of the centre towards a point within 0.5 of it: |b| < 2, disc >= 0.25
    // for radius >= 1, so the roots (of magnitude below 4) stay well conditioned.
    const vec3 o = vec3(r.v(-1.2f, 1.2f));
    const vec3 target = vec3(r.v(-0.25f, 0.25f));
    const vec3 d = normalize(target - o);
    const float r_in = r(1.0f, 1.2f), r_out = r(1.3f, 1.6f), limit = r(0.5f, 4.0f);
    cases.push_back({arguments(k % 2, vec4(k % 2 ? r_in : r_out, r_out, limit, 0), vec4(o, 0), vec4(d, 0)),
                     kArithmetic});
  }
  compare("ray_sphere", probe_ray_sphere, cases);
}

TEST_CASE("equirect_mapping.glsl on the GPU agrees with the CPU", "[probe]") {
  std::vector<Case> cases;
  for (int column = 0; column < 64; column += 3)
    for (int f = 0; f < 2; ++f) {
      const float latitude = 0.05f * column - 1.5f;
      cases.push_back({arguments(f, vec4(float(column), 64.0f, 0, 0), vec4(std::cos(latitude), std::sin(latitude), 0, 0)),
                       kTranscendental});
    }
  compare("equirect_mapping", probe_equirect_mapping, cases);
}

TEST_CASE("cube_faces.glsl on the GPU agrees with the CPU", "[probe]") {
  Random r(12);
  std::vector<Case> cases;
  for (int face = 0; face < 6; ++face)
    for (int k = 0; k < 8; ++k) {
      const vec3 direction = normalize(vec3(r.v(-1.0f, 1.0f)) + vec3(1e-3f));
      cases.push_back({arguments(0, vec4(float(face), r(-1.0f, 1.0f), r(-1.0f, 1.0f), 0)), kExact});
      cases.push_back({arguments(1, vec4(float(face), float(k), float(7 - k), 0), vec4(8.0f, 0, 0, 0)), kArithmetic});
      cases.push_back({arguments(2, vec4(0.0f), vec4(direction, 0)), kExact});
      cases.push_back({arguments(3, vec4(float(cube_face_of(direction)), 0, 0, 0), vec4(direction, 0)), kArithmetic});
    }
  compare("cube_faces", probe_cube_faces, cases);
}

TEST_CASE("hash.glsl on the GPU agrees with the CPU", "[probe]") {
  Random r(13);
  std::vector<Case> cases;
  for (int k = 0; k < 48; ++k) {
    // Integers below 2^24 pass exactly as floats.
    const vec4 v = vec4(std::floor(r(0.0f, 16777215.0f)), std::floor(r(0.0f, 16777215.0f)),
                        std::floor(r(0.0f, 16777215.0f)), 0.0f);
    cases.push_back({arguments(k % 3, vec4(0.0f), v), kExact});
  }
  compare("hash", probe_hash, cases);
}

TEST_CASE("cover_density.glsl on the GPU agrees with the CPU", "[probe]") {
  Random r(14);
  std::vector<Case> cases;
  const vec4 fbm(4.0f, 4.0f, 2.0f, 0.5f);  // frequency, octaves, lacunarity, gain
  for (int k = 0; k < 32; ++k) {
    const vec4 p = vec4(normalize(vec3(r.v(-1.0f, 1.0f)) + vec3(1e-3f)), 0.0f);
    const vec4 seed_and_offset(7.0f, r(-0.5f, 0.5f), r(-0.5f, 0.5f), r(-0.5f, 0.5f));
    cases.push_back({arguments(k % 2, vec4(0.0f), p, fbm, seed_and_offset), kFbm});
    cases.push_back({arguments(2, vec4(r(0.0f, 1.0f), r(0.0f, 0.5f), r(0.5f, 1.0f), 0)), kArithmetic});
  }
  compare("cover_density", probe_cover_density, cases);
}

TEST_CASE("cloud_density.glsl on the GPU agrees with the CPU", "[probe]") {
  Random r(15);
  std::vector<Case> cases;
  for (int f = 0; f < 10; ++f)
    for (int k = 0; k < 12; ++k) {
      vec4 a(r(0.0f, 1.0f), r(0.0f, 1.0f), r(0.0f, 1.0f), 0.0f);
      if (f == 0) a.y = a.x + r(0.05f, 1.0f);  // hermite_step needs a < b
      if (f == 7) a.x = float(k % 9);          // noise_period's cloud type
      if (f == 8) a = vec4(r(-1.0f, 1.0f), r(0.25f, 1.0f), 0, 0);  // cloud_phase(nu, scale)
      if (f == 9) a = vec4(r(0.0f, 8.0f), r(-1.0f, 1.0f), 0, 0);   // sun_scattering(tau, nu)
      const vec4 b(r(0.0f, 1.0f), r(0.0f, 1.0f), float(k % 9), 0.0f);
      const bool transcendental = f == 5 || f == 8 || f == 9;
      cases.push_back({arguments(f, a, b), f == 7 ? kExact : transcendental ? kTranscendental : kArithmetic});
    }
  compare("cloud_density", probe_cloud_density, cases);
}

TEST_CASE("worley.glsl on the GPU agrees with the CPU", "[probe]") {
  Random r(16);
  std::vector<Case> cases;
  const vec4 key = vec4(std::floor(r(0.0f, 16777215.0f)), std::floor(r(0.0f, 16777215.0f)), 12345.0f, 0.0f);
  for (int k = 0; k < 64; ++k) {
    const int f = k % 4;
    const vec4 period = (k / 4) % 2 ? vec4(5.0f, 7.0f, 3.0f, 0.0f) : vec4(0.0f);
    const vec4 p = f < 2 ? vec4(std::floor(r(-40.0f, 40.0f)), std::floor(r(-40.0f, 40.0f)), std::floor(r(-40.0f, 40.0f)), 0)
                         : (f == 2 ? r.v(0.0f, 1.0f) : r.v(-20.0f, 20.0f));
    const vec4 a(r(0.5f, 3.0f), float(k % 3 - 1), float((k / 3) % 3 - 1), 0.0f);
    cases.push_back({arguments(f, a, p, period, key), f < 2 ? kExact : kWorley});
  }
  compare("worley", probe_worley, cases);
}

TEST_CASE("worley_fbm.glsl on the GPU agrees with the CPU", "[probe]") {
  Random r(17);
  std::vector<Case> cases;
  const float highest_frequency = 3.0f * 16.0f;  // 5 octaves of lacunarity 2 from frequency 3
  for (int k = 0; k < 32; ++k) {
    const vec4 period = k % 2 ? vec4(4.0f, 4.0f, 4.0f, 0.0f) : vec4(0.0f);
    cases.push_back({arguments(0, vec4(0.0f), r.v(0.0f, 1.0f), vec4(3.0f, 5.0f, 2.0f, 0.5f),
                               vec4(99.0f, period.x, period.y, period.z)),
                     kFbm * highest_frequency});
  }
  compare("worley_fbm", probe_worley_fbm, cases);
}

TEST_CASE("cloud_march.glsl on the GPU agrees with the CPU", "[probe][march]") {
  test::test_context();
  // The textures at the units the probe reads: a 16^3 noise volume and a 4 x 4 weather field of
  // five channels with varying coverage in [0.2, 0.9].
  const render::NoiseVolume noise(16, 3);
  const int size = 4, channels = 5;
  std::vector<float> weather;
  for (int c = 0; c < channels; ++c)
    for (int k = 0; k < size * size; ++k) weather.push_back(0.2f + 0.7f * float((3 * k + c) % 7) / 6.0f);
  GLuint weather_texture = 0;
  glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &weather_texture);
  glTextureStorage3D(weather_texture, 1, GL_R32F, size, size, channels);
  glTextureSubImage3D(weather_texture, 0, 0, 0, 0, size, size, channels, GL_RED, GL_FLOAT, weather.data());
  glTextureParameteri(weather_texture, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(weather_texture, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(weather_texture, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(weather_texture, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glBindTextureUnit(1, noise.texture());
  glBindTextureUnit(2, weather_texture);
  MarchSources sources;
  sources.noise = noise.host_copy();
  sources.weather = {size, channels, weather.data()};
  auto cpu = [&](const mat4& x) { return probe_cloud_march(x, sources); };

  // Altitudes are rounded at the scale of the Earth's radius (march_tolerance.hpp): the height
  // fraction moves by kPosition over the 1500 m layers, the noise values by kPosition over the
  // 4000 m shortest period in texels times the largest texel step, the shape by 1 / 0.6 of that;
  // whole marches by march_tolerance, relative.
  const float height = float(test::kPosition / 1500.0);
  const float detail = float(test::kPosition / 4000.0 * 16 * test::max_texel_step(sources.noise));
  const float shape = detail / 0.6f;
  const float march = float(test::march_tolerance(1500.0, 4000.0, sources.noise));
  // A shell shifted by kPosition moves the crossing of a ray at elevation e by kPosition / sin e;
  // the rays here rise at least 0.2 rad (sin > 0.198).
  const float crossing = float(test::kPosition / 0.198);

  Random r(18);
  std::vector<Case> cases;
  auto relative = [&](const mat4& x, float tolerance) {
    const vec4 v = abs(cpu(x));
    return Case{x, tolerance * std::max({1e-6f, v.x, v.y, v.z, v.w})};
  };
  for (int k = 0; k < 12; ++k) {
    const vec4 pixel(float(k % 16), float((5 * k) % 9), 0, 0);
    cases.push_back({arguments(0, vec4(0, 0, float(k % 2), 0), vec4(0), vec4(0), pixel), kTranscendental});
    // Points in the two layers, within 20 km of the camera.
    const int layer = k % 2;
    const float altitude = layer == 0 ? r(1600.0f, 2900.0f) : r(3600.0f, 4900.0f);
    const vec4 p(r(-20000.0f, 20000.0f), r(-20000.0f, 20000.0f), altitude - 860.0f, 0.0f);
    cases.push_back({arguments(1, vec4(float(k % 5), 0, 0, 0), p), kArithmetic});
    cases.push_back({arguments(2, vec4(float(layer), r(10.0f, 3000.0f), 0, 0), p), std::max(height, shape)});
    cases.push_back({arguments(3, vec4(float(layer), r(10.0f, 3000.0f), 0, 0), p), 0.01f * march});
    cases.push_back(relative(arguments(4, vec4(float(layer), 0, 0, 0), p), march));
    // View rays rising 0.2 to 1.2 rad.
    const float elevation = r(0.2f, 1.2f), azimuth = r(-3.0f, 3.0f);
    const vec4 d(std::cos(elevation) * std::sin(azimuth), std::cos(elevation) * std::cos(azimuth), std::sin(elevation), 0);
    cases.push_back({arguments(5, vec4(0, r(5000.0f, 150000.0f), 0, 0), vec4(0), d), crossing});
    cases.push_back(relative(arguments(6, vec4(0, 150000.0f, r(0.0f, 1.0f), 0), vec4(0), d), march));
    cases.push_back(relative(arguments(7, vec4(0), vec4(0), vec4(0), pixel), march));
    cases.push_back({arguments(8, vec4(float(65535 + k - 6), 0, 0, 0)), kExact});
  }
  compare("cloud_march", cpu, cases);
  glDeleteTextures(1, &weather_texture);
}
