#version 450
// Pass 4a: the coverage threshold's statistics on the GPU (src/cover/gpu_reductions.cpp
// drives the stages; docs/performance.md explains the two-level histogram).
//   stage 0: smallest and largest density (workgroup reduction, then one atomic each);
//   stage 1: solid-angle weighted histogram of 4096 bins over [min, max];
//   stage 2: the same within coarse bin u_coarse, 4096 fine bins;
//   stage 3: the texels of fine bin (u_coarse, u_fine) listed with their weights, and the
//            largest density of fine bins below it.
// Bins are computed in double with the same expression as cover::calibrate_coverage, so a
// texel falls in the same bin on both paths.
layout(local_size_x = 16, local_size_y = 16, local_size_z = 1) in;
layout(r32f, binding = 0) uniform readonly imageCube density_field;
#include "texel_weights.glsl"

const int bins = 4096;
uniform int u_stage;
uniform float u_density_min;
uniform float u_density_max;
uniform int u_coarse;
uniform int u_fine;

// stage 0: words 0, 1 = sortable min, max; stage 3: word 2 = sortable max below, word 3 =
// sortable max inside, word 4 = members found.
layout(std430, binding = 1) buffer Scalars { uint scalars[]; };
layout(std430, binding = 2) buffer Histogram { uint histogram[]; };  // 2 words per bin
layout(std430, binding = 3) buffer Members { uvec2 members[]; };    // (float bits, units)

shared uint group_min[256];
shared uint group_max[256];

int coarse_bin(double u) { return min(bins - 1, int(u)); }

void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID);
  int size = imageSize(density_field).x;
  bool inside = texel.x < size && texel.y < size;
  float density = inside ? imageLoad(density_field, texel).x : 0.0f;
  if (u_stage == 0) {
    uint local = gl_LocalInvocationIndex;
    group_min[local] = inside ? sortable_bits(density) : 0xFFFFFFFFu;
    group_max[local] = inside ? sortable_bits(density) : 0u;
    barrier();
    for (uint half_count = 128u; half_count > 0u; half_count >>= 1) {
      if (local < half_count) {
        group_min[local] = min(group_min[local], group_min[local + half_count]);
        group_max[local] = max(group_max[local], group_max[local + half_count]);
      }
      barrier();
    }
    if (local == 0u) {
      atomicMin(scalars[0], group_min[0]);
      atomicMax(scalars[1], group_max[0]);
    }
    return;
  }
  if (!inside) return;
  double span = double(u_density_max) - double(u_density_min);
  // As on the host: the difference in float, the rest in double.
  precise float offset = density - u_density_min;
  double u = span <= 0.0lf ? 0.0lf : double(offset) / span * double(bins);
  int coarse = span <= 0.0lf ? 0 : coarse_bin(u);
  // Within a coarse bin, u - coarse is exact and scaling by 4096 is exact.
  int fine = span <= 0.0lf ? 0 : min(bins - 1, int((u - double(coarse)) * double(bins)));
  uint units = texel_weight(texel.x, texel.y, size);
  if (u_stage == 1) {
    ADD_UNITS64(histogram, coarse, units);
  } else if (u_stage == 2) {
    if (coarse == u_coarse) ADD_UNITS64(histogram, fine, units);
  } else {
    if (coarse < u_coarse || (coarse == u_coarse && fine < u_fine)) {
      atomicMax(scalars[2], sortable_bits(density));
    } else if (coarse == u_coarse && fine == u_fine) {
      atomicMax(scalars[3], sortable_bits(density));
      uint slot = atomicAdd(scalars[4], 1u);
      if (slot < uint(members.length())) members[slot] = uvec2(floatBitsToUint(density), units);
    }
  }
}
