#pragma once
// Error bounds for the curl velocity, from the geometry of Worley F1: its gradient is the unit
// vector (p - feature) / F1, so a perturbation dp of the sample point turns it by dp / F1.
#include <algorithm>

#include "shader_math/shader_math.hpp"
#include "tolerances.hpp"

namespace nephele::test {

// F1 below which curl_octave_bound divides by this floor instead: only a guard against division
// by zero (F1 = 0 on a feature point), not a tolerance; the term is capped at 2 anyway, the most
// two unit gradients can differ.
constexpr float kF1Floor = 1.0e-6f;
// The largest change of a unit vector (|u - u'| <= 2), which caps each octave's term.
constexpr float kUnitVectorChange = 2.0f;

// The GPU's and C++'s lattice coordinates p = (n + offset) f_k (|n| = 1) differ by the rounding
// of the product and of what follows in the lattice (the cell offset, possibly fused on one side
// only): half an ulp of |p| <= f_k per component and operation, sqrt(3) 2^-24 f_k = 1.0e-7 f_k
// in length each; 1e-6 f_k allows about 10 of them. Partly empirical: the count of operations
// (and that the roundings of values below 3 in the cell, absolute rather than relative to f_k,
// stay within it for f_k < 1) is an estimate the GPU tests confirm, not a derivation.
constexpr float kLatticeRelative = 1.0e-6f;
static_assert(kLatticeRelative >= 1.7321f * kUlp * 8);
// The latitude mix m = sin(a lat), dm/dlat = a cos(a lat): lat is portable_asin on both sides
// (the same float operations), but GLSL 4.50 (section 4.7.1) leaves the precision of sin and cos
// undefined, so the GPU's may differ from C++'s by what llvmpipe's approximations give.
// Empirical: with an error e of a few ulp (2.4e-7), the gradient moves by s (e |grad w| +
// a e (|w| + |P|)), about 1e-6 for the defaults (s = 0.5, a = 2.5, P = 0.5, |grad w| of a few
// units); 1e-5 absolute is that with room, not a bound for every parameter set.
constexpr float kLatitudeMixAbsolute = 1.0e-5f;

// s * sum over both potentials and their octaves of (a_k / sum a) * f_k * term(f_k, F1_k),
// where term bounds the change of the unit gradient at octave k (F1 in cell units).
template <class Term>
float curl_octave_bound(glsl::vec3 n, const glsl::CurlParams& c, Term term) {
  float bound = 0.0f;
  for (const glsl::FbmParams* f : {&c.potential_north, &c.potential_south}) {
    float amplitude = 1.0f, frequency = f->frequency, norm = 0.0f, sum = 0.0f;
    for (int k = 0; k < f->octaves; ++k) {
      const float f1 = glsl::worley_f1(n * frequency, glsl::ivec3(0), glsl::noise_key(f->seed, glsl::uint(k))).w;
      sum += amplitude * frequency * std::min(kUnitVectorChange, term(frequency, std::max(f1, kF1Floor)));
      norm += amplitude;
      amplitude *= f->gain;
      frequency *= f->lacunarity;
    }
    if (norm > 0.0f) bound += c.strength * sum / norm;
  }
  return bound;
}

// GPU and CPU differ by rounding of n * f_k (kLatticeRelative f_k, which turns octave k's unit
// gradient by that over F1) and by sin/cos in the latitude mix (kLatitudeMixAbsolute).
inline float curl_rounding_bound(glsl::vec3 n, const glsl::CurlParams& c) {
  return kLatitudeMixAbsolute + curl_octave_bound(n, c, [](float f, float f1) { return kLatticeRelative * f / f1; });
}

}  // namespace nephele::test
