// Cloud densities of each layer type, as functions of the height fraction in the layer, the
// local coverage and two noise values (a shape noise and a detail noise, both inverted Worley
// fBm in [0, 1]). In the style of Webanck et al., "Procedural Cloudscapes" (Computer Graphics
// Forum 37(2), 2018): coverage thresholds, Hermite steps H and a vertical profile per type;
// see docs/layers.md. Cumulus and alto have the paper's exact forms in webanck_forms.glsl.
#ifndef NEPHELE_CLOUD_DENSITY_GLSL
#define NEPHELE_CLOUD_DENSITY_GLSL
#include "prelude.glsl"

const int CLOUD_CIRRUS = 0;
const int CLOUD_CIRROSTRATUS = 1;
const int CLOUD_CIRROCUMULUS = 2;
const int CLOUD_ALTO = 3;
const int CLOUD_CUMULUS = 4;
const int CLOUD_STRATOCUMULUS = 5;
const int CLOUD_STRATUS = 6;
const int CLOUD_FOG = 7;

// The cubic Hermite step H(a, b, x): 0 below a, 1 above b, 3t^2 - 2t^3 between.
float hermite_step(float a, float b, float x) {
  float t = clamp((x - a) / (b - a), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

// Vertical profile of a sheet: soft bottom and top.
float sheet_profile(float h, float soft) {
  return hermite_step(0.0f, soft, h) * (1.0f - hermite_step(1.0f - soft, 1.0f, h));
}

// Heaped clouds (cirrocumulus, the cells of stratocumulus): the shape noise must exceed
// the clear-sky fraction 1 - c, more so higher up (rounded tops, flat bases); the detail noise
// erodes the edges.
float heaped_density(float h, float c, float shape, float detail, float top_rounding) {
  float field = shape - (1.0f - c) - top_rounding * h * (1.0f - 0.5f * c);
  float eroded = field - 0.25f * (1.0f - detail) * (1.0f - hermite_step(0.0f, 0.25f, field));
  return hermite_step(0.0f, 0.12f, eroded) * hermite_step(0.0f, 0.06f, h) * (1.0f - hermite_step(0.95f, 1.0f, h));
}

// How much of a sheet stands where the shape noise (uniform in [0, 1]) is `shape` under coverage
// c: a ramp centred on the quantile 1 - c, so that the sheet's mean over the sky is c exactly and
// its edges are frayed by the noise; the ramp (0.3 of the noise's range) narrows as c nears 0
// or 1, so that no coverage draws nothing and full coverage an unbroken sheet. (An earlier form,
// H(0.15, 0.55, c + (shape - 1/2) / 2), drew a fifth of the sky with some cloud at c = 0 and
// nearly all of it at c = 1/2: the ground saw a veil where the orbit view saw clear sky.)
float sheet_amount(float c, float shape) {
  float cc = clamp(c, 0.0f, 1.0f);
  float half_width = min(0.15f, min(cc, 1.0f - cc));
  if (half_width <= 0.0f) return shape > 1.0f - cc ? 1.0f : 0.0f;
  return hermite_step(1.0f - cc - half_width, 1.0f - cc + half_width, shape);
}

// Stratiform sheets: coverage through sheet_amount, a soft profile, faint texture.
float sheet_density(float h, float c, float shape, float detail) {
  return sheet_amount(c, shape) * sheet_profile(h, 0.25f) * (0.7f + 0.3f * detail);
}

// The sea of fog (a stratus deck under a winter inversion, docs/terrain.md): full density from
// its base (below the ground of the Plateau) up to a top that the shape noise lowers by up to
// FOG_TOP_UNDULATION of the layer (about 45 m for the default 490-800 m layer), with a sharp
// edge FOG_TOP_EDGE thick there: the inversion caps the mixed layer, so the fog ends within
// metres rather than thinning away with height; faint texture from the detail noise.
const float FOG_TOP_UNDULATION = 0.15f;
const float FOG_TOP_EDGE = 0.05f;
float fog_density(float h, float c, float shape, float detail) {
  float top = 1.0f - FOG_TOP_UNDULATION * shape;
  return c * (1.0f - hermite_step(top - FOG_TOP_EDGE, top, h)) * (0.85f + 0.15f * detail);
}

float cloud_density(int type, float h, float c, float shape, float detail) {
  if (c <= 0.0f || h < 0.0f || h > 1.0f) return 0.0f;
  // Cumulus and alto have Webanck et al.'s exact forms (webanck_forms.glsl), which the marcher
  // evaluates on their own fields; they have no density of this kind.
  if (type == CLOUD_CUMULUS || type == CLOUD_ALTO) return 0.0f;
  if (type == CLOUD_STRATOCUMULUS) {
    // Flattened heaps that merge into a sheet as coverage grows.
    return max(heaped_density(h, c, shape, detail, 0.3f), sheet_density(h, c - 0.3f, shape, detail));
  }
  if (type == CLOUD_STRATUS) return sheet_density(h, c, shape, detail);
  if (type == CLOUD_CIRRUS) {
    // Fibres: the noise is stretched along the wind by the caller; thin, patchy.
    return c * hermite_step(0.45f, 0.8f, shape * (0.6f + 0.4f * detail)) * sheet_profile(h, 0.4f);
  }
  if (type == CLOUD_CIRROSTRATUS) return c * sheet_profile(h, 0.4f) * (0.5f + 0.5f * detail);
  if (type == CLOUD_CIRROCUMULUS) return heaped_density(h, c, shape, detail, 0.1f);
  if (type == CLOUD_FOG) return fog_density(h, c, shape, detail);
  return 0.0f;
}

// The noise volume holds uniformly distributed values (rank-equalised after it is made), so that
// "shape > 1 - c" covers the fraction c of the sky. Mixing two independent uniforms,
// x = (1 - w) u1 + w u2 with w <= 1/2, gives a trapezoidal distribution; its CDF turns x back
// into a uniform value:
//   F(x) = x^2 / (2 a b)            for 0 <= x <= b
//        = (x - b/2) / a            for b <= x <= a
//        = 1 - (1 - x)^2 / (2 a b)  for a <= x <= 1,   a = 1 - w, b = w.
float uniform_from_mix(float x, float w) {
  float a = 1.0f - w;
  float b = w;
  float t = clamp(x, 0.0f, 1.0f);
  if (t <= b) return t * t / (2.0f * a * b);
  if (t <= a) return (t - 0.5f * b) / a;
  return 1.0f - (1.0f - t) * (1.0f - t) / (2.0f * a * b);
}

// Horizontal size (m) of one noise period along and across the wind, per type.
vec2 noise_period(int type) {
  if (type == CLOUD_CUMULUS) return vec2(6000.0f, 6000.0f);
  if (type == CLOUD_STRATOCUMULUS) return vec2(5000.0f, 5000.0f);
  if (type == CLOUD_STRATUS) return vec2(12000.0f, 12000.0f);
  if (type == CLOUD_ALTO) return vec2(4000.0f, 4000.0f);
  if (type == CLOUD_CIRRUS) return vec2(40000.0f, 5000.0f);
  if (type == CLOUD_CIRROSTRATUS) return vec2(20000.0f, 20000.0f);
  if (type == CLOUD_CIRROCUMULUS) return vec2(1500.0f, 1500.0f);
  return vec2(3000.0f, 3000.0f);  // fog
}

// Henyey-Greenstein lobes forward (g = 0.8) and back (g = -0.3), 70:30.
float cloud_phase(float nu, float scale) {
  float forward = 0.8f * scale;
  float back = -0.3f * scale;
  float f = (1.0f - forward * forward) / pow(max(1.0f + forward * forward - 2.0f * forward * nu, 1.0e-6f), 1.5f);
  float b = (1.0f - back * back) / pow(max(1.0f + back * back - 2.0f * back * nu, 1.0e-6f), 1.5f);
  return (0.7f * f + 0.3f * b) / (4.0f * 3.14159265358979f);
}

// Sample i of n of a light march over a path of length_to_exit towards the sun, spaced
// quadratically (s = L t^2): the light that reaches a point is decided by the first hundred
// metres towards the sun (an optical depth of 1 every 50 m in a cumulus), so the steps are
// short there and long further out. Returns (distance of the sample's midpoint, step length).
vec2 light_sample(int i, int n, float length_to_exit) {
  float t0 = float(i) / float(n);
  float t1 = float(i + 1) / float(n);
  float t = 0.5f * (t0 + t1);
  return vec2(length_to_exit * t * t, length_to_exit * (t1 * t1 - t0 * t0));
}

// Sun light reaching a cloud point through optical depth tau towards the sun, with multiple
// scattering approximated by octaves (Wrenninge, Kulla and Lundqvist, "Oz: The Great and
// Volumetric", SIGGRAPH 2013 talk): sum_i a^i e^{-b^i tau} p(nu; c^i g), a = c = 1/2, b = 1/4:
// the deeper octaves see a quarter and a sixteenth of the optical depth, which keeps the bases
// of thick clouds (tau of 30 and more towards the sun) from turning black.
// The powder term (Schneider, "The real-time volumetric cloudscapes of Horizon Zero Dawn",
// SIGGRAPH 2015 Advances in Real-Time Rendering): near a cloud's sun-facing surface the light
// has not yet been scattered into all directions, so that surface looks darker than the single
// and octave terms give, most when the sun is behind the viewer. Art-directed, as Schneider's:
//   P = 1 - k w(nu) exp(-2 tau),  w = (1 - nu) / 2,
// tau the optical depth towards the sun, nu the cosine between the view ray and the sun, k in
// [0, 1] the strength (the scene key powder; 0 leaves the light as it is). Multiplies the sun term.
float powder_factor(float tau, float nu, float strength) {
  return 1.0f - strength * (0.5f - 0.5f * nu) * exp(-2.0f * tau);
}

float sun_scattering(float tau, float nu) {
  float sum = 0.0f;
  float a = 1.0f;
  float b = 1.0f;
  float c = 1.0f;
  for (int i = 0; i < 3; ++i) {
    sum += a * exp(-b * tau) * cloud_phase(nu, c);
    a *= 0.5f;
    b *= 0.25f;
    c *= 0.5f;
  }
  return sum;
}

#endif
