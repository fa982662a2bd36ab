#pragma once
// Error bounds for the curl velocity, from the geometry of Worley F1: its gradient is the unit
// vector (p - feature) / F1, so a perturbation dp of the sample point turns it by dp / F1.
#include <algorithm>

#include "shader_math/shader_math.hpp"

namespace nephele::test {

// s * sum over both potentials and their octaves of (a_k / sum a) * f_k * term(f_k, F1_k),
// where term bounds the change of the unit gradient at octave k (F1 in cell units).
template <class Term>
float curl_octave_bound(glsl::vec3 n, const glsl::CurlParams& c, Term term) {
  float bound = 0.0f;
  for (const glsl::FbmParams* f : {&c.potential_north, &c.potential_south}) {
    float amplitude = 1.0f, frequency = f->frequency, norm = 0.0f, sum = 0.0f;
    for (int k = 0; k < f->octaves; ++k) {
      const float f1 = glsl::worley_f1(n * frequency, glsl::ivec3(0), glsl::noise_key(f->seed, glsl::uint(k))).w;
      sum += amplitude * frequency * std::min(2.0f, term(frequency, std::max(f1, 1e-6f)));
      norm += amplitude;
      amplitude *= f->gain;
      frequency *= f->lacunarity;
    }
    if (norm > 0.0f) bound += c.strength * sum / norm;
  }
  return bound;
}

// GPU and CPU differ by rounding of n * f_k (a few ulp, below 1e-6 f_k for |n| = 1) and by a
// few ulp of sin/asin/cos in the latitude mix (1e-5 absolute).
inline float curl_rounding_bound(glsl::vec3 n, const glsl::CurlParams& c) {
  return 1e-5f + curl_octave_bound(n, c, [](float f, float f1) { return 1e-6f * f / f1; });
}

}  // namespace nephele::test
