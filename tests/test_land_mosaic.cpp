// The land's mosaic below the day map's texels (shaders/lib/land_mosaic.glsl, on the CPU twin):
// its mean over many texels is the map's colour, its forest takes the share the colour implies,
// and it fades to the map's colour where the footprint or the map resolves its patches.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

#include "shader_math/shader_math.hpp"

using namespace nephele;
using glsl::vec3;
using glsl::vec4;

namespace {

constexpr float radius = 6371000.0f;
constexpr float fine_footprint = 10.0f;  // m: every octave drawn, the forest's edges sharp
constexpr float day_texel = 20000.0f;    // m: the default day map's

// Points spread uniformly over the sphere: far enough apart (a few hundred km on average for
// these counts) that the field's values at them are independent.
std::vector<vec3> sphere_points(int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<float> normal;
  std::vector<vec3> points;
  for (int k = 0; k < count; ++k) points.push_back(glm::normalize(vec3(normal(rng), normal(rng), normal(rng))));
  return points;
}

// The field without relief.
glsl::MosaicSample sample_at(vec3 up, float footprint) {
  return glsl::mosaic_sample(up, radius, footprint, 0.0f, 1.0f);
}

struct Moments {
  vec3 mean{0.0f};
  vec3 deviation{0.0f};
};

Moments factor_moments(const std::vector<vec3>& points, vec4 day, float footprint) {
  glm::dvec3 sum(0.0), squares(0.0);
  for (const vec3& up : points) {
    const glm::dvec3 f(glsl::land_mosaic(up, day, radius, footprint, day_texel, sample_at(up, footprint)));
    sum += f;
    squares += f * f;
  }
  const double n = double(points.size());
  const glm::dvec3 mean = sum / n;
  return {vec3(mean), vec3(glm::sqrt(glm::max(squares / n - mean * mean, glm::dvec3(0.0))))};
}

// Texels of the default day map (linear RGB, xplanet's earth.jpg): farmland near Paris, the
// Beauce, the Black Forest, Bern, and the arid centre of Spain.
const vec4 paris(0.081f, 0.104f, 0.020f, 1.0f);
const vec4 beauce(0.104f, 0.129f, 0.029f, 1.0f);
const vec4 black_forest(0.033f, 0.062f, 0.004f, 1.0f);
const vec4 bern(0.045f, 0.083f, 0.009f, 1.0f);
const vec4 spain(0.306f, 0.228f, 0.082f, 1.0f);

}  // namespace

TEST_CASE("the forest covers the share of the land that the texel's brightness implies", "[fast][land mosaic]") {
  const std::vector<vec3> points = sphere_points(20000, 3);
  for (const vec4 day : {paris, beauce, black_forest, bern}) {
    const float share = glsl::mosaic_forest_share(vec3(day));
    // The share is the mix of open land and forest with the texel's luminance, within its bounds.
    const float open = glsl::MOSAIC_OPEN_LUMINANCE;
    const float forest =
        open * glsl::mosaic_luminance(glsl::LAND_FOREST) / glsl::mosaic_luminance(glsl::field_mean_albedo(1.0f));
    const float expected = std::clamp((open - glsl::mosaic_luminance(vec3(day))) / (open - forest),
                                      glsl::MOSAIC_FOREST_MIN, glsl::MOSAIC_FOREST_MAX);
    CHECK(share == Approx(expected).epsilon(1e-5));
    for (const float footprint : {fine_footprint, 1000.0f, 3000.0f}) {
      double wooded = 0.0;
      for (const vec3& up : points) wooded += glsl::mosaic_forest(sample_at(up, footprint), share);
      // Sampling (4 standard deviations of a share between 0 and 1) and the field's departure
      // from the normal distribution whose quantile sets the threshold (three octaves of gradient
      // noise: 0.02). The footprint changes how soft the woods' edges are, not their share.
      const double n = double(points.size());
      INFO("share " << share << ", footprint " << footprint << " m, measured " << wooded / n);
      CHECK(std::abs(wooded / n - share) <= 0.02 + 4 * std::sqrt(share * (1 - share) / n));
    }
  }
  // Brighter texels have less forest, darker ones more: the Beauce least, the Black Forest most.
  CHECK(glsl::mosaic_forest_share(vec3(beauce)) < glsl::mosaic_forest_share(vec3(paris)));
  CHECK(glsl::mosaic_forest_share(vec3(paris)) < glsl::mosaic_forest_share(vec3(bern)));
  CHECK(glsl::mosaic_forest_share(vec3(bern)) < glsl::mosaic_forest_share(vec3(black_forest)));
}

TEST_CASE("the mosaic's mean over many texels is the day map's colour", "[fast][land mosaic]") {
  const std::vector<vec3> points = sphere_points(20000, 5);
  for (const vec4 day : {paris, beauce, black_forest, bern, spain}) {
    const Moments m = factor_moments(points, day, fine_footprint);
    const vec3 r = glsl::forest_contrast();
    const float share = glsl::mosaic_forest_share(vec3(day));
    for (int c = 0; c < 3; ++c) {
      // The forest's share may miss by the first test's allowance (0.02 + sampling), which moves
      // the mean by that times the step from open land's factor to the forest's; the mean's own
      // sampling error is 4 deviations over sqrt(n).
      const float open = 1.0f / (1.0f - share + share * r[c]);
      const float allowance = 0.03f * open * (1.0f - r[c]) + 4 * m.deviation[c] / std::sqrt(float(points.size()));
      INFO("texel (" << day.r << ", " << day.g << ", " << day.b << ") channel " << c << ": mean factor " << m.mean[c]
                     << ", deviation " << m.deviation[c]);
      CHECK(std::abs(m.mean[c] - 1.0f) <= allowance);
    }
  }
}

TEST_CASE("vegetated land is forest or open land, forest darker by the albedos' ratio", "[fast][land mosaic]") {
  const vec3 r = glsl::forest_contrast();
  // Forest (0.035, 0.06, 0.03) over the summer fields' mean (0.082, 0.1395, 0.0545).
  CHECK(r.x == Approx(0.035 / 0.082).epsilon(1e-4));
  CHECK(r.y == Approx(0.06 / 0.1395).epsilon(1e-4));
  CHECK(r.z == Approx(0.03 / 0.0545).epsilon(1e-4));
  const float share = glsl::mosaic_forest_share(vec3(paris));
  const vec3 open = vec3(1.0f) / (vec3(1.0f - share) + share * r);
  int forest = 0, fields = 0;
  for (const vec3& up : sphere_points(4000, 7)) {
    const glsl::MosaicSample sample = sample_at(up, fine_footprint);
    const float wood = glsl::mosaic_forest(sample, share);
    const vec3 f = glsl::land_mosaic(up, paris, radius, fine_footprint, day_texel, sample);
    if (wood > 1.0f - 1e-6f) {
      // Deep in the forest the factor is the forest's: no brightness of the fields there.
      ++forest;
      for (int c = 0; c < 3; ++c) CHECK(f[c] == Approx(r[c] * open[c]).epsilon(1e-5));
    } else if (wood < 1e-6f) {
      // Open land: the open factor times the fields' brightness, the same in every channel
      // (ratios of channels kept), within the fields' spread's 4.3 deviations of gradient noise
      // (PERLIN_BOUND / PERLIN_OCTAVE_SIGMA = 3.84).
      ++fields;
      const vec3 brightness = f / open;
      CHECK(brightness.x == Approx(brightness.y).epsilon(1e-5));
      CHECK(brightness.y == Approx(brightness.z).epsilon(1e-5));
      CHECK(std::abs(brightness.x - 1.0f) <=
            glsl::MOSAIC_FIELD_SPREAD * glsl::PERLIN_BOUND / glsl::PERLIN_OCTAVE_SIGMA + 1e-5f);
    }
  }
  CHECK(forest > 20);  // of 4000: the tails beyond 4.75 deviations of the unresolved part
  CHECK(fields > 200);
}

TEST_CASE("arid land varies in brightness about the map's colour, keeping its hue", "[fast][land mosaic]") {
  CHECK(glsl::mosaic_vegetation(vec3(spain)) == 0.0f);
  CHECK(glsl::mosaic_vegetation(vec3(paris)) == 1.0f);  // (G - R) / (G + R) = 0.12
  const std::vector<vec3> points = sphere_points(20000, 11);
  for (const vec3& up : points) {
    const vec3 f = glsl::land_mosaic(up, spain, radius, fine_footprint, day_texel, sample_at(up, fine_footprint));
    REQUIRE(f.x == f.y);
    REQUIRE(f.y == f.z);
  }
  // Its deviation is the spread (the clamp at half the brightness lies 4 spreads below: it
  // cuts nothing of a normal's mass that the tolerance sees).
  const Moments m = factor_moments(points, spain, fine_footprint);
  CHECK(m.deviation.x == Approx(glsl::MOSAIC_ARID_SPREAD).epsilon(0.05));
  CHECK(std::abs(m.mean.x - 1.0f) <= 4 * glsl::MOSAIC_ARID_SPREAD / std::sqrt(float(points.size())));
}

TEST_CASE("the mosaic fades to the map's colour from half its largest wavelength, on fine maps and on ice",
          "[fast][land mosaic]") {
  for (const vec3& up : sphere_points(200, 13)) {
    // A footprint of half the largest patches' wavelength: nothing is drawn.
    const float wide = 0.5f * glsl::MOSAIC_WAVELENGTH;
    CHECK(glsl::land_mosaic(up, paris, radius, wide, day_texel, sample_at(up, wide)) == vec3(1.0f));
    CHECK(glsl::mosaic_sample(up, radius, wide, 0.1f, 18500.0f).relief == glsl::vec2(0.0f));
    // A map whose texels resolve the patches gets none.
    const glsl::MosaicSample fine = sample_at(up, fine_footprint);
    CHECK(glsl::land_mosaic(up, paris, radius, fine_footprint, glsl::MOSAIC_MIN_DAY_TEXEL, fine) == vec3(1.0f));
    // Ice (the day map's alpha 0) keeps the map's colour.
    CHECK(glsl::land_mosaic(up, vec4(vec3(paris), 0.0f), radius, fine_footprint, day_texel, fine) == vec3(1.0f));
  }
  // Between, the detail grows continuously with the footprint's shrinking: the factor's
  // deviation over the texels rises from 0 to the full mosaic's.
  const std::vector<vec3> points = sphere_points(4000, 17);
  float previous = 0.0f;
  for (float footprint : {5500.0f, 4500.0f, 3500.0f, 2500.0f, 1500.0f, 500.0f, 10.0f}) {
    const float deviation = factor_moments(points, paris, footprint).deviation.y;
    INFO("footprint " << footprint << " m: deviation " << deviation);
    CHECK(deviation > previous);
    previous = deviation;
  }
}

namespace {

constexpr float relief_texel = 18500.0f;  // m: the ETOPO5 relief map's

// The relief's heights (m) as mosaic_sample draws their slopes: -sum_k steepness_k / sigma_g x
// wavelength_k x |noise_k| (an octave's noise changes by its gradient per lattice unit, a
// wavelength of metres), at the point `metres` east of `up` along a sphere of `sphere` m.
double ridged_height(vec3 up, double metres, float roughness, float sphere) {
  const glm::dvec3 u(up);
  const glm::dvec3 east = glm::normalize(glm::dvec3(-u.y, u.x, 0.0));
  const glm::dvec3 at = glm::normalize(u + east * (metres / sphere));
  double height = 0.0;
  float wavelength = glsl::MOSAIC_WAVELENGTH;
  for (int k = 0; k < glsl::MOSAIC_OCTAVES; ++k) {
    const double steepness = roughness * std::pow(wavelength / (2.0 * relief_texel), glsl::RELIEF_HURST - 1.0);
    const float n = glsl::mosaic_octave(vec3(at * double(sphere / wavelength)), k).w;
    height -= steepness / glsl::PERLIN_GRADIENT_SIGMA * wavelength * std::abs(n);
    wavelength /= glsl::MOSAIC_OCTAVE_RATIO;
  }
  return height;
}

}  // namespace

TEST_CASE("the relief below the texels has the ridged heights' slopes", "[fast][land mosaic]") {
  // On a sphere of 30 km, whose lattice coordinates stay below 23 (float positions within 2e-6 of
  // a cell): on the Earth's radius they reach 4800, and rounding the positions alone would move the
  // heights' differences by more than the test resolves. The formulas do not depend on the radius.
  const float sphere = 30000.0f, roughness = 0.05f;
  double heights_per_noise = 0.0;  // m of height per unit of noise, summed over the octaves
  for (int k = 0; k < glsl::MOSAIC_OCTAVES; ++k) {
    const double wavelength = glsl::MOSAIC_WAVELENGTH / std::pow(glsl::MOSAIC_OCTAVE_RATIO, k);
    heights_per_noise += roughness * std::pow(wavelength / (2.0 * relief_texel), glsl::RELIEF_HURST - 1.0) *
                         wavelength / glsl::PERLIN_GRADIENT_SIGMA;
  }
  int compared = 0;
  for (const vec3& up : sphere_points(400, 19)) {
    const glsl::MosaicSample s = glsl::mosaic_sample(up, sphere, fine_footprint, roughness, relief_texel);
    // Central differences over +-10 m (1/133 of the finest octave's cell): the heights' third
    // derivative (the quintic fades' up to about 60 per cell cubed) leaves errors of order
    // h^2 / 6 of it: 1e-3 of the slopes; skipped within 30 m of a crest, where |noise| has its kink.
    const double h = 10.0;
    bool crest = false;
    float wavelength = glsl::MOSAIC_WAVELENGTH;
    for (int k = 0; k < glsl::MOSAIC_OCTAVES; ++k) {
      const glsl::vec4 o = glsl::mosaic_octave(up * (sphere / wavelength), k);
      crest = crest || std::abs(o.w) < glm::length(vec3(o)) * 30.0f / wavelength;
      wavelength /= glsl::MOSAIC_OCTAVE_RATIO;
    }
    if (crest) continue;
    ++compared;
    const double slope = (ridged_height(up, h, roughness, sphere) - ridged_height(up, -h, roughness, sphere)) / (2 * h);
    INFO("relief east " << s.relief.x << ", heights' slope " << slope);
    // The heights' float noise: positions rounded to an ulp of the lattice coordinates (2^-19 below
    // 32) move each octave's noise by up to its gradient's 3 components (0.71 each, typically)
    // times that, and its height by steepness x wavelength / sigma_g times the noise (2600 m summed
    // over the octaves at this roughness), over the differences' 20 m.
    CHECK(s.relief.x ==
          Approx(slope).epsilon(1e-3).margin(heights_per_noise * 3 * 0.71 * std::ldexp(1.0, -19) / (2 * h)));
  }
  CHECK(compared > 300);
}

TEST_CASE("the relief's steepness follows a self-affine surface's from the map's texels down", "[fast][land mosaic]") {
  // Each octave's slope has the root mean square roughness (wavelength / (2 texels))^(H - 1) in
  // each direction (the ridges' sign flips leave the gradient's magnitude), the octaves independent.
  const float roughness = 0.04f;
  double expected = 0.0;
  float wavelength = glsl::MOSAIC_WAVELENGTH;
  for (int k = 0; k < glsl::MOSAIC_OCTAVES; ++k) {
    expected += std::pow(roughness * std::pow(wavelength / (2.0 * relief_texel), glsl::RELIEF_HURST - 1.0), 2.0);
    wavelength /= glsl::MOSAIC_OCTAVE_RATIO;
  }
  expected = std::sqrt(expected);
  const std::vector<vec3> points = sphere_points(20000, 23);
  double east = 0.0, north = 0.0;
  for (const vec3& up : points) {
    const glsl::vec2 r = glsl::mosaic_sample(up, radius, fine_footprint, roughness, relief_texel).relief;
    east += double(r.x) * r.x;
    north += double(r.y) * r.y;
  }
  // The gradient's deviation (PERLIN_GRADIENT_SIGMA's test: 0.65 / sqrt(n) relative, four of them).
  const double allowance = 4 * 0.65 / std::sqrt(double(points.size()));
  CHECK(std::sqrt(east / points.size()) == Approx(expected).epsilon(allowance));
  CHECK(std::sqrt(north / points.size()) == Approx(expected).epsilon(allowance));
  // About 5.5 times the map's own slopes at 1.3 km: steep where the map is rough, flat where it is.
  CHECK(expected / roughness == Approx(5.48).epsilon(0.01));
  // No relief on flat ground (the sea) or at the poles, where east is undefined.
  CHECK(glsl::mosaic_sample(points[0], radius, fine_footprint, 0.0f, relief_texel).relief == glsl::vec2(0.0f));
  CHECK(glsl::mosaic_sample(vec3(0, 0, 1), radius, fine_footprint, roughness, relief_texel).relief == glsl::vec2(0.0f));
}
