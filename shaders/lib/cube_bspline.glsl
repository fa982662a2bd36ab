// Cubic B-spline filtering of a cube map with four bilinear lookups: the orbit view samples its
// cover with it, so that a cover texel seen from close by has no corners (a bilinear lookup
// has kinks along the texel grid, which the eye reads as a staircase of the texels). The
// B-spline weights of the 4 x 4 texels around a point add up, along each axis, in pairs whose
// ratio a bilinear lookup reproduces when placed between the two texels of a pair (Sigg, C.
// and Hadwiger, M. 2005, "Fast third-order texture filtering", GPU Gems 2, chapter 20). The
// filter is C2-continuous and smooths the cover like a Gaussian of about 0.6 texels' standard
// deviation (the cubic B-spline's variance is 1/3 texel^2); it keeps each texel's mean
// over a uniform area, so coverage statistics stay. The lookups leave the face by up to two
// texels near an edge: their directions run onto the extended face plane, where seamless cube
// filtering reads the neighbour face (docs/orbit_view.md, "Cover filtering").
#ifndef NEPHELE_CUBE_BSPLINE_GLSL
#define NEPHELE_CUBE_BSPLINE_GLSL
#include "prelude.glsl"
#include "cube_faces.glsl"

// The four lookup directions and the weights of the second lookup along s and t: the filtered
// value is mix(mix(L(d00), L(d10), g.x), mix(L(d01), L(d11), g.x), g.y) for bilinear lookups L.
struct CubeBsplineTaps {
  vec3 d00;
  vec3 d10;
  vec3 d01;
  vec3 d11;
  vec2 g;
};

// The cubic B-spline's weights of the texels i - 1, i, i + 1, i + 2 for a point at fraction f
// past texel i's centre.
vec4 bspline_weights(float f) {
  float f2 = f * f, f3 = f2 * f;
  float w0 = (1.0f - 3.0f * f + 3.0f * f2 - f3) / 6.0f;
  float w1 = (4.0f - 6.0f * f2 + 3.0f * f3) / 6.0f;
  float w2 = (1.0f + 3.0f * f + 3.0f * f2 - 3.0f * f3) / 6.0f;
  float w3 = f3 / 6.0f;
  return vec4(w0, w1, w2, w3);
}

// The lookups for direction r on a cube of `size` texels a face edge.
CubeBsplineTaps cube_bspline_taps(vec3 r, float size) {
  int face = cube_face_of(r);
  vec2 st = 0.5f * cube_face_coords(face, r) + 0.5f;
  vec2 x = st * size - 0.5f;  // in texel centres: texel k's centre at k
  vec2 i = floor(x);
  vec2 f = x - i;
  vec4 ws = bspline_weights(f.x), wt = bspline_weights(f.y);
  // Each pair's lookup between its two texels, at the ratio of their weights, in face coordinates.
  vec2 first = i - 1.0f + vec2(ws.y / (ws.x + ws.y), wt.y / (wt.x + wt.y));
  vec2 second = i + 1.0f + vec2(ws.w / (ws.z + ws.w), wt.w / (wt.z + wt.w));
  vec2 c0 = 2.0f * (first + 0.5f) / size - 1.0f;
  vec2 c1 = 2.0f * (second + 0.5f) / size - 1.0f;
  CubeBsplineTaps taps;
  taps.d00 = cube_face_point(face, c0.x, c0.y);
  taps.d10 = cube_face_point(face, c1.x, c0.y);
  taps.d01 = cube_face_point(face, c0.x, c1.y);
  taps.d11 = cube_face_point(face, c1.x, c1.y);
  taps.g = vec2(ws.z + ws.w, wt.z + wt.w);
  return taps;
}

// The filtered value from the bilinear lookups at the four taps.
vec4 cube_bspline_combine(IN(CubeBsplineTaps) taps, vec4 c00, vec4 c10, vec4 c01, vec4 c11) {
  return mix(mix(c00, c10, taps.g.x), mix(c01, c11, taps.g.x), taps.g.y);
}

#endif
