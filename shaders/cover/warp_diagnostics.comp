#version 450
// The warp's stiffness, folding and sub-step figures as reductions (src/cover/gpu_reductions.cpp).
// Per texel the same differences as cover::flow_rates and cover::folding_report
// (src/cover/stability.cpp, the CPU reference), in double from the float fields:
//   stage 0: each invocation walks a strip of u_strip texels of a column; integer figures
//            (solid-angle units, counts) are summed over the strip and go to atomics, the
//            others to its partial record;
//   stage 1: one workgroup folds the partial records in a fixed order into `totals`.
// Integer atomics commute and the folding order is fixed, so the figures are the same on
// every run.
layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;
layout(rgba32f, binding = 0) uniform readonly image2DArray curl_field;
layout(rgba32f, binding = 1) uniform readonly image2DArray warp_field;
#include "../lib/cube_faces.glsl"
#include "texel_weights.glsl"
#include "cube_tile.glsl"

uniform int u_stage;
uniform int u_strip;
uniform double u_step;   // h
uniform double u_limit;  // the integrator's stable h rho
uniform int u_partials;  // stage 1: records of stage 0

// Words: 0-1 folded units, 2-3 beyond-limit units, 4 capped texels, 5 off-sphere texels,
// 6 largest |attempts| (sortable float).
layout(std430, binding = 1) buffer Counters { uint counters[]; };
const int figures = 6;  // max rho, min J, max J, sum w (J-1)^2, sum w, sum |attempts|
layout(std430, binding = 2) buffer Partials { double partials[]; };
layout(std430, binding = 3) buffer Totals { double totals[]; };

const double none_low = 1.0e300lf;  // identity of min (no texel)
double acc[figures];

// Texels by image position (row j of layer l); directions by face position (face_texel).
dvec3 direction(int layer, int i, int j, int size) {
  ivec3 at = face_texel(ivec3(i, j, layer));
  return dvec3(texel_direction(at.z, at.x, at.y, size));
}
dvec3 curl_at(int layer, int i, int j) { return dvec3(imageLoad(curl_field, ivec3(i, j, layer)).xyz); }
dvec3 warp_at(int layer, int i, int j) { return dvec3(imageLoad(warp_field, ivec3(i, j, layer)).xyz); }

void clear_acc() {
  acc[0] = 0.0lf;
  acc[1] = none_low;
  acc[2] = -none_low;
  for (int f = 3; f < figures; ++f) acc[f] = 0.0lf;
}

// Folds a record into acc (min and max written out so that NaN never wins, as std::min).
void fold(double rho, double jmin, double jmax, double err2, double weight, double attempts) {
  acc[0] = rho > acc[0] ? rho : acc[0];
  acc[1] = jmin < acc[1] ? jmin : acc[1];
  acc[2] = jmax > acc[2] ? jmax : acc[2];
  acc[3] += err2;
  acc[4] += weight;
  acc[5] += attempts;
}

// The neighbours are clamped to the image's rows: a tile's image holds a row of halo beyond each
// edge that is not the face's, so this is the face's clamp (cube_tiles.hpp).
void texel_figures(int layer, int i, int j, int size, int rows, inout uint capped, inout uint off, inout uint most,
                   inout uvec2 folded, inout uvec2 beyond) {
  uint units = texel_weight(i, face_texel(ivec3(i, j, layer)).y, size);
  vec4 w4 = imageLoad(warp_field, ivec3(i, j, layer));
  if (w4.w < 0.0f) capped += 1u;
  most = max(most, sortable_bits(abs(w4.w)));
  double length_w = sqrt(dot(dvec3(w4.xyz), dvec3(w4.xyz)));
  if (!(abs(length_w - 1.0lf) <= 1e-5lf)) off += 1u;
  double attempts = abs(double(w4.w));
  int i0 = max(i - 1, 0), i1 = min(i + 1, size - 1), j0 = max(j - 1, 0), j1 = min(j + 1, rows - 1);
  if (i0 == i1 || j0 == j1) {
    fold(0.0lf, none_low, -none_low, 0.0lf, 0.0lf, attempts);
    return;
  }
  dvec3 n = direction(layer, i, j, size);
  dvec3 e1 = direction(layer, i1, j, size) - direction(layer, i0, j, size);
  dvec3 e2 = direction(layer, i, j1, size) - direction(layer, i, j0, size);
  // Spectral radius of the tangential velocity gradient G = D E^-1 (cover::flow_rates).
  dvec3 d1 = curl_at(layer, i1, j) - curl_at(layer, i0, j);
  dvec3 d2 = curl_at(layer, i, j1) - curl_at(layer, i, j0);
  dvec3 t1 = normalize(e1 - dot(e1, n) * n);
  dvec3 t2 = cross(n, t1);
  double e11 = dot(e1, t1), e12 = dot(e2, t1), e21 = dot(e1, t2), e22 = dot(e2, t2);
  double d11 = dot(d1, t1), d12 = dot(d2, t1), d21 = dot(d1, t2), d22 = dot(d2, t2);
  double det_e = e11 * e22 - e12 * e21;
  double g11 = (d11 * e22 - d12 * e21) / det_e, g12 = (d12 * e11 - d11 * e12) / det_e;
  double g21 = (d21 * e22 - d22 * e21) / det_e, g22 = (d22 * e11 - d21 * e12) / det_e;
  double trace = g11 + g22, det = g11 * g22 - g12 * g21;
  double discriminant = 0.25lf * trace * trace - det;
  double rho = discriminant >= 0.0lf ? 0.5lf * abs(trace) + sqrt(discriminant) : sqrt(det);
  // As stiffness_report: the rate as stored (float) times h against the limit.
  if (u_step * double(float(rho)) > u_limit) beyond = add_units(beyond, units);
  // Area Jacobian of the warp (cover::folding_report).
  double area = dot(cross(e1, e2), n);
  dvec3 w = normalize(dvec3(w4.xyz));
  double warped_area = dot(cross(warp_at(layer, i1, j) - warp_at(layer, i0, j), warp_at(layer, i, j1) - warp_at(layer, i, j0)), w);
  double jacobian = warped_area / area;
  if (!(jacobian > 0.0lf)) folded = add_units(folded, units);
  double weight = double(units);
  fold(rho, jacobian, jacobian, weight * (jacobian - 1.0lf) * (jacobian - 1.0lf), weight, attempts);
}

void main() {
  clear_acc();
  if (u_stage == 1) {
    // One workgroup: invocation k folds records k, k + 64, ... in order; then invocation 0
    // folds the 64 results in order.
    uint local = gl_LocalInvocationIndex;
    for (int p = int(local); p < u_partials; p += 64)
      fold(partials[figures * p], partials[figures * p + 1], partials[figures * p + 2], partials[figures * p + 3],
           partials[figures * p + 4], partials[figures * p + 5]);
    for (int f = 0; f < figures; ++f) partials[figures * (u_partials + int(local)) + f] = acc[f];
    memoryBarrierBuffer();
    barrier();
    if (local == 0u) {
      clear_acc();
      for (int p = u_partials; p < u_partials + 64; ++p)
        fold(partials[figures * p], partials[figures * p + 1], partials[figures * p + 2], partials[figures * p + 3],
             partials[figures * p + 4], partials[figures * p + 5]);
      for (int f = 0; f < figures; ++f) totals[f] = acc[f];
    }
    return;
  }
  int size = u_face_size, rows = imageSize(warp_field).y;
  int strips = (u_tile_rows.y - u_tile_rows.x + u_strip - 1) / u_strip;
  // Strips run down columns, so that neighbouring invocations read neighbouring texels.
  int i = int(gl_GlobalInvocationID.x), s = int(gl_GlobalInvocationID.y), layer = int(gl_GlobalInvocationID.z);
  if (i >= size || s >= strips) return;
  uint capped = 0u, off = 0u, most = 0u;
  uvec2 folded = uvec2(0u), beyond = uvec2(0u);  // the strip's units, added once below
  for (int j = u_tile_rows.x + s * u_strip; j < min(u_tile_rows.y, u_tile_rows.x + (s + 1) * u_strip); ++j)
    texel_figures(layer, i, j, size, rows, capped, off, most, folded, beyond);
  if (folded != uvec2(0u)) ADD_WORDS64(counters, 0, folded);
  if (beyond != uvec2(0u)) ADD_WORDS64(counters, 1, beyond);
  if (capped > 0u) atomicAdd(counters[4], capped);
  if (off > 0u) atomicAdd(counters[5], off);
  atomicMax(counters[6], most);
  int record = (layer * strips + s) * size + i;
  for (int f = 0; f < figures; ++f) partials[figures * record + f] = acc[f];
}
