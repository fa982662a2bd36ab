// The warp's velocity as a cubic B-spline of the curl sampled on a grid per cube face
// (`curl_mode spline`; docs/numerics.md, "The spline velocity"). The grid of face f has `cells`
// nodes per face edge at the texel centres of a cells^2 face, continued past the face's edges
// by SPLINE_MARGIN nodes on each side: the gnomonic face coordinates (sc, tc) simply extend
// beyond [-1, 1], and normalize(cube_face_point(f, sc, tc)) there is an ordinary direction,
// so the margin holds more curl evaluations, not copies of neighbouring faces. A point of the
// face then has all 4 x 4 nodes of its spline on its own face's grid, and the spline is C2
// everywhere inside each face. Across a face edge the two faces' splines differ only by their
// approximation errors.
//
// The spline is the quasi-interpolant: its coefficients are the samples prefiltered by
// (-1, 8, -1)/6 along each axis (prefilter_cubic_bspline), which makes it reproduce cubic
// polynomials, so it approximates the field to O(h^4) instead of the O(h^2) of the plain
// B-spline with the samples as coefficients. The prefilter reads one more sample beyond each
// node, so the samples have a margin of SPLINE_MARGIN + 1.
//
// The coefficient grid is a SplineImage parameter (prelude.glsl; in C++ a SplineSource): layer
// `face`, (cells + 2 SPLINE_MARGIN)^2 coefficients, index i being node i - SPLINE_MARGIN, where
// cells is the `curl_size` parameter (nodes per face edge inside the face).
#ifndef NEPHELE_CURL_SPLINE_GLSL
#define NEPHELE_CURL_SPLINE_GLSL
#include "prelude.glsl"
#include "cube_faces.glsl"

// Nodes beyond each face edge: a cubic B-spline reads the nodes floor(x) - 1 .. floor(x) + 2,
// and x reaches -0.5 and cells - 0.5 on the face's edges.
const int SPLINE_MARGIN = 2;

// The direction of the node at array index (i, j) of `face`'s grid, whose arrays begin `margin`
// nodes before the face's edge: the texel centre (i - margin, j - margin) of a cells^2 face,
// continued beyond the edges along the face's plane (shaders/cover/curl_spline.comp samples the
// curl there with margin SPLINE_MARGIN + 1).
vec3 curl_spline_node(int face, int i, int j, int margin, int cells) {
  return texel_direction(face, i - margin, j - margin, cells);
}

// The four uniform cubic B-spline weights of the nodes floor(x) - 1 .. floor(x) + 2 at the
// fraction t = x - floor(x) (C. de Boor, "A Practical Guide to Splines", 2001, chapter IX).
// They are positive and sum to 1.
vec4 cubic_bspline_weights(float t) {
  float s = 1.0f - t;
  float t2 = t * t;
  float t3 = t2 * t;
  return vec4(s * s * s, 4.0f - 6.0f * t2 + 3.0f * t3, 1.0f + 3.0f * (t + t2 - t3), t3) * (1.0f / 6.0f);
}

// The quasi-interpolating prefilter of the cubic B-spline along one axis: the coefficient of a
// node from the samples at it and its two neighbours, c = f - (f'' h^2)/6 with f'' by the
// central difference. A B-spline with coefficients c_i = p(i) reproduces p + p''/6 for cubic p
// (its weights have variance 1/3 and no third moment), so this c reproduces cubics exactly.
vec4 prefilter_cubic_bspline(vec4 previous, vec4 centre, vec4 next) {
  return (8.0f * centre - previous - next) * (1.0f / 6.0f);
}

// One row of the 4 x 4 coefficients, weighted along x: coefficients (i .. i + 3, j) of layer
// `layer` (the face, plus 6 per time node of the moving flow).
vec4 curl_spline_row(int layer, int i, int j, vec4 wx, SplineImage spline) {
  return wx.x * imageLoad(spline, ivec3(i, j, layer)) + wx.y * imageLoad(spline, ivec3(i + 1, j, layer)) +
         wx.z * imageLoad(spline, ivec3(i + 2, j, layer)) + wx.w * imageLoad(spline, ivec3(i + 3, j, layer));
}

// The spline of the curl grid at the unit direction w (xyz; w: the cyclonic depth, which the
// grid carries along, curl_flow.glsl): a sum of 16 coefficients of w's face,
// written without a loop (llvmpipe counts every loop iteration against a per-invocation limit;
// docs/numerics.md, "llvmpipe's loop limit").
// The grid of time node `node` is layers 6 node .. 6 node + 5 (the moving flow's; 0 otherwise).
vec4 sample_curl_spline_node(vec3 w, SplineImage spline, int node) {
  int cells = imageSize(spline).x - 2 * SPLINE_MARGIN;
  int face = cube_face_of(w);
  int layer = face + 6 * node;
  vec2 st = 0.5f * cube_face_coords(face, w) + 0.5f;
  float x = st.x * float(cells) - 0.5f;
  float y = st.y * float(cells) - 0.5f;
  // A driver's division may put |sc| an ulp above 1; the nodes stay within the margin.
  float x0 = clamp(floor(x), -1.0f, float(cells - 1));
  float y0 = clamp(floor(y), -1.0f, float(cells - 1));
  vec4 wx = cubic_bspline_weights(x - x0);
  vec4 wy = cubic_bspline_weights(y - y0);
  int i = int(x0) - 1 + SPLINE_MARGIN;
  int j = int(y0) - 1 + SPLINE_MARGIN;
  vec4 sum = wy.x * curl_spline_row(layer, i, j, wx, spline) +
             wy.y * curl_spline_row(layer, i, j + 1, wx, spline) +
             wy.z * curl_spline_row(layer, i, j + 2, wx, spline) +
             wy.w * curl_spline_row(layer, i, j + 3, wx, spline);
  return sum;
}

vec4 sample_curl_spline(vec3 w, SplineImage spline) {
  return sample_curl_spline_node(w, spline, 0);
}

// The moving flow's warp grid (--warp-grid; shaders/cover/moving_warp.comp's WARP_GRID variant):
// the back-trajectories' ends from the nodes of a grid as the curl's, prefiltered as its samples,
// for the older layer in layers 0-5 (`layer` 0) and the younger's in 6-11 (1). A texel's end is
// their spline at its direction x, renormalised onto the sphere: the quasi-interpolant errs by
// O(h^4) as the curl's spline does (docs/numerics.md, 8b, "The warp grid"). Its w, not
// renormalised, is the spline of the nodes' w: the noise grid's octaves (moving_warp.comp).
vec4 warp_grid_sample(vec3 x, SplineImage grid, int layer) {
  vec4 s = sample_curl_spline_node(x, grid, layer);
  return vec4(normalize(vec3(s)), s.w);
}

// The warp's velocity: the spline's value projected onto the tangent plane at w. The spline
// approximates the curl, which is tangent at w, so its normal part is no larger than its error
// (O(h^4)); the projection removes that part, as the procedural curl has none, and cannot
// increase the error (it is an orthogonal projection and the exact value is in its range).
vec3 spline_velocity(vec3 w, SplineImage spline) {
  vec3 v = vec3(sample_curl_spline(w, spline));
  return v - dot(v, w) * w;
}

// Node `node`'s spline where the drift has carried its pattern after `angle` radians about the
// axis: the moving flow's vortices drift east as a rotation R(-omega(z) t) of their potential
// (moving_flow.glsl's drifted_potential, the same for every generation, and the zonal term is
// symmetric about the axis), so the flow dt after a node is the node's turned by omega dt:
// sampled at R(-angle) w and its vector turned back by R(angle). Exact for a rigid rotation;
// the shear of omega(z) errs by O(dt), with opposite signs at the two nodes around a time, which
// the linear mix below cancels to first order.
vec4 sample_curl_spline_node_turned(vec3 w, SplineImage spline, int node, float angle) {
  float c = cos(angle);
  float s = sin(angle);
  vec4 v = sample_curl_spline_node(vec3(c * w.x + s * w.y, c * w.y - s * w.x, w.z), spline, node);
  return vec4(c * v.x - s * v.y, s * v.x + c * v.y, v.z, v.w);
}

// The moving flow between time nodes (docs/algorithm.md, "The moving flow"): the splines of the
// nodes floor(node) and floor(node) + 1 (clamped to the grid's nodes), each turned with the
// drift to the time (`turn`: the drift's angle per node spacing at w's latitude, 0 for none),
// mixed linearly in time (the cyclonic depth in w too); spline_velocity_in_time projects it as
// spline_velocity. What is left is the change of the pattern itself (the generations' shares)
// and the drift's shear (docs/numerics.md, 8b).
vec4 sample_curl_spline_in_time(vec3 w, SplineImage spline, float node, float turn) {
  int last = imageSize(spline).z / 6 - 1;
  float first = clamp(floor(node), 0.0f, float(max(last - 1, 0)));
  float f = clamp(node - first, 0.0f, 1.0f);
  int k = int(first);
  int next = min(k + 1, last);
  return (1.0f - f) * sample_curl_spline_node_turned(w, spline, k, turn * (node - first)) +
         f * sample_curl_spline_node_turned(w, spline, next, turn * (node - float(next)));
}

vec3 spline_velocity_in_time(vec3 w, SplineImage spline, float node, float turn) {
  vec3 v = vec3(sample_curl_spline_in_time(w, spline, node, turn));
  return v - dot(v, w) * w;
}

// The spline as the source of the warp's stepping rules (warp_step.glsl).
vec3 warp_velocity(vec3 w, SplineImage spline) { return spline_velocity(w, spline); }

#endif
