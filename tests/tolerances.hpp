#pragma once
// Tolerances that several tests share, each with the derivation of its value. A constant whose
// value was not derived but fitted to what the code gave says "empirical". Values were kept as
// they were when they became constants; where the derivation asks for less, a static_assert
// checks that the value is at least what the derivation asks for.

namespace nephele::test {

// One float rounding, relative: 2^-24 (half an ulp of values in [1, 2)).
constexpr float kUlp = 1.0f / 16777216.0f;
// One double rounding, relative: 2^-53.
constexpr double kDoubleUlp = 1.0 / 9007199254740992.0;

// |length(w) - 1| for a unit vector made by normalize, on either side: the squared length
// (3 products, 2 sums, up to 2 of them fused: 3 ulp), inversesqrt (GLSL: 2 ulp; C++: sqrt and a
// division, 2 roundings) and the 3 products (1 ulp), then the test's own length (3 ulp of the
// square, halved by sqrt, and sqrt's rounding: 2.5 ulp): about 8.5 ulp, 5.1e-7; 1e-6 (16.8 ulp)
// leaves a factor of 2.
constexpr float kUnitLength = 1.0e-6f;
static_assert(kUnitLength >= 8.5f * kUlp);

// A texel direction against texel_direction on the other side (GPU or another formula): the face
// coordinates' division (GLSL: 2.5 ulp), normalize (kUnitLength's 6 ulp) and up to 2 contracted
// multiply-adds: 8 ulp per component, sqrt(3) x 8 ulp = 8.3e-7 in length; rounded up to 1e-6
// (the same value as kDirection of test_shader_probes.cpp).
constexpr float kDirection = 1.0e-6f;
static_assert(kDirection >= 1.7321f * 8 * kUlp);

// Rounding of one operation in the warp's rounding bounds: 2.4e-7 is 2^-22 rounded up, four
// float roundings (2^-24 each), room for fused operations done differently on GPU and CPU.
constexpr double kOperationRounding = 2.4e-7;
static_assert(kOperationRounding >= 4 * double(kUlp));
// Operations per velocity evaluation in a warp step, each kOperationRounding: the bilinear
// sample's fractions and two mixes (about 5) and the step's multiply-add and normalisation
// (about 3). A count, not measured: the bound is checked against what it must cover, the
// largest GPU-CPU difference, by the tests that use it.
constexpr int kOperationsPerEvaluation = 8;

// Worley fBm values (test stream functions built from them) computed in float: values below 1,
// sums of up to 5 weighted octaves and a division, a couple of ulp of values below 1 (2^-24 each
// relative, 6e-8): 1e-7 (1.7 ulp). Only roughly derived: the octaves' lattice coordinates p f
// (up to 24 here) carry their own rounding, f |p| 2^-24 per octave, weighted by a_k / sum a.
constexpr float kFbmValueRounding = 1.0e-7f;

// The curl velocity v = s cross(n, g) is tangent: cross(n, g) . n vanishes exactly for any n, so
// only rounding remains. Each component of the cross product is rounded by up to 2 ulp of
// |n||g| (its two products and the subtraction, possibly fused), which the dot product with n
// carries over (|n| = 1), and the dot product adds 3 ulp of |v|: 4 ulp of s|g| + 3 ulp of |v|.
// The bound 1e-6 (1 + |v|) (16.8 ulp) covers that whenever s |g| <= 3 (1 + |v|), i.e. as long
// as grad phi's normal component (from the 3D Worley gradients) is not much larger than the
// tangential one plus 3 / s: it holds in the tests (they pass), but it is not derived for every
// parameter set (partly empirical).
constexpr float kTangentRelative = 1.0e-6f;
static_assert(kTangentRelative >= 4 * kUlp * 3 + 3 * kUlp);

// portable_asin against arcsin: Abramowitz and Stegun 4.4.46 bound the approximation by 2e-8;
// float evaluation of the polynomial and sqrt adds about 4 ulp of pi/2 (4 x 2^-23 x 1.57 = 7.5e-7
// in the worst case, 5e-7 as measured: the second term is empirical, below the 4-ulp figure).
constexpr double kAsinApproximation = 2e-8;
constexpr double kAsinRounding = 5e-7;
constexpr double kPortableAsin = kAsinApproximation + kAsinRounding;

// The adaptive Bogacki-Shampine warp's global error against its requested tolerance: error
// control per step with local extrapolation keeps the global error of the order of the
// tolerance; the factor 5 is empirical (what the zonal-flow runs give with room), not derived.
constexpr double kAdaptiveErrorFactor = 5.0;

// Solid-angle fractions of texels summed in double in two different orders (or scalings) and
// compared: recursive summation of N non-negative terms of total at most 1 errs by at most
// (N - 1) 2^-53, 6.8e-13 for the 6 x 32^2 texels of the cover tests. For 6 x 64^2 texels (the
// coverage test's largest size) that worst case is 2.7e-12, above this value; the typical
// (random-walk) error sqrt(N) 2^-53 is 1.7e-14. So not a strict bound at the largest size:
// kept as set.
constexpr double kFractionSum = 1.0e-12;
static_assert(kFractionSum >= (6 * 32 * 32 - 1) * kDoubleUlp);

// A window's 8-bit framebuffer against the same tone-mapped float image: storing v rounds
// 255 v to an integer (half a step, 0.5 / 255), and OpenGL leaves the direction of that rounding
// to the implementation (a further half step); bilinear sampling at texel centres adds a few
// float ulps, far below. One 8-bit step in all.
constexpr double kEightBitDisplay = 1.0 / 255.0;

// A flight step of d metres against the straight line between the camera's positions (ECEF):
// the move goes along the tangent plane, d^2 / 2R (1 mm at 100 m) above the camera's height,
// and back down along the normal to that height, which shortens the line by about
// d^3 / (2 R^2), 1e-8 m at 100 m; 1e-6 m is a hundred times that, and far above the double
// rounding of GeographicLib's conversions (about 1e-9 m at the Earth's radius).
constexpr double kFlightStepMetres = 1.0e-6;

}  // namespace nephele::test
