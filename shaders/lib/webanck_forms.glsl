// The cumulus and altostratus/altocumulus forms of Webanck, Cortial, Guérin and Galin,
// "Procedural Cloudscapes", Computer Graphics Forum 37(2), 2018, supplementary material, as
// written there (docs/layers.md "Webanck forms" gives every formula, the units and what is
// substituted): density max(0, phi - delta) from fields G3 (octaves of gradient noise) and W3
// (octaves of complemented Worley noise) over p_n = p / 1080, p in units of 100 m, in a frame
// whose x runs along the local wind. The exact fields (webanck_g3, webanck_w3,
// cumulus_fields_exact, alto_fields_exact) are the reference; the renderer reads the same fields
// baked into its noise volume (cloud_march.glsl).
#ifndef NEPHELE_WEBANCK_FORMS_GLSL
#define NEPHELE_WEBANCK_FORMS_GLSL
#include "prelude.glsl"
#include "tileable_noise.glsl"
#include "worley_fbm.glsl"
#include "cloud_density.glsl"
#include "cloud_properties.glsl"

// Standard deviation of the weighted octave mean sum_k a_k n_k / sum_k a_k of independent
// octaves (a_k = persistence^k) of a noise with deviation sigma: sigma sqrt(sum a^2) / sum a.
float octave_mean_sigma(int octaves, float persistence, float sigma) {
  float sum = 0.0f;
  float sum_squares = 0.0f;
  float a = 1.0f;
  for (int k = 0; k < octaves; ++k) {
    sum += a;
    sum_squares += a * a;
    a *= persistence;
  }
  return sigma * sqrt(sum_squares) / sum;
}

// G3's map to [0, 1]: the octave mean m of gradient noise, standardised by its derived
// deviation and put through the normal CDF, G3 = Phi(m / sigma_m). The octave sum is close to
// normal, so G3 is close to uniform (a rank-equalising map): the paper's H thresholds then
// select the fractions of space they name (H(0.45, 0.65, n2) keeps about 45 %).
float g3_from_mean(float mean, int octaves, float persistence) {
  return normal_cdf(mean / octave_mean_sigma(octaves, persistence, PERLIN_OCTAVE_SIGMA));
}

// The fBm parameters of o octaves, persistence p, lacunarity l, base frequency f, not periodic.
FbmParams webanck_octaves(int octaves, float persistence, float lacunarity, float frequency, uint seed) {
  return make_fbm_params(frequency, octaves, lacunarity, persistence, seed, ivec3(0));
}

// G3(o, p, l, f, x): o octaves of gradient noise, persistence p, lacunarity l, base frequency
// f (cycles per unit of x), not periodic; octave k hashed with noise_key(seed, k).
float webanck_g3(int octaves, float persistence, float lacunarity, float frequency, vec3 x, uint seed) {
  return g3_from_mean(perlin_fbm_mean(x, webanck_octaves(octaves, persistence, lacunarity, frequency, seed)), octaves, persistence);
}

// W3(o, p, l, f, x): the weighted mean of octaves of complemented Worley noise 1 - w, with
// w = F1 / sqrt 3 in [0, 1] (F1 of one feature point per cell is below sqrt 3).
float webanck_w3(int octaves, float persistence, float lacunarity, float frequency, vec3 x, uint seed) {
  return worley_unit(worley_fbm_mean(x, webanck_octaves(octaves, persistence, lacunarity, frequency, seed)), true);
}

// p_n of a point p (metres; x east, y north, z up) in the frame whose x runs along the unit
// wind direction (east, north): p / 100 m / 1080.
vec3 webanck_position(vec3 p, vec2 wind) {
  vec3 along = vec3(dot(vec2(p), wind), dot(vec2(p), vec2(-wind.y, wind.x)), p.z);
  return along * (1.0f / 108000.0f);
}

// Each field's own hash seed.
uint field_seed(uint seed, int field) { return seed ^ (0x9E3779B9u * uint(field + 1)); }

// Cumulus: phi = 2 k2 n3 H(0.45, 0.65, n2), k2 = (1 - k1) + k1 n5, k1 = H(0.1, 0.9, n4)^2.
// shift moves the n2 window (0 in the paper; the renderer ties it to the weather's coverage).
float cumulus_phi(float n2, float n3, float n4, float n5, float shift) {
  float k1 = hermite_step(0.1f, 0.9f, n4);
  k1 *= k1;
  float k2 = (1.0f - k1) + k1 * n5;
  return 2.0f * k2 * n3 * hermite_step(0.45f + shift, 0.65f + shift, n2);
}

// Cumulus: delta = 0.77 ((1 - n6) + 0.5 (1 - n7) + 0.25 n8 + 0.5 n9).
float cumulus_delta(float n6, float n7, float n8, float n9) {
  return 0.77f * ((1.0f - n6) + 0.5f * (1.0f - n7) + 0.25f * n8 + 0.5f * n9);
}

// Altostratus (k = 1) to altocumulus (k = 0): phi = k + (1 - k) H(0.43, 1, n1),
// delta = (1 - k)(0.75 n2 + 0.25 (1 - n3)).
float alto_phi(float k, float n1) { return k + (1.0f - k) * hermite_step(0.43f, 1.0f, n1); }

float alto_delta(float k, float n2, float n3) { return (1.0f - k) * (0.75f * n2 + 0.25f * (1.0f - n3)); }

// The exact cumulus fields n2..n9 at p_n, time offset tau: (n2, n3, n4, n5) and (n6, n7, n8, n9).
// n3, n4, n5 and their offsets q3..q5 are substitutes (their definitions are missing from the
// available text; docs/layers.md): n3 = G3(8, 0.52, 2.02, 40, p_n + (-2 tau, 0, 0)),
// n4 = G3(.., 40, p_n + (-2 tau, 0, 0)) of another seed, n5 = G3(.., 80, p_n + (-3 tau, 0, 0)).
void cumulus_fields_exact(vec3 pn, float tau, uint seed, OUT(vec4) shape, OUT(vec4) detail) {
  vec3 q = vec3(-tau, 0.0f, 0.0f);
  shape.x = webanck_g3(8, 0.52f, 2.02f, 15.0f, vec3(0.65f * pn.x, pn.y, pn.z) + q, field_seed(seed, 2));
  shape.y = webanck_g3(8, 0.52f, 2.02f, 40.0f, pn + 2.0f * q, field_seed(seed, 3));
  shape.z = webanck_g3(8, 0.52f, 2.02f, 40.0f, pn + 2.0f * q, field_seed(seed, 4));
  shape.w = webanck_g3(8, 0.52f, 2.02f, 80.0f, pn + 3.0f * q, field_seed(seed, 5));
  detail.x = webanck_w3(4, 0.33f, 3.0f, 160.0f, pn + 4.0f * q, field_seed(seed, 6));
  detail.y = webanck_w3(2, 0.5f, 2.0f, 240.0f, pn + 0.8f * q, field_seed(seed, 7));
  detail.z = webanck_g3(8, 0.52f, 2.02f, 288.0f, pn + 8.0f * q, field_seed(seed, 8));
  detail.w = webanck_g3(8, 0.52f, 2.02f, 384.0f, pn + 8.0f * q, field_seed(seed, 9));
}

// The exact alto fields (n1, n2, n3) at p_n, time offset tau.
vec3 alto_fields_exact(vec3 pn, float tau, uint seed) {
  vec3 q = vec3(-tau, 0.0f, 0.0f);
  float n1 = webanck_g3(8, 0.52f, 2.02f, 36.0f, vec3(0.35f * pn.x, pn.y, pn.z) + 2.0f * q, field_seed(seed, 11));
  float n2 = webanck_g3(8, 0.52f, 2.02f, 96.0f, pn + 8.0f * q, field_seed(seed, 12));
  float n3 = webanck_w3(4, 0.33f, 3.0f, 400.0f, pn + 8.0f * q, field_seed(seed, 13));
  return vec3(n1, n2, n3);
}

// Coverage windows (docs/layers.md, "Coverage windows"): how the weather's coverage c opens the
// forms so that the share c of the sky holds cloud, as the orbit view draws the cover. The paper's
// forms have one coverage each (n2 > 0.55 and alto's fixed window); ours move along a path
// p = 0 (no cloud) .. 2 (every column cloudy), and a table gives the p of each c. A column counts
// as cloudy where its optical depth through the layer reaches 1; the columns' share, not the
// points', is what a view from above sees, and the fields vary with height, so that a window
// covering the share c of the points covers more of the columns (the sheet's 0.1 of the points
// is 0.25 of the columns).

// Piecewise-linear interpolation of 17 values at x = 0, 1/16, .., 1: the first sixteen in
// a[i / 4][i % 4] (mat4's columns), the seventeenth in last. As the sum of the knots' hat
// functions max(0, 1 - |t - i|), t = 16 x: four dot products, no indexing by a variable (which
// made llvmpipe's compile of the marcher ten times slower).
float knots17(mat4 a, float last, float x) {
  float t = clamp(x, 0.0f, 1.0f) * 16.0f;
  vec4 i = vec4(0.0f, 1.0f, 2.0f, 3.0f);
  vec4 one = vec4(1.0f);
  vec4 zero = vec4(0.0f);
  return dot(a[0], max(zero, one - abs(vec4(t) - i))) + dot(a[1], max(zero, one - abs(vec4(t) - i - 4.0f))) +
         dot(a[2], max(zero, one - abs(vec4(t) - i - 8.0f))) + dot(a[3], max(zero, one - abs(vec4(t) - i - 12.0f))) +
         last * max(0.0f, 1.0f - abs(t - 16.0f));
}

// The cumulus's path: p in [0, 1] lowers n2's window from [1, 1.2] (nothing) to [-0.2, 0] (every
// n2), p in [1, 2] then lowers delta's weight from 1 to 0 (k2 n3 alone caps the cover at about
// 0.76 of the columns: merging cumulus erode less), and p in [2, 3] lifts phi by up to 1, above
// the marcher's detail erosion (which leaves densities of 1 and more alone): an unbroken deck.
// Returns (window shift, delta's weight, lift).
vec3 cumulus_window(float p) {
  return vec3(0.55f - 1.2f * clamp(p, 0.0f, 1.0f), 1.0f - clamp(p - 1.0f, 0.0f, 1.0f), clamp(p - 2.0f, 0.0f, 1.0f));
}

// Altocumulus's path: p in [0, 1] lowers n1's window from [1, 1.57] to [0, 0.57] (the paper's
// [0.43, 1] at p = 0.57), p in [1, 2] on to [-0.57, 0] while delta's weight falls to 0.
vec2 altocumulus_window(float p) {
  return vec2(0.57f - clamp(p, 0.0f, 1.0f) - 0.57f * clamp(p - 1.0f, 0.0f, 1.0f), 1.0f - clamp(p - 1.0f, 0.0f, 1.0f));
}

// The tables: p at c = i / 16, by bisection on a Monte Carlo share of 3000 columns of the exact
// fields through the rules' layers (cumulus 1500 m from 1000 m, alto 1500 m from 3500 m;
// tests/test_webanck_coverage.cpp's hidden case [.calibration] prints them), the end knots (c = 0
// and 1) extended from their neighbours. The cumulus's include the marcher's detail erosion of
// its edges (cloud_march.glsl's detail_eroded at the renderer's strength, 0.35), which takes a
// tenth of its cover. The sheet's is the points' coverage for sheet_amount.
const mat4 CUMULUS_WINDOW_KNOTS =
    mat4(0.1662f, 0.2308f, 0.2954f, 0.3620f, 0.4312f, 0.5047f, 0.5802f, 0.6630f,
         0.7428f, 0.8145f, 0.8984f, 1.0021f, 1.2246f, 1.4305f, 1.6854f, 1.9345f);
const mat4 ALTOCUMULUS_WINDOW_KNOTS =
    mat4(0.2690f, 0.3269f, 0.3848f, 0.4367f, 0.4855f, 0.5328f, 0.5870f, 0.6429f,
         0.7020f, 0.7652f, 0.8218f, 0.8867f, 0.9617f, 1.0474f, 1.1330f, 1.2481f);
const mat4 ALTOSTRATUS_COVER_KNOTS =
    mat4(0.0029f, 0.0245f, 0.0461f, 0.0716f, 0.0998f, 0.1311f, 0.1728f, 0.2236f,
         0.2799f, 0.3397f, 0.4071f, 0.4734f, 0.5365f, 0.6132f, 0.6923f, 0.7887f);

const float CUMULUS_WINDOW_LAST = 2.1835f;
const float ALTOCUMULUS_WINDOW_LAST = 1.3632f;
const float ALTOSTRATUS_COVER_LAST = 0.8851f;

// The windows at coverage c; no coverage, no cloud (p = 0).
vec3 cumulus_window_at(float c) {
  return cumulus_window(c > 0.0f ? knots17(CUMULUS_WINDOW_KNOTS, CUMULUS_WINDOW_LAST, c) : 0.0f);
}
vec2 altocumulus_window_at(float c) {
  return altocumulus_window(c > 0.0f ? knots17(ALTOCUMULUS_WINDOW_KNOTS, ALTOCUMULUS_WINDOW_LAST, c) : 0.0f);
}
float altostratus_cover_at(float c) {
  return c > 0.0f ? knots17(ALTOSTRATUS_COVER_KNOTS, ALTOSTRATUS_COVER_LAST, c) : 0.0f;
}

// Cumulus's phi and delta's weight under coverage c at the height fraction h: the tops are rounded
// by raising the window with height (0.25 h; ours, not the paper's).
vec2 cumulus_phi_at(vec4 shape, float c, float h) {
  vec3 w = cumulus_window_at(c);
  return vec2(cumulus_phi(shape.x, shape.y, shape.z, shape.w, w.x + 0.25f * h) + w.z, w.y);
}

// The forms' envelopes over the layer's height fraction h: cumulus flat-based with a thin top
// fade, alto a soft sheet.
float cumulus_gate(float h) { return hermite_step(0.0f, 0.06f, h) * (1.0f - hermite_step(0.95f, 1.0f, h)); }
float alto_gate(float h) { return sheet_profile(h, 0.25f); }

// Alto's phi and delta's weight under coverage c, morph k (1 altostratus .. 0 altocumulus): the
// sheet's part k by sheet_amount (its edges frayed by n1), the cells' part 1 - k through their
// window; both grow with n1, so the two parts share their cloud. (The paper's sheet covers its
// whole domain; gating the product phi by a mix of the two let k (1 - k) of the sky cloud where
// the coverage was nil.)
vec2 alto_phi_at(float k, float c, float n1) {
  vec2 w = altocumulus_window_at(c);
  return vec2(k * sheet_amount(altostratus_cover_at(c), n1) + (1.0f - k) * hermite_step(0.43f + w.x, 1.0f + w.x, n1), w.y);
}

// Densities max(0, phi - delta) from the fields.
float cumulus_form(vec4 shape, vec4 detail, float shift) {
  return max(cumulus_phi(shape.x, shape.y, shape.z, shape.w, shift) -
                 cumulus_delta(detail.x, detail.y, detail.z, detail.w), 0.0f);
}

float alto_form(float k, vec3 n) { return max(alto_phi(k, n.x) - alto_delta(k, n.y, n.z), 0.0f); }

#endif
