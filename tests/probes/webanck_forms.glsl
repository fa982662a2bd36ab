// Probe of lib/webanck_forms.glsl (shared GLSL/C++ subset; tests/test_library_probes.cpp).
// x[0] = (function, a, b, c), x[1], x[2]: further arguments. The functions (x[0].x):
const int PROBE_NORMAL_CDF = 0;  // normal_cdf(a), octave_mean_sigma(b, c, x[1].x), g3_from_mean(a, b, c)
const int PROBE_WEBANCK_OCTAVES = 1;
const int PROBE_WEBANCK_FIELDS = 2;  // webanck_g3, webanck_w3, field_seed
const int PROBE_WEBANCK_POSITION = 3;
const int PROBE_FORM_PROFILES = 4;  // cumulus_phi, cumulus_delta, alto_phi, alto_delta
const int PROBE_FORMS = 5;  // cumulus_form, alto_form
const int PROBE_CUMULUS_FIELDS_EXACT = 6;
const int PROBE_ALTO_FIELDS_EXACT = 7;
// knots17(x[1..2] as a mat4's first columns, ...) and the windows: x[1] = the first eight knots,
// (cumulus_window(a), altocumulus_window(a)) or, b >= 0.5, (cumulus_phi_at(x[2], c, x[1].x).x,
// alto_phi_at(x[1].y, c, x[1].z).x, cumulus_gate(a) + alto_gate(a), altostratus_cover_at(c) +
// knots17 of x[1], x[2] twice at c)
const int PROBE_COVERAGE_WINDOWS = 8;
#ifndef __cplusplus
#include "../lib/webanck_forms.glsl"
#endif
vec4 probe_webanck_forms(mat4 x) {
  int f = int(x[0].x);
  float a = x[0].y;
  float b = x[0].z;
  float c = x[0].w;
  uint seed = uint(x[2].w);
  if (f == PROBE_NORMAL_CDF)
    return vec4(normal_cdf(a), octave_mean_sigma(int(b), c, x[1].x), g3_from_mean(a, int(b), c), 0.0f);
  if (f == PROBE_WEBANCK_OCTAVES) {
    FbmParams fbm = webanck_octaves(int(a), b, c, x[1].x, seed);
    return vec4(fbm.frequency + float(fbm.period.x), float(fbm.octaves), fbm.lacunarity, fbm.gain + float(fbm.seed));
  }
  if (f == PROBE_WEBANCK_FIELDS)
    return vec4(webanck_g3(int(a), b, c, x[1].w, vec3(x[1]), seed), webanck_w3(int(a), b, c, x[1].w, vec3(x[1]), seed),
                float(field_seed(seed, int(a)) >> 8u), 0.0f);
  if (f == PROBE_WEBANCK_POSITION) return vec4(webanck_position(vec3(x[1]), vec2(x[2])), 0.0f);
  if (f == PROBE_FORM_PROFILES)
    return vec4(cumulus_phi(a, b, c, x[1].x, x[1].y), cumulus_delta(a, b, c, x[1].x), alto_phi(a, b),
                alto_delta(a, b, c));
  if (f == PROBE_FORMS) return vec4(cumulus_form(x[1], x[2], a), alto_form(a, vec3(x[1])), 0.0f, 0.0f);
  if (f == PROBE_CUMULUS_FIELDS_EXACT) {
    vec4 shape;
    vec4 detail;
    cumulus_fields_exact(vec3(x[1]), a, seed, shape, detail);
    return b < 0.5f ? shape : detail;
  }
  if (f == PROBE_COVERAGE_WINDOWS) {
    if (b < 0.5f) return vec4(vec2(cumulus_window(a)) + vec2(cumulus_window(a).z), altocumulus_window(a));
    mat4 knots = mat4(x[1], x[2], x[1], x[2]);
    return vec4(cumulus_phi_at(x[2], c, x[1].x).x + cumulus_window_at(c).x + cumulus_window_at(c).z, alto_phi_at(x[1].y, c, x[1].z).x +
                altocumulus_window_at(c).x, cumulus_gate(a) + alto_gate(a), altostratus_cover_at(c) + knots17(knots, x[3].x, c));
  }
  return vec4(alto_fields_exact(vec3(x[1]), a, seed), 0.0f);  // PROBE_ALTO_FIELDS_EXACT
}
