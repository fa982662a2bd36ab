// Tileable noise textures on the CPU: Perlin against a textbook evaluation, its bound, the
// distribution of gradients and feature points, exact tiling, the row walk against the point
// functions, value ranges, seeds and the checks of a texture specification.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include "noise/noise_spec.hpp"
#include "noise/noise_texture.hpp"
#include "shader_math/shader_math.hpp"
#include "tolerances.hpp"

using namespace nephele;
using namespace nephele::glsl;
using test::kUlp;

namespace {

// perlin_noise against the textbook evaluation in double at the same float p: f = p - floor(p)
// is exact for p >= 0 and within 2^-25 for negative p (so the rounding of positions near 40 does
// not enter); the float dot products (values below 2), fade polynomials and 7 lerps round about
// 20 times, 2^-23 each for values below 2: 2.4e-6 (1.3e-6 measured over 2e5 points). 2e-5 is 8x
// looser (kept as set). The operation count is an estimate, not counted exactly.
constexpr double kPerlinVsTextbook = 2e-5;
static_assert(kPerlinVsTextbook >= 20 * 2 * kUlp);
// The grid of spacing 1/48 misses the maximum of the smooth S by about |S''| / 2 x (1/96)^2 per
// axis, a few 1e-4 for |S''| of a few units: 2e-3 leaves room. Partly empirical (S'' near the
// maximum is not computed).
constexpr double kPerlinBoundGrid = 2e-3;
// Statistical checks allow 6 standard deviations. For chi-square statistics (skewed) mean + 6 sd
// is exceeded with probability 5e-5 for 11 degrees of freedom and 1.3e-6 for 63; for a mean of
// 64000 products (close to normal) 2e-9. The seeds are fixed, so the tests are deterministic.
constexpr double kSigmas = 6.0;
// A shifted point q = p + k period (|q| < 30) is rounded to half an ulp of values below 32,
// 2^-20 = 9.5e-7, along one axis, which moves the noise by its slope (below 3 per unit, not
// derived here) times that, 2.9e-6, plus both sides' evaluation rounding (kPerlinVsTextbook's
// 2.4e-6 each): 7.7e-6 (2.7e-6 measured). 1e-5 leaves a factor 1.3 over that estimate.
constexpr double kPerlinTiling = 1.0e-5;
static_assert(kPerlinTiling >= 3 * 16 * kUlp + 2 * 20 * 2 * kUlp);
// Channel values one texture period further along (texel units below 128: half an ulp 3.8e-6)
// times a slope below 10 per texel (an estimate, not derived): 3.8e-5; 1e-4 leaves a factor 2.6.
// Partly empirical (the slope bound and the rounding of the cell coordinates are not derived).
constexpr double kChannelTiling = 1.0e-4;
static_assert(kChannelTiling >= 10 * 64 * kUlp);
// The row walk against the point functions for Worley types: the squared distance dy^2 + dz^2
// summed first, one rounding of a value below 3 (2^-24 relative, halved by the square root: 5.2e-8
// of F1 <= sqrt 3), then averaged and scaled by <= 1 (two roundings of values <= 1): 1.7e-7; 2e-7
// leaves a factor 1.2.
constexpr double kRowWalk = 2.0e-7;
static_assert(kRowWalk >= 1.7321f * kUlp / 2 + 2 * kUlp);
// The inverted Worley channel against 1 - (1 - w) / sqrt 3 of the fBm: kRowWalk for the F1 values
// (carried through the fBm's mean, weights summing to 1) and the rescaling's 3 roundings on
// either side (6 x 2^-24): 5.6e-7; 1e-6 leaves a factor 1.8.
constexpr double kInvertedWorleyRescaled = 1.0e-6;
static_assert(kInvertedWorleyRescaled >= kRowWalk + 6 * kUlp);
// The channel values spread over at least this much of [0, 1] on a 16^3 texture: a choice
// (empirical), not derived.
constexpr float kChannelSpread = 0.2f;
// Two seeds give fewer than one texel in this many equal: a choice (empirical; equal values by
// chance are far rarer for continuous noise).
constexpr size_t kSameAtMostOneIn = 100;

double fade_d(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }

// Perlin 2002 written out: trilinear interpolation of the 8 corner dot products in double.
double textbook_perlin(dvec3 p, ivec3 period, uvec3 key) {
  const dvec3 base = floor(p);
  const dvec3 f = p - base;
  double n[2][2][2];
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        const ivec3 corner = wrap_cell(ivec3(base) + ivec3(i, j, k), period);
        n[i][j][k] = dot(dvec3(perlin_gradient(corner, key)), f - dvec3(i, j, k));
      }
  const dvec3 u(fade_d(f.x), fade_d(f.y), fade_d(f.z));
  auto lerp = [](double a, double b, double t) { return a + t * (b - a); };
  const double x00 = lerp(n[0][0][0], n[1][0][0], u.x), x10 = lerp(n[0][1][0], n[1][1][0], u.x);
  const double x01 = lerp(n[0][0][1], n[1][0][1], u.x), x11 = lerp(n[0][1][1], n[1][1][1], u.x);
  return lerp(lerp(x00, x10, u.y), lerp(x01, x11, u.y), u.z);
}

vec3 random_point(std::mt19937& rng, float extent) {
  std::uniform_real_distribution<float> u(-extent, extent);
  return vec3(u(rng), u(rng), u(rng));
}

noise::TextureSpec spec_of(int w, int h, int d, noise::NoiseType type, int cells, int octaves, std::uint32_t seed = 5) {
  noise::TextureSpec spec;
  spec.width = w;
  spec.height = h;
  spec.depth = d;
  spec.seed = seed;
  spec.channels[0].type = type;
  spec.channels[0].cells = cells;
  spec.channels[0].octaves = octaves;
  spec.channels[0].worley_cells = cells;
  spec.channels[0].worley_octaves = 2;
  return spec;
}

}  // namespace

TEST_CASE("perlin noise equals the textbook trilinear evaluation", "[fast][noise]") {
  std::mt19937 rng(21);
  const uvec3 key = noise_key(3u, 0u);
  for (int n = 0; n < 20000; ++n) {
    const vec3 p = random_point(rng, 40.0f);
    const ivec3 period = n % 2 ? ivec3(0) : ivec3(7, 5, 9);
    // The float operations of the evaluation (f itself is exact): kPerlinVsTextbook.
    REQUIRE(perlin_noise(p, period, key) ==
            Approx(textbook_perlin(p, period, key)).epsilon(0).margin(kPerlinVsTextbook));
  }
}

TEST_CASE("perlin_noise_gradient gives perlin noise and its derivative, whose deviation is the closed form's",
          "[fast][noise]") {
  std::mt19937 rng(29);
  const uvec3 key = noise_key(6u, 2u);
  const double h = 1e-4;  // central differences of the double evaluation: O(h^2) truncation
  double squares = 0.0;
  const int count = 100000;
  for (int n = 0; n < count; ++n) {
    const vec3 p = random_point(rng, 40.0f);
    const vec4 r = perlin_noise_gradient(p, key);
    REQUIRE(r.w == Approx(textbook_perlin(p, ivec3(0), key)).epsilon(0).margin(kPerlinVsTextbook));
    if (n < 10000) {
      for (int axis = 0; axis < 3; ++axis) {
        // The textbook evaluation in double at p +- h along the axis (points off the lattice
        // planes by more than h, where the noise is smooth).
        dvec3 step(0.0);
        step[axis] = h;
        const dvec3 f = dvec3(p) - floor(dvec3(p));
        if (f[axis] < 2 * h || f[axis] > 1 - 2 * h) continue;
        const double derivative =
            (textbook_perlin(dvec3(p) + step, ivec3(0), key) - textbook_perlin(dvec3(p) - step, ivec3(0), key)) /
            (2 * h);
        // The float sums of eight corners' terms up to 6 each: 8 x 6 x 20 operations' rounding.
        REQUIRE(r[axis] == Approx(derivative).epsilon(0).margin(1e-4));
      }
    }
    squares += double(r.x) * r.x;
  }
  // The x component's deviation over uniform points: the closed form within 4 standard errors
  // (the square's relative deviation measured 1.23, over the square root 0.62 / sqrt(n); 0.65 taken).
  CHECK(std::sqrt(squares / count) == Approx(PERLIN_GRADIENT_SIGMA).epsilon(4 * 0.65 / std::sqrt(double(count))));
}

TEST_CASE("perlin noise vanishes on lattice points and stays inside its bound", "[fast][noise]") {
  const uvec3 key = noise_key(8u, 1u);
  for (int k = -3; k <= 3; ++k)
    for (int j = -3; j <= 3; ++j)
      for (int i = -3; i <= 3; ++i) REQUIRE(perlin_noise(vec3(i, j, k), ivec3(4), key) == 0.0f);
  std::mt19937 rng(4);
  float largest = 0.0f;
  for (int n = 0; n < 200000; ++n) {
    const float v = perlin_noise(random_point(rng, 100.0f), ivec3(0), key);
    REQUIRE(std::abs(v) <= PERLIN_BOUND);
    largest = std::max(largest, std::abs(v));
  }
  WARN("largest |perlin| in 200000 samples: " << largest);
}

TEST_CASE("the perlin bound is the supremum over all gradient choices", "[fast][noise]") {
  // S(f) = sum_c w_c(f) max_g g.(f - c) bounds |noise| and is reached when every corner's gradient
  // points its way; the max over g of g.d is the sum of the two largest |d_i|.
  const int n = 48;
  double best = 0.0;
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const double f[3] = {double(i) / n, double(j) / n, double(k) / n};
        double s = 0.0;
        for (int c = 0; c < 8; ++c) {
          double w = 1.0, d[3];
          for (int a = 0; a < 3; ++a) {
            const int o = (c >> a) & 1;
            d[a] = std::abs(f[a] - o);
            w *= o ? fade_d(f[a]) : 1.0 - fade_d(f[a]);
          }
          std::sort(d, d + 3);
          s += w * (d[1] + d[2]);
        }
        best = std::max(best, s);
      }
  // A grid of spacing 1/48 finds the maximum 1.036354 to a few 1e-4 (S is smooth near it).
  CHECK(best <= PERLIN_BOUND);
  CHECK(best >= PERLIN_BOUND - kPerlinBoundGrid);
}

TEST_CASE("perlin gradients are uniform over the twelve edge directions", "[fast][noise]") {
  const uvec3 key = noise_key(11u, 0u);
  std::vector<int> counts(12, 0);
  const int n = 120000;
  for (int k = 0; k < n; ++k) {
    const vec3 g = perlin_gradient(ivec3(k % 50, k / 50 % 50, k / 2500), key);
    REQUIRE(dot(g, g) == 2.0f);
    // Index: which axis is zero (3 ways) and the two signs (4 ways).
    const int zero = g.x == 0.0f ? 0 : (g.y == 0.0f ? 1 : 2);
    const float a = zero == 0 ? g.y : g.x, b = zero == 2 ? g.y : g.z;
    counts[4 * zero + (a < 0 ? 1 : 0) + (b < 0 ? 2 : 0)]++;
  }
  double chi2 = 0;
  for (int c : counts) chi2 += (c - n / 12.0) * (c - n / 12.0) / (n / 12.0);
  CHECK(chi2 < 11 + kSigmas * std::sqrt(22.0));
}

TEST_CASE("the texture's feature points are jittered uniformly and independently in their cells", "[fast][noise]") {
  // Through the keys a texture uses (channel seed, octave): joint 4^3 bins, and no correlation
  // between the axes (TileableVolumeNoise's points all lie on their cell's diagonal).
  const noise::TextureSpec spec = noise::preset("erosion", 9);
  const FbmParams fbm = noise::channel_params(spec, 1).fbm;
  const uvec3 key = noise_key(fbm.seed, 1u);
  const int n = 64000;
  std::vector<int> counts(64, 0);
  double xy = 0, yz = 0, zx = 0;
  for (int k = 0; k < n; ++k) {
    const vec3 o = feature_offset(ivec3(k % 40, k / 40 % 40, k / 1600), ivec3(40), key);
    counts[int(o.x * 4) + 4 * int(o.y * 4) + 16 * int(o.z * 4)]++;
    xy += (o.x - 0.5) * (o.y - 0.5);
    yz += (o.y - 0.5) * (o.z - 0.5);
    zx += (o.z - 0.5) * (o.x - 0.5);
  }
  double chi2 = 0;
  for (int c : counts) chi2 += (c - n / 64.0) * (c - n / 64.0) / (n / 64.0);
  CHECK(chi2 < 63 + kSigmas * std::sqrt(2.0 * 63));
  // Each product has variance 1/144; kSigmas standard errors of the mean.
  const double limit = kSigmas / 12.0 / std::sqrt(double(n));
  CHECK(std::abs(xy / n) < limit);
  CHECK(std::abs(yz / n) < limit);
  CHECK(std::abs(zx / n) < limit);
}

TEST_CASE("periodic perlin noise tiles exactly for negative coordinates too", "[fast][noise]") {
  const ivec3 period(4, 6, 5);
  const uvec3 key = noise_key(2u, 0u);
  std::mt19937 rng(13);
  for (int n = 0; n < 3000; ++n) {
    const vec3 p = random_point(rng, 10.0f);
    const float a = perlin_noise(p, period, key);
    for (int axis = 0; axis < 3; ++axis)
      for (int shift : {-3, -1, 1, 2}) {
        vec3 q = p;
        q[axis] += float(shift * period[axis]);
        // The rounding of the shifted position (|q| < 30, ulp 2e-6) times the slope (< 3), and
        // both sides' evaluation: kPerlinTiling.
        REQUIRE(perlin_noise(q, period, key) == Approx(a).epsilon(0).margin(kPerlinTiling));
      }
  }
}

TEST_CASE("every channel type tiles across the texture's edges", "[fast][noise]") {
  // The value one period further along each axis, negative included, is the same up to the
  // rounding of the position (texel units < 100, ulp 8e-6, times a slope below 10 per texel).
  noise::TextureSpec spec = spec_of(24, 16, 8, noise::NoiseType::perlin_worley, 3, 2);
  spec.channels.push_back(spec.channels[0]);
  spec.channels[1].type = noise::NoiseType::worley;
  spec.channels[1].cells = 6;
  spec.channels.push_back(spec.channels[1]);
  spec.channels[2].type = noise::NoiseType::perlin;
  std::mt19937 rng(17);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (size_t c = 0; c < spec.channels.size(); ++c) {
    const NoiseChannel channel = noise::channel_params(spec, static_cast<int>(c));
    const vec3 size(spec.width, spec.height, spec.depth);
    for (int n = 0; n < 500; ++n) {
      const vec3 p = vec3(u(rng), u(rng), u(rng)) * size;
      const float a = noise_channel_value(p, channel);
      for (int axis = 0; axis < 3; ++axis)
        for (int shift : {-2, 1, 3}) {
          vec3 q = p;
          q[axis] += float(shift) * size[axis];
          REQUIRE(noise_channel_value(q, channel) == Approx(a).epsilon(0).margin(kChannelTiling));
        }
    }
  }
}

TEST_CASE("the row walk computes the point functions' values", "[fast][noise]") {
  using noise::NoiseType;
  // Widths above 64 take two row segments; non-cubic sizes keep cubic cells.
  const noise::TextureSpec specs[] = {
      spec_of(16, 16, 16, NoiseType::worley, 4, 1),
      spec_of(72, 8, 8, NoiseType::inverted_worley, 9, 3),
      spec_of(16, 16, 16, NoiseType::perlin, 2, 4),
      spec_of(20, 10, 5, NoiseType::perlin, 4, 1),
      spec_of(100, 20, 20, NoiseType::perlin, 5, 1),  // cells of 20 texels: perlin_row_wide, a partial segment
      spec_of(128, 16, 16, NoiseType::perlin, 8, 2),  // the finishing octave walked wide
      spec_of(16, 8, 8, NoiseType::perlin_worley, 2, 3),
      spec_of(12, 12, 12, NoiseType::worley, 12, 1),  // one texel per cell
  };
  for (const auto& spec : specs) {
    const noise::Volume volume = noise::generate_cpu(spec);
    const NoiseChannel channel = noise::channel_params(spec, 0);
    for (int z = 0; z < spec.depth; ++z)
      for (int y = 0; y < spec.height; ++y)
        for (int x = 0; x < spec.width; ++x) {
          INFO("type " << noise::type_name(spec.channels[0].type) << " texel " << x << " " << y << " " << z);
          if (channel.type == NOISE_PERLIN) {
            // The same float operations in the same order.
            REQUIRE(volume.at(x, y, z, 0) == noise::reference_value(channel, x, y, z));
          } else {
            // The row walk sums dy^2 + dz^2 first: one rounding of a squared distance below 3
            // (2^-24 relative, halved by the square root), then averaged and scaled by <= 1.
            REQUIRE(volume.at(x, y, z, 0) ==
                    Approx(noise::reference_value(channel, x, y, z)).epsilon(0).margin(kRowWalk));
          }
        }
  }
}

TEST_CASE("inverted worley channels are the cover library's inverted worley fbm rescaled", "[fast][noise]") {
  const noise::TextureSpec spec = spec_of(16, 16, 16, noise::NoiseType::inverted_worley, 2, 3);
  const noise::Volume volume = noise::generate_cpu(spec);
  const FbmParams fbm = noise::channel_params(spec, 0).fbm;
  for (int z = 0; z < 16; z += 3)
    for (int y = 0; y < 16; y += 2)
      for (int x = 0; x < 16; ++x) {
        const float w = inverted_worley_fbm(vec3(x, y, z) + 0.5f, fbm).w;  // mean of 1 - F1
        REQUIRE(volume.at(x, y, z, 0) ==
                Approx(1.0f - (1.0f - w) / std::sqrt(3.0f)).epsilon(0).margin(kInvertedWorleyRescaled));
      }
}

TEST_CASE("channel values stay inside 0 to 1 without clipping", "[fast][noise]") {
  using noise::NoiseType;
  for (NoiseType type : {NoiseType::worley, NoiseType::inverted_worley, NoiseType::perlin, NoiseType::perlin_worley}) {
    const noise::Volume volume = noise::generate_cpu(spec_of(16, 16, 16, type, 2, 2));
    float lo = 1.0f, hi = 0.0f;
    for (float v : volume.values) {
      REQUIRE(v >= 0.0f);
      REQUIRE(v <= 1.0f);
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
    // The bounds are never reached (no texel saturates), and the values spread.
    INFO(noise::type_name(type) << ": " << lo << " .. " << hi);
    CHECK(lo > 0.0f);
    CHECK(hi < 1.0f);
    CHECK(hi - lo > kChannelSpread);
  }
}

TEST_CASE("seeds select the noise and the same seed gives the same texture", "[fast][noise]") {
  noise::TextureSpec spec = spec_of(16, 8, 8, noise::NoiseType::perlin_worley, 2, 2, 7);
  const noise::Volume a = noise::generate_cpu(spec);
  CHECK(noise::generate_cpu(spec).values == a.values);
  spec.seed = 8;
  const noise::Volume b = noise::generate_cpu(spec);
  int same = 0;
  for (size_t k = 0; k < a.values.size(); ++k) same += a.values[k] == b.values[k];
  CHECK(same < int(a.values.size() / kSameAtMostOneIn));
}

TEST_CASE("channels default to one detail level each with their own seeds", "[fast][noise]") {
  const noise::TextureSpec shape = noise::preset("shape", 1);
  REQUIRE(shape.channels.size() == 4);
  CHECK(shape.width == 128);
  CHECK(shape.channels[0].type == noise::NoiseType::perlin_worley);
  for (int c = 1; c < 4; ++c) {
    CHECK(shape.channels[c].type == noise::NoiseType::inverted_worley);
    CHECK(noise::channel_params(shape, c).fbm.period.x == 4 << (c - 1));
    CHECK(noise::channel_params(shape, c).fbm.seed != noise::channel_params(shape, c - 1).fbm.seed);
  }
  CHECK(noise::channel_params(shape, 0).worley.seed != noise::channel_params(shape, 0).fbm.seed);
  const noise::TextureSpec erosion = noise::preset("erosion", 1);
  CHECK(erosion.width == 32);
  CHECK(erosion.channels.size() == 3);
  CHECK_NOTHROW(noise::validate(shape));
  CHECK_NOTHROW(noise::validate(erosion));
}

TEST_CASE("texture specifications that cannot tile are refused with the option named", "[fast][noise]") {
  auto message = [](const noise::TextureSpec& spec) {
    try {
      noise::validate(spec);
    } catch (const noise::SpecError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  using noise::NoiseType;
  // 10 cells along 32 texels give 10 * 20 / 32 cells along the height 20.
  CHECK_THAT(message(spec_of(32, 20, 32, NoiseType::worley, 10, 1)),
             Catch::Contains("--cells") && Catch::Contains("multiple of 8"));
  CHECK(message(spec_of(32, 20, 32, NoiseType::worley, 8, 1)).empty());
  // Cells narrower than a texel.
  CHECK_THAT(message(spec_of(16, 16, 16, NoiseType::worley, 17, 1)), Catch::Contains("--cells"));
  CHECK_THAT(message(spec_of(16, 16, 16, NoiseType::worley, 4, 4)), Catch::Contains("--octaves"));
  noise::TextureSpec lacunarity = spec_of(32, 32, 32, NoiseType::perlin, 4, 3);
  lacunarity.channels[0].lacunarity = 1.5f;  // 4, 6, 9: fine
  CHECK(message(lacunarity).empty());
  lacunarity.channels[0].octaves = 4;  // 13.5 cells
  CHECK_THAT(message(lacunarity), Catch::Contains("--lacunarity"));
  CHECK_THAT(message(spec_of(0, 16, 16, NoiseType::worley, 1, 1)), Catch::Contains("--width"));
  CHECK_THAT(message(spec_of(16, -3, 16, NoiseType::worley, 1, 1)), Catch::Contains("--height"));
  noise::TextureSpec none = spec_of(8, 8, 8, NoiseType::worley, 1, 1);
  none.channels.clear();
  CHECK_THAT(message(none), Catch::Contains("--channels"));
  CHECK_THROWS_AS(noise::parse_type("simplex"), noise::SpecError);
  CHECK_THROWS_AS(noise::preset("cumulus", 1), noise::SpecError);
}

TEST_CASE("texels_below finds the first texel of every cell with the texels' own rounding", "[fast][noise]") {
  for (int size : {7, 12, 30, 64, 100, 128, 333, 2048})
    for (int cells : {1, 3, 7, 10, 16, 29, 64}) {
      if (cells > size) continue;
      const float frequency = float(cells) / float(size);
      int expected = 0;
      for (int c = 0; c <= cells; ++c) {
        // Brute force: the first texel whose centre lies in cell c or beyond.
        while (expected < size && std::floor((float(expected) + 0.5f) * frequency) < float(c)) ++expected;
        INFO("size " << size << " cells " << cells << " cell " << c);
        REQUIRE(texels_below(c, frequency) == expected);
      }
    }
}
