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
  FbmParams fbm;
  fbm.frequency = frequency;
  fbm.octaves = octaves;
  fbm.lacunarity = lacunarity;
  fbm.gain = persistence;
  fbm.seed = seed;
  fbm.period = ivec3(0);
  return fbm;
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

// Densities max(0, phi - delta) from the fields.
float cumulus_form(vec4 shape, vec4 detail, float shift) {
  return max(cumulus_phi(shape.x, shape.y, shape.z, shape.w, shift) -
                 cumulus_delta(detail.x, detail.y, detail.z, detail.w), 0.0f);
}

float alto_form(float k, vec3 n) { return max(alto_phi(k, n.x) - alto_delta(k, n.y, n.z), 0.0f); }

#endif
