// The light of a plane-parallel cloud slab (docs/orbit_view.md, "Cloud light"): how much of the
// sunlight a cloud of optical thickness tau reflects and lets through, by the delta-Eddington
// approximation for conservative scattering, and the source function that makes a marched slab
// reflect and transmit those amounts. Cloud droplets scatter visible light conservatively (single
// scattering albedo above 0.999) and strongly forwards (asymmetry g = 0.85; Hansen and Travis
// 1974, "Light scattering in planetary atmospheres", Space Sci. Rev. 16).
#ifndef NEPHELE_SLAB_SCATTERING_GLSL
#define NEPHELE_SLAB_SCATTERING_GLSL
#include "prelude.glsl"
#include "portable_math.glsl"

const float CLOUD_ASYMMETRY = 0.85f;

// The share of diffuse light falling on a conservatively scattering layer of vertical optical
// depth tau that gets through it: 1 / (1 + 3/4 (1 - g) tau) (the two-stream Eddington
// approximation; Bohren, "Multiple scattering of light and some of its observable consequences",
// Am. J. Phys. 55, 1987).
float slab_diffuse_transmittance(float tau) { return 1.0f / (1.0f + 0.75f * (1.0f - CLOUD_ASYMMETRY) * max(tau, 0.0f)); }

// The isotropic source per unit of the sky's radiance that makes a slab of optical thickness tau,
// lit by a sky of uniform radiance, look from above as bright as the share of the sky's light it
// reflects: all that it does not let through, 1 - slab_diffuse_transmittance(tau), over the
// slab's own emissivity 1 - exp(-tau) (3/4 (1 - g) = 0.1125 as tau goes to 0).
float slab_sky_source(float tau) {
  float t = max(tau, 0.0f);
  float reflected = 1.0f - slab_diffuse_transmittance(t);
  return t < 1.0e-4f ? 0.75f * (1.0f - CLOUD_ASYMMETRY) : reflected / (1.0f - exp(-t));
}

// The sun's cosine below which the slab formulas hold it (a grazing sun's light is gone anyway).
const float SLAB_MIN_MU0 = 0.02f;

// The share of the sunlight (flux on the horizontal, sun at cosine mu0) that a conservatively
// scattering slab of optical thickness tau over a black surface reflects: the delta-Eddington
// approximation (Joseph, Wiscombe and Weinman 1976, "The delta-Eddington approximation for
// radiative flux transfer", J. Atmos. Sci. 33): the phase function's forward peak, the share
// f = g^2, is taken as unscattered, which leaves tau' = (1 - f) tau and g' = g / (1 + g), and
// Eddington's solution for that slab is
//   R = (3/4 (1 - g) tau + (1/2 - 3/4 mu0) (1 - exp(-tau' / mu0))) / (1 + 3/4 (1 - g) tau)
// ((1 - g') tau' = (1 - g) tau). Against a Monte Carlo of the Henyey-Greenstein slab
// (tests/test_slab_scattering.cpp) it is within 0.02 for mu0 >= 0.5 and underestimates a low sun's
// reflectance by up to 0.06 at mu0 = 0.3, as Joseph et al. found.
float slab_reflectance(float tau, float mu0) {
  float m = max(mu0, SLAB_MIN_MU0);
  float t = max(tau, 0.0f);
  float a = 0.75f * (1.0f - CLOUD_ASYMMETRY) * t;
  float scaled = (1.0f - CLOUD_ASYMMETRY * CLOUD_ASYMMETRY) * t;
  return clamp((a + (0.5f - 0.75f * m) * (1.0f - exp(-scaled / m))) / (1.0f + a), 0.0f, 1.0f);
}

// The share of the sunlight that crosses the slab in the delta-Eddington forward peak or
// unscattered: exp(-tau' / mu0). What the slab neither reflects nor lets through so is diffuse.
float slab_direct_transmittance(float tau, float mu0) {
  float m = max(mu0, SLAB_MIN_MU0);
  return exp(-(1.0f - CLOUD_ASYMMETRY * CLOUD_ASYMMETRY) * max(tau, 0.0f) / m);
}

// The radiance that singly scattered sunlight (irradiance 1 on a plane facing the sun, phase
// function value `phase` towards the viewer) gives a slab of optical thickness tau seen straight
// down (x) and straight up from below (y): the integrals of phase exp(-t / mu0) exp(-t) over the
// depth t, and of phase exp(-t / mu0) exp(-(tau - t)).
vec2 slab_single_scattering(float tau, float mu0, float phase_down, float phase_up) {
  float m = max(mu0, SLAB_MIN_MU0);
  float t = max(tau, 0.0f);
  float down = phase_down * m / (1.0f + m) * (1.0f - exp(-t * (1.0f + 1.0f / m)));
  float k = 1.0f - 1.0f / m;  // <= 0
  // (exp(-t / m) - exp(-t)) / k, and its limit t exp(-t) when the sun is overhead.
  float up = abs(k * t) < 1.0e-3f ? t * exp(-t) * (1.0f + 0.5f * k * t) : (exp(-t / m) - exp(-t)) / k;
  return vec2(down, phase_up * max(up, 0.0f));
}

// b1 - a1 = tau - 2 + (2 + tau) exp(-tau) (slab_source's moments), without the cancellation of
// its terms near 2 below tau 1: there its series, the sum over k >= 3 of (-1)^k (2 - k) tau^k / k!,
// to k = 8 (the next term, tau^9 / 51840, is below 2e-4 of the sum).
float slab_moment_difference(float tau) {
  float t = max(tau, 0.0f);
  if (t >= 1.0f) return t - 2.0f + (2.0f + t) * exp(-t);
  return t * t * t * (1.0f / 6.0f + t * (-1.0f / 12.0f + t * (1.0f / 40.0f + t * (-1.0f / 180.0f + t * (1.0f / 1008.0f - t / 6720.0f)))));
}

// The multiply scattered light of a slab of optical thickness tau as an isotropic source of
// radiance per unit optical depth J(t) = x + y t, t the depth below the slab's top, for sunlight
// of irradiance 1 on a plane facing the sun at cosine mu0. Its x and y are such that the slab seen
// straight down, with the single scattering of the phase values phase_down and phase_up added,
// has the radiance R mu0 / pi of a reflectance R = slab_reflectance spread evenly over the
// directions, and seen straight up from below the diffuse transmittance T = 1 - R - the direct
// share, as T mu0 / pi: the integrals of J exp(-t) and J exp(-(tau - t)) over the depth are
//   x a0 + y a1 = top,  x a0 + y b1 = bottom,
// a0 = 1 - e, a1 = 1 - (1 + tau) e, b1 = tau - 1 + e, e = exp(-tau). Within a conservative slab
// the diffuse light falls linearly with depth (the two-stream solution), which is why J is
// linear. In thin slabs the two conditions nearly coincide (b1 - a1 ~ tau^3 / 6)
// and J goes to a constant (y = 0) from tau 0.4 down to 0.2, keeping the view from above exact.
vec2 slab_source(float tau, float mu0, float phase_down, float phase_up) {
  float t = max(tau, 0.0f);
  if (t <= 0.0f || mu0 <= 0.0f) return vec2(0.0f);
  float m = max(mu0, SLAB_MIN_MU0);
  float reflectance = slab_reflectance(t, m);
  float diffuse_through = max(1.0f - reflectance - slab_direct_transmittance(t, m), 0.0f);
  vec2 single = slab_single_scattering(t, m, phase_down, phase_up);
  float top = max(reflectance * mu0 / PI_F - single.x, 0.0f);
  float bottom = max(diffuse_through * mu0 / PI_F - single.y, 0.0f);
  float e = exp(-t);
  float a0 = 1.0f - e;
  float a1 = 1.0f - (1.0f + t) * e;
  float slope = smoothstep(0.2f, 0.4f, t) * (bottom - top) / max(slab_moment_difference(t), 1.0e-9f);
  vec2 source = vec2((top - slope * a1) / a0, slope);
  // Where that line would be negative at an end, the line through 0 there instead, which keeps
  // the view from above exact and misses the one from below by the least a source that is nowhere
  // negative can: at the base where a low sun on a thin slab reflects far more than it lets
  // through diffusely (J falls to 0 there, the view from below too bright), at the top where a
  // high sun on a thin slab lets through far more than it reflects (J rises from 0, too dim).
  if (source.x + source.y * t < 0.0f) {
    float x = top / max(a0 - a1 / t, 1.0e-9f);
    source = vec2(x, -x / t);
  } else if (source.x < 0.0f) {
    source = vec2(0.0f, top / max(a1, 1.0e-9f));
  }
  return source;
}

// J at depth t (slab_source's x + y t), never negative (float rounding at the base).
float slab_source_at(vec2 source, float depth) { return max(source.x + source.y * depth, 0.0f); }

#endif
