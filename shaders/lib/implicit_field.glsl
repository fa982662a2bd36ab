// Implicit cloud primitives after Montenegro et al. (docs/model.md): the Wyvill-1 field of a
// point or segment skeleton, Lipus's blending operator and Perlin's turbulence, either per
// primitive before blending (their eq. 6) or once after it (eq. 5).
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
  vec4 extra;  // lacunarity lc, noise fraction np, seed (an integer below 2^24), unused
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

// Perlin's turbulence N(q) = sum_k a ga^k |n(fr lc^k q)| over the octaves, n the gradient noise
// of perlin.glsl (not periodic), keyed by the seed.
float model_turbulence(vec3 q, IN(ModelNoise) noise) {
  int octaves = int(noise.shape.x);
  float frequency = noise.shape.y;
  float amplitude = noise.shape.z;
  uvec3 key = uvec3(uint(noise.extra.z), 0x9E3779B9u, 0x85EBCA6Bu);
  float sum = 0.0f;
  for (int k = 0; k < octaves; ++k) {
    sum += amplitude * abs(perlin_noise(q * frequency, ivec3(0), key));
    amplitude *= noise.shape.w;
    frequency *= noise.extra.x;
  }
  return sum;
}

// The noise fraction np of a field value f: (1 - np) f + np f N (eq. 5 on rho, eq. 6 on g_i).
float apply_turbulence(float f, float turbulence, float fraction) {
  return (1.0f - fraction) * f + fraction * f * turbulence;
}

// Lipus's operator for equal weights w: rho + g - rho g / w = w (1 - (1 - rho/w)(1 - g/w)),
// symmetric and associative, so the blend of any order is the same, and at most w when
// rho, g <= w.
float lipus_blend(float rho, float g, float w) {
  return rho + g - rho * g / w;
}

// One primitive's contribution folded into rho (rho starts at 0; eq. 2 or eq. 3 with g or g').
// q = p / scale is the point in noise coordinates.
float model_accumulate(float rho, vec3 p, vec3 q, IN(ModelPrimitive) prim, int blend) {
  float g = primitive_field(p, prim);
  if (g <= 0.0f) return rho;  // outside the influence: exactly no change in every blend
  if (blend == MODEL_BLEND_PER_PRIMITIVE)
    g = apply_turbulence(g, model_turbulence(q, prim.noise), prim.noise.extra.y);
  if (blend == MODEL_BLEND_SUM) return rho + g;
  return lipus_blend(rho, g, prim.kind.x);
}

// The density after all primitives: the global turbulence of eq. 5, then the clamp to [0, 1]
// (the paper's pseudocode writes max(rho, 1) where the clamp min(rho, 1) is meant).
float model_finish(float rho, vec3 q, int blend, IN(ModelNoise) noise) {
  if (blend == MODEL_BLEND_GLOBAL && rho > 0.0f)
    rho = apply_turbulence(rho, model_turbulence(q, noise), noise.extra.y);
  return clamp(rho, 0.0f, 1.0f);
}

#endif
