#version 450
// The warp's stiffness, folding and sub-step figures as reductions (src/cover/gpu_reductions.cpp).
// Per texel the same differences as cover::flow_rates and cover::folding_report
// (src/cover/stability.cpp, the CPU reference), in double from the float fields:
//   stage 0: per texel; integer figures (solid-angle units, counts) by atomics, the others
//            per workgroup into `partials` by a fixed tree;
//   stage 1: one workgroup folds the partials in a fixed order into `totals`.
// Integer atomics commute and the trees are fixed, so the figures are the same on every run.
layout(local_size_x = 16, local_size_y = 16, local_size_z = 1) in;
layout(rgba32f, binding = 0) uniform readonly imageCube curl_field;
layout(rgba32f, binding = 1) uniform readonly imageCube warp_field;
#include "../lib/cube_faces.glsl"
#include "texel_weights.glsl"

uniform int u_stage;
uniform double u_step;   // h
uniform double u_limit;  // the integrator's stable h rho
uniform int u_partials;  // stage 1: workgroups of stage 0

// Words: 0-1 folded units, 2-3 beyond-limit units, 4 capped texels, 5 off-sphere texels,
// 6 largest |attempts| (sortable float).
layout(std430, binding = 1) buffer Counters { uint counters[]; };
const int figures = 6;  // max rho, min J, max J, sum w (J-1)^2, sum w, sum |attempts|
layout(std430, binding = 2) buffer Partials { double partials[]; };
layout(std430, binding = 3) buffer Totals { double totals[]; };

shared double group[figures][256];

const double none_low = 1.0e300lf;  // identity of min (no texel)

dvec3 direction(int face, int i, int j, int size) { return dvec3(texel_direction(face, i, j, size)); }
dvec3 curl_at(int face, int i, int j) { return dvec3(imageLoad(curl_field, ivec3(i, j, face)).xyz); }
dvec3 warp_at(int face, int i, int j) { return dvec3(imageLoad(warp_field, ivec3(i, j, face)).xyz); }

void combine(uint a, uint b) {
  group[0][a] = max(group[0][a], group[0][b]);
  group[1][a] = group[1][b] < group[1][a] ? group[1][b] : group[1][a];
  group[2][a] = group[2][b] > group[2][a] ? group[2][b] : group[2][a];
  for (int f = 3; f < figures; ++f) group[f][a] += group[f][b];
}

void reduce_group() {
  uint local = gl_LocalInvocationIndex;
  barrier();
  for (uint half_count = 128u; half_count > 0u; half_count >>= 1) {
    if (local < half_count) combine(local, local + half_count);
    barrier();
  }
}

void texel_figures() {
  uint local = gl_LocalInvocationIndex;
  ivec3 texel = ivec3(gl_GlobalInvocationID);
  int size = imageSize(warp_field).x;
  int face = texel.z, i = texel.x, j = texel.y;
  double rho = 0.0lf, jmin = none_low, jmax = -none_low, err2 = 0.0lf, weight = 0.0lf, attempts = 0.0lf;
  if (i < size && j < size) {
    uint units = texel_weight(i, j, size);
    vec4 w4 = imageLoad(warp_field, texel);
    attempts = abs(double(w4.w));
    if (w4.w < 0.0f) atomicAdd(counters[4], 1u);
    atomicMax(counters[6], sortable_bits(abs(w4.w)));
    double length_w = sqrt(dot(dvec3(w4.xyz), dvec3(w4.xyz)));
    if (!(abs(length_w - 1.0lf) <= 1e-5lf)) atomicAdd(counters[5], 1u);
    int i0 = max(i - 1, 0), i1 = min(i + 1, size - 1), j0 = max(j - 1, 0), j1 = min(j + 1, size - 1);
    if (i0 != i1 && j0 != j1) {
      dvec3 n = direction(face, i, j, size);
      dvec3 e1 = direction(face, i1, j, size) - direction(face, i0, j, size);
      dvec3 e2 = direction(face, i, j1, size) - direction(face, i, j0, size);
      // Spectral radius of the tangential velocity gradient G = D E^-1 (cover::flow_rates).
      dvec3 d1 = curl_at(face, i1, j) - curl_at(face, i0, j);
      dvec3 d2 = curl_at(face, i, j1) - curl_at(face, i, j0);
      dvec3 t1 = normalize(e1 - dot(e1, n) * n);
      dvec3 t2 = cross(n, t1);
      double e11 = dot(e1, t1), e12 = dot(e2, t1), e21 = dot(e1, t2), e22 = dot(e2, t2);
      double d11 = dot(d1, t1), d12 = dot(d2, t1), d21 = dot(d1, t2), d22 = dot(d2, t2);
      double det_e = e11 * e22 - e12 * e21;
      double g11 = (d11 * e22 - d12 * e21) / det_e, g12 = (d12 * e11 - d11 * e12) / det_e;
      double g21 = (d21 * e22 - d22 * e21) / det_e, g22 = (d22 * e11 - d21 * e12) / det_e;
      double trace = g11 + g22, det = g11 * g22 - g12 * g21;
      double discriminant = 0.25lf * trace * trace - det;
      rho = discriminant >= 0.0lf ? 0.5lf * abs(trace) + sqrt(discriminant) : sqrt(det);
      // As stiffness_report: the rate as stored (float) times h against the limit.
      if (u_step * double(float(rho)) > u_limit) ADD_UNITS64(counters, 1, units);
      // Area Jacobian of the warp (cover::folding_report).
      double area = dot(cross(e1, e2), n);
      dvec3 w = normalize(dvec3(w4.xyz));
      double warped_area = dot(cross(warp_at(face, i1, j) - warp_at(face, i0, j), warp_at(face, i, j1) - warp_at(face, i, j0)), w);
      double jacobian = warped_area / area;
      if (!(jacobian > 0.0lf)) ADD_UNITS64(counters, 0, units);
      jmin = jacobian;
      jmax = jacobian;
      weight = double(units);
      err2 = weight * (jacobian - 1.0lf) * (jacobian - 1.0lf);
    }
  }
  group[0][local] = rho;
  group[1][local] = jmin;
  group[2][local] = jmax;
  group[3][local] = err2;
  group[4][local] = weight;
  group[5][local] = attempts;
  reduce_group();
  if (local == 0u) {
    uint index = gl_WorkGroupID.x + gl_NumWorkGroups.x * (gl_WorkGroupID.y + gl_NumWorkGroups.y * gl_WorkGroupID.z);
    for (int f = 0; f < figures; ++f) partials[figures * index + f] = group[f][0];
  }
}

void fold_partials() {
  uint local = gl_LocalInvocationIndex;
  group[0][local] = 0.0lf;
  group[1][local] = none_low;
  group[2][local] = -none_low;
  for (int f = 3; f < figures; ++f) group[f][local] = 0.0lf;
  // Each invocation folds every 256th partial in order, then the tree.
  for (int p = int(local); p < u_partials; p += 256) {
    group[0][local] = max(group[0][local], partials[figures * p]);
    double lo = partials[figures * p + 1], hi = partials[figures * p + 2];
    group[1][local] = lo < group[1][local] ? lo : group[1][local];
    group[2][local] = hi > group[2][local] ? hi : group[2][local];
    for (int f = 3; f < figures; ++f) group[f][local] += partials[figures * p + f];
  }
  reduce_group();
  if (local == 0u)
    for (int f = 0; f < figures; ++f) totals[f] = group[f][0];
}

void main() {
  if (u_stage == 0) texel_figures();
  else fold_partials();
}
