// Implicit cloud primitives after Montenegro et al. (docs/model.md): the Wyvill-1 field of a
// point or segment skeleton, Lipus's blending operator and Perlin's turbulence, either per
// primitive before blending (their eq. 6) or once after it (eq. 5). The turbulence also erodes
// the field's edge as in Schneider's Nubis (model_erode), which moves the surface into lobes
// (eq. 5 and 6 only scale the field, so its zero contour, the cloud's outline, stays put), and
// the condensation level and the tropopause cut the density flat (model_levels).
#ifndef NEPHELE_IMPLICIT_FIELD_GLSL
#define NEPHELE_IMPLICIT_FIELD_GLSL
#include "prelude.glsl"
#include "perlin.glsl"

// Skeleton kinds.
const int MODEL_POINT = 0;
const int MODEL_SEGMENT = 1;

// Blends: plain sum (eq. 2), Lipus (eq. 3), Lipus then global turbulence (eq. 5), turbulence
// per primitive then Lipus (eq. 6, the paper's method).
const int MODEL_BLEND_SUM = 0;
const int MODEL_BLEND_LIPUS = 1;
const int MODEL_BLEND_GLOBAL = 2;
const int MODEL_BLEND_PER_PRIMITIVE = 3;

// Turbulence parameters, packed in vec4s so that one layout serves std430 buffers and C++.
struct ModelNoise {
  vec4 shape;  // octaves, frequency, amplitude a, gain ga
  vec4 extra;  // lacunarity lc, noise fraction np, seed (an integer below 2^24), erosion e
};

// One primitive: the skeleton (a point, or the segment from a to b), its radius R (field 1
// inside), influence I (the field falls to 0 at distance R + I), weight w and noise.
struct ModelPrimitive {
  vec4 a;      // xyz: the point (or the segment's start); w: radius R
  vec4 b;      // xyz: the segment's end (points: unused); w: influence I
  vec4 kind;   // x: weight w; y: MODEL_POINT or MODEL_SEGMENT; zw: unused
  ModelNoise noise;
};

// Wyvill's soft-object field of the normalised distance x = (d - R) / I: 1 for x <= 0,
// -4/9 x^6 + 17/9 x^4 - 22/9 x^2 + 1 on [0, 1], 0 beyond. Its derivative
// -24/9 x^5 + 68/9 x^3 - 44/9 x is 0 at both ends, so the field is C1 across both edges.
float wyvill1(float x) {
  if (x <= 0.0f) return 1.0f;
  if (x >= 1.0f) return 0.0f;
  float x2 = x * x;
  return ((-4.0f / 9.0f * x2 + 17.0f / 9.0f) * x2 - 22.0f / 9.0f) * x2 + 1.0f;
}

// Distance from p to the segment a..b (a point when a = b).
float segment_distance(vec3 p, vec3 a, vec3 b) {
  vec3 ab = b - a;
  float len2 = dot(ab, ab);
  float t = len2 > 0.0f ? clamp(dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
  return length(p - (a + t * ab));
}

// Distance from p to a primitive's skeleton.
float primitive_distance(vec3 p, IN(ModelPrimitive) prim) {
  if (int(prim.kind.y) == MODEL_SEGMENT) return segment_distance(p, vec3(prim.a), vec3(prim.b));
  return length(p - vec3(prim.a));
}

// g = w b((d - R) / I).
float primitive_field(vec3 p, IN(ModelPrimitive) prim) {
  float x = (primitive_distance(p, prim) - prim.a.w) / prim.b.w;
  return prim.kind.x * wyvill1(x);
}

// The mean of |n| over space for the gradient noise n of perlin.glsl: 0.2201, measured over 4
// million random points (standard error 8e-5; tests/test_model.cpp measures it again). Its RMS is
// PERLIN_OCTAVE_SIGMA = 0.270 (webanck_forms.glsl); a normal variable would have 0.8 x that.
const float PERLIN_MEAN_ABS = 0.2201f;

// Perlin's turbulence N(q) = sum_k a ga^k |n(fr lc^k q)| over the octaves, n the gradient noise
// of perlin.glsl (not periodic), keyed by the seed. Octaves finer than the volume can hold are
// replaced by their mean, PERLIN_MEAN_ABS (so N keeps its mean and the erosion its depth): the
// noise's share is 1 up to max_frequency / 2 cycles per unit of q and 0 from max_frequency on
// (the density pass passes a quarter of its voxels per unit, so no octave is finer than 4
// voxels a cycle; max_frequency <= 0 keeps every octave).
float model_turbulence(vec3 q, IN(ModelNoise) noise, float max_frequency) {
  int octaves = int(noise.shape.x);
  float frequency = noise.shape.y;
  float amplitude = noise.shape.z;
  uvec3 key = uvec3(uint(noise.extra.z), 0x9E3779B9u, 0x85EBCA6Bu);
  float sum = 0.0f;
  for (int k = 0; k < octaves; ++k) {
    float kept = max_frequency > 0.0f ? 1.0f - smoothstep(0.5f * max_frequency, max_frequency, frequency) : 1.0f;
    float value = kept > 0.0f ? abs(perlin_noise(q * frequency, ivec3(0), key)) : 0.0f;
    sum += amplitude * mix(PERLIN_MEAN_ABS, value, kept);
    amplitude *= noise.shape.w;
    frequency *= noise.extra.x;
  }
  return sum;
}

// The noise fraction np of a field value f: (1 - np) f + np f N (eq. 5 on rho, eq. 6 on g_i).
float apply_turbulence(float f, float turbulence, float fraction) {
  return (1.0f - fraction) * f + fraction * f * turbulence;
}

// Erosion of a field value f by the turbulence N (Schneider's remap of the base shape by the
// detail noise): where N is small (the creases between the turbulence's lobes) the field loses
// up to e, where N >= 1 nothing; the rest is stretched back onto [0, 1]:
//   f' = max(0, (f - k) / (1 - k)),  k = e (1 - min(N, 1)).
// The cloud's outline moves inwards by up to e of the field's fall-off, the creases deepest,
// which gives lobes on lobes (cauliflower) where eq. 5 and 6 give a smooth outline; f = 1 stays
// 1, so the core of a cloud is untouched. e = 0 is the identity.
float model_erode(float f, float turbulence, float erosion) {
  float k = erosion * (1.0f - min(turbulence, 1.0f));
  return k < 1.0f ? max(f - k, 0.0f) / (1.0f - k) : 0.0f;
}

// A field value detailed by a turbulence: scaled (eq. 5/6), then eroded.
float model_detail(float f, vec3 q, IN(ModelNoise) noise, float max_frequency) {
  float turbulence = model_turbulence(q, noise, max_frequency);
  return model_erode(apply_turbulence(f, turbulence, noise.extra.y), turbulence, noise.extra.w);
}

// The flat base and top of a cloud: a cumulus's base is the condensation level, the same for
// every updraught of the cloud, and a cumulonimbus's anvil spreads under the tropopause, which
// the updraught cannot pierce (WMO International Cloud Atlas). levels = (base, top) in model
// units of z (a base of 0 and a top of 1 cut nothing); the density rises from 0 to 1 over MODEL_LEVEL_EDGE above the base and falls over
// the same below the top (a cumulus base is sharp to tens of metres; 1 % of the cube keeps the
// step above two voxels at 256^3).
const float MODEL_LEVEL_EDGE = 0.01f;
float model_levels(float z, vec2 levels) {
  float above_base = levels.x > 0.0f ? smoothstep(levels.x, levels.x + MODEL_LEVEL_EDGE, z) : 1.0f;
  float below_top = levels.y < 1.0f ? 1.0f - smoothstep(levels.y - MODEL_LEVEL_EDGE, levels.y, z) : 1.0f;
  return above_base * below_top;
}

// Lipus's operator for equal weights w: rho + g - rho g / w = w (1 - (1 - rho/w)(1 - g/w)),
// symmetric and associative, so the blend of any order is the same, and at most w when
// rho, g <= w.
float lipus_blend(float rho, float g, float w) {
  return rho + g - rho * g / w;
}

// One primitive's contribution folded into rho (rho starts at 0; eq. 2 or eq. 3 with g or g').
// q = p / scale is the point in noise coordinates; max_frequency as model_turbulence's.
float model_accumulate(float rho, vec3 p, vec3 q, IN(ModelPrimitive) prim, int blend, float max_frequency) {
  float g = primitive_field(p, prim);
  if (g <= 0.0f) return rho;  // outside the influence: exactly no change in every blend
  if (blend == MODEL_BLEND_PER_PRIMITIVE) g = model_detail(g, q, prim.noise, max_frequency);
  if (blend == MODEL_BLEND_SUM) return rho + g;
  return lipus_blend(rho, g, prim.kind.x);
}

// The density after all primitives: the global turbulence of eq. 5, the clamp to [0, 1] (the
// paper's pseudocode writes max(rho, 1) where the clamp min(rho, 1) is meant), then the levels
// at the model point's height z.
float model_finish(float rho, float z, vec3 q, int blend, IN(ModelNoise) noise, vec2 levels, float max_frequency) {
  if (blend == MODEL_BLEND_GLOBAL && rho > 0.0f) rho = model_detail(rho, q, noise, max_frequency);
  return clamp(rho, 0.0f, 1.0f) * model_levels(z, levels);
}

#endif
