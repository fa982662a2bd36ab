#pragma once
// How far the marcher's GPU and C++ results may differ (tests/test_cloud_march.cpp and the
// cloud_march probe), derived from where float rounding matters most in it.
//
// Every sample's altitude is length(p - centre) - R with |p - centre| ~ R = 6.37e6 m, whose
// ulp is 0.5 m: the driver's dot products (fused multiply-adds) and square root against C++'s
// put the two sides' altitudes (and the ray-shell intervals, from the same cancellation) up to
// 2.5 ulp apart, kPosition = 1.25 m. Everything else (exp, pow, log2 within GLSL's 3 + 2|x| ulp,
// divisions 2.5 ulp, texture filtering) is below 1e-5 relative (measured against these terms, it
// is negligible). That position difference moves a sample
//   - in height fraction by kPosition / thickness, against vertical profiles no steeper than
//     30 per unit height (cumulus top: 1 - H(0.95, 1, h), slope 1.5 / 0.05);
//   - through the noise volume's vertical coordinate altitude / period by kPosition / period *
//     texels texels (the horizontal coordinates are small numbers, rounded far more finely),
//     where neighbouring texels differ by at most the volume's largest step (measured on the
//     volume, max_texel_step), the shape's remap (uniform_from_mix) multiplies by up to 1 / 0.6
//     and the coverage threshold's step H(0, 0.12, .) by up to 1.5 / 0.12 = 12.5.
// To first order each sample's contribution (and extinction) changes by at most that fraction of
// itself, so the pixel does too. Not covered: a coarse probe whose cloud bound crosses zero or a
// step count that flips between the two sides (neither happens in the tests' scenes).
#include <algorithm>

#include "shader_math/shader_math.hpp"

namespace nephele::test {

constexpr double kPosition = 1.25;  // metres, 2.5 ulp of the Earth's radius in float
// The steepest vertical profile, per unit height fraction: the cumulus top 1 - H(0.95, 1, h),
// a Hermite step over 0.05 with slope up to 1.5 / 0.05 = 30.
constexpr double kSteepestProfile = 30.0;
// The coverage threshold's step H(0, 0.12, .): slope up to 1.5 / 0.12 = 12.5.
constexpr double kThresholdSlope = 12.5;
// The shape's remap uniform_from_mix has slope up to 1 / a, a = 1 - w = 0.6 (w = 0.4).
constexpr double kRemapA = 0.6;

// The largest difference between neighbouring texels (along any axis, wrapping) of the noise
// volume's base level in one channel (0 R .. 3 A).
inline float max_texel_step_of(const glsl::VolumeSource& volume, int channel) {
  const int n = volume.size;
  const auto& v = volume.levels[0];
  auto at = [&](int i, int j, int k) { return v[(static_cast<size_t>(k % n) * n + j % n) * n + i % n][channel]; };
  float step = 0.0f;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (float next : {at(i + 1, j, k), at(i, j + 1, k), at(i, j, k + 1)})
          step = std::max(step, std::abs(next - at(i, j, k)));
  return step;
}

// The same over the shape and detail channels (RG), which the other types read.
inline float max_texel_step(const glsl::VolumeSource& volume) {
  return std::max(max_texel_step_of(volume, 0), max_texel_step_of(volume, 1));
}

// Relative tolerance for layers at least `thickness` thick whose noise repeats vertically every
// `period` metres or more, with the volume `noise` of noise.size texels per period.
inline double march_tolerance(double thickness, double period, const glsl::VolumeSource& noise) {
  const double vertical = kSteepestProfile * kPosition / thickness;
  const double texels_moved = kPosition / period * noise.size;
  return vertical + kThresholdSlope / kRemapA * max_texel_step(noise) * texels_moved;
}

}  // namespace nephele::test
