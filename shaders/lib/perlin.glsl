// 3D gradient noise after Perlin, "Improving Noise", SIGGRAPH 2002: quintic fade, gradients
// from the 12 cube edge directions, here hashed with pcg3d on a (optionally) periodic lattice.
#ifndef NEPHELE_PERLIN_GLSL
#define NEPHELE_PERLIN_GLSL
#include "prelude.glsl"
#include "hash.glsl"
#include "worley.glsl"

// |perlin_noise| stays below this. The supremum over all gradient choices is
// max over f in [0,1]^3 of sum_c w_c(f) max_g g.(f - c) = 1.0363538 (reached near
// f = (0.355, 0.5, 0.481) when every corner's gradient points its way; found by dense search
// and local refinement, docs/noise.md); the bound leaves room for float rounding.
const float PERLIN_BOUND = 1.03636f;

// Standard deviation of one octave of perlin_noise over a uniformly distributed point:
// Var = (2/3) E[sum_c w_c^2 |f - c|^2] (each gradient of the 12 has E[g g^T] = (2/3) I and the
// corners' gradients are independent) = 2 A B^2 with B = int_0^1 (1 - F)^2 + F^2 = 181/231 and
// A = int_0^1 (1 - F)^2 t^2 + F^2 (1 - t)^2 = 535/9009 for the quintic fade F:
// Var = 35054270/480729249 (docs/layers.md).
const float PERLIN_OCTAVE_SIGMA = 0.27003508f;

// Standard deviation of one component of one octave's gradient (per lattice unit) over a
// uniformly distributed point: d/dx of sum_c w_c g_c.(f - c) is sum_c (dw_c/dx g_c.(f - c) + w_c g_cx),
// whose variance, with the corners' gradients independent and E[g g^T] = (2/3) I, integrates the
// quintic fade's polynomials exactly to 238536280/480729249 (the same denominator as above).
const float PERLIN_GRADIENT_SIGMA = 0.70441233f;

// Perlin's quintic 6t^5 - 15t^4 + 10t^3: C2 across lattice planes.
float perlin_fade(float t) {
  return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f);
}

// The gradient at an (already wrapped) lattice point: one of (+-1, +-1, 0), (+-1, 0, +-1),
// (0, +-1, +-1), picked by the top 24 bits of the hash scaled to 0..11 (uniform up to 2^-24).
vec3 perlin_gradient(ivec3 lattice, uvec3 key) {
  uint h = pcg3d(uvec3(lattice) ^ key).x;
  uint index = ((h >> 8u) * 12u) >> 24u;
  float s0 = (index & 1u) != 0u ? -1.0f : 1.0f;
  float s1 = (index & 2u) != 0u ? -1.0f : 1.0f;
  uint pair = index >> 2u;
  if (pair == 0u) return vec3(s0, s1, 0.0f);
  if (pair == 1u) return vec3(s0, 0.0f, s1);
  return vec3(0.0f, s0, s1);
}

// Bilinear weights (w00, w10, w01, w11) of the faded offsets fy, fz; first index y.
vec4 perlin_yz_weights(float fy, float fz) {
  float wy = perlin_fade(fy);
  float wz = perlin_fade(fz);
  return vec4((1.0f - wy) * (1.0f - wz), wy * (1.0f - wz), (1.0f - wy) * wz, wy * wz);
}

// Along a line of constant (fy, fz) through a lattice cell, the y and z interpolation of the
// four corners of the face at lattice x is A + B (fx - ox) (ox = 0 or 1, the face's offset).
// Returns vec2(A, B) for the wrapped face x, wrapped rows ys = (y0, y1), zs = (z0, z1).
vec2 perlin_face(int x, ivec2 ys, ivec2 zs, float fy, float fz, vec4 w, uvec3 key) {
  vec3 g00 = perlin_gradient(ivec3(x, ys.x, zs.x), key);
  vec3 g10 = perlin_gradient(ivec3(x, ys.y, zs.x), key);
  vec3 g01 = perlin_gradient(ivec3(x, ys.x, zs.y), key);
  vec3 g11 = perlin_gradient(ivec3(x, ys.y, zs.y), key);
  float a = w.x * (g00.y * fy + g00.z * fz) + w.y * (g10.y * (fy - 1.0f) + g10.z * fz) +
            w.z * (g01.y * fy + g01.z * (fz - 1.0f)) + w.w * (g11.y * (fy - 1.0f) + g11.z * (fz - 1.0f));
  float b = w.x * g00.x + w.y * g10.x + w.z * g01.x + w.w * g11.x;
  return vec2(a, b);
}

// The x interpolation between the faces at ox = 0 and ox = 1 with the faded fx.
float perlin_along_row(vec2 face0, vec2 face1, float fx) {
  float n0 = face0.x + face0.y * fx;
  float n1 = face1.x + face1.y * (fx - 1.0f);
  return n0 + perlin_fade(fx) * (n1 - n0);
}

// Gradient noise at p in lattice units: sum over the 8 corners c of the cell of
// fade weights times g_c.(p - c), in [-PERLIN_BOUND, PERLIN_BOUND]; 0 on every lattice point.
// Periodic with `period` lattice cells per axis (0: not periodic on that axis). Factored
// per x face (perlin_face) so that the row walk in noise_rows.glsl computes the same floats.
float perlin_noise(vec3 p, ivec3 period, uvec3 key) {
  vec3 base = floor(p);
  vec3 f = p - base;
  ivec3 cell = wrap_cell(ivec3(base), period);
  ivec2 ys = ivec2(cell.y, wrap_step(cell.y, 1, period.y));
  ivec2 zs = ivec2(cell.z, wrap_step(cell.z, 1, period.z));
  vec4 w = perlin_yz_weights(f.y, f.z);
  vec2 face0 = perlin_face(cell.x, ys, zs, f.y, f.z, w, key);
  vec2 face1 = perlin_face(wrap_step(cell.x, 1, period.x), ys, zs, f.y, f.z, w, key);
  return perlin_along_row(face0, face1, f.x);
}

// perlin_noise (not periodic) with its gradient in lattice units: (d/dx, d/dy, d/dz, value). The
// gradient of sum_c w_c(f) g_c.(f - c) is sum_c (grad w_c) g_c.(f - c) + w_c g_c, each w_c a product
// of the fade (far corner) or one less it (near corner) along the axes, the fade's derivative
// 30 t^2 (t - 1)^2. One pass over the corners, where differences would take three more noises.
vec4 perlin_noise_gradient(vec3 p, uvec3 key) {
  vec3 base = floor(p);
  vec3 f = p - base;
  ivec3 cell = ivec3(base);
  vec3 fade = vec3(perlin_fade(f.x), perlin_fade(f.y), perlin_fade(f.z));
  vec3 fade_slope = 30.0f * f * f * (f - 1.0f) * (f - 1.0f);
  vec4 result = vec4(0.0f);
  for (int k = 0; k < 8; ++k) {
    ivec3 corner = ivec3(k & 1, (k >> 1) & 1, k >> 2);
    vec3 far = vec3(corner);
    vec3 g = perlin_gradient(cell + corner, key);
    float along = dot(g, f - far);
    vec3 a = mix(vec3(1.0f) - fade, fade, far);
    vec3 da = mix(-fade_slope, fade_slope, far);
    float weight = a.x * a.y * a.z;
    result += vec4(vec3(da.x * a.y * a.z, a.x * da.y * a.z, a.x * a.y * da.z) * along + weight * g, weight * along);
  }
  return result;
}

#endif
