#version 450
// The calibration between passes 4a and 4b (docs/algorithm.md): the coverage threshold's
// statistics on the GPU (src/cover/gpu_reductions.cpp drives the stages; docs/performance.md
// explains the two-level histogram).
//   stage 0: smallest and largest density;
//   stage 1: solid-angle weighted histogram of 4096 bins over [min, max];
//   stage 2: the texels of coarse bin u_coarse listed with their weights;
//   stage 3: the histogram of 4096 fine bins within coarse bin u_coarse;
//   stage 4: the texels of fine bin (u_coarse, u_fine) listed;
//   stage 5: the largest density of the bins below (u_coarse, u_fine).
// The latitude profile (docs/climate.md) has its own stages, per latitude band:
//   stage 6: a histogram of band_bins bins over [min, max] per band;
//   stage 7: per band, band_bins fine bins within that band's crossing bin (band_crossing);
//   stage 8: each band's cloudy weight at the smooth threshold of the remap pass.
// Each invocation walks a strip of u_strip texels of a column and adds runs of one bin at once,
// so that few atomics are needed.
layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;
layout(r32f, binding = 0) uniform readonly image2DArray density_field;
#include "texel_weights.glsl"
#include "../lib/cube_faces.glsl"
#include "band_thresholds.glsl"
#include "cube_tile.glsl"

const int bins = 4096;
uniform int u_stage;
uniform int u_strip;
uniform float u_density_min;
uniform float u_scale;       // bins / (max - min)
uniform float u_coarse_low;  // lower edge of coarse bin u_coarse
uniform float u_fine_scale;  // bins / (width of a coarse bin)
uniform int u_coarse;
uniform int u_fine;

// Words: 0, 1 = sortable min, max (stage 0); 2 = sortable max below (stage 5); 3 = sortable
// max of the listed texels, 4 = texels found (stages 2, 4).
layout(std430, binding = 1) buffer Scalars { uint scalars[]; };
layout(std430, binding = 2) buffer Histogram { uint histogram[]; };  // 2 words per bin
layout(std430, binding = 3) buffer Members { uvec2 members[]; };    // (float bits, units)
// Per band: its crossing coarse bin and that bin's lower edge (float bits), from the host.
layout(std430, binding = 7) readonly buffer BandCrossing { uvec2 band_crossing[]; };
const int band_bins = 256;
uniform float u_band_scale;  // band_bins / (max - min)

// Coarse and fine bin of a density. Any binning that never puts a larger density in a lower
// bin finds the same cut (the cut nearest the target lies in the bin where the cumulative
// fraction crosses it), and float rounding is monotone: (d - min) * scale never decreases
// with d. The host gives scale 0 when all densities are equal.
ivec2 bins_of(float density) {
  int coarse = min(bins - 1, int((density - u_density_min) * u_scale));
  int fine = clamp(int((density - u_coarse_low) * u_fine_scale), 0, bins - 1);
  return ivec2(coarse, fine);
}

void list_member(float density, uint units) {
  atomicMax(scalars[3], sortable_bits(density));
  uint slot = atomicAdd(scalars[4], 1u);
  if (slot < uint(members.length())) members[slot] = uvec2(floatBitsToUint(density), units);
}

void main() {
  int size = u_face_size;
  // Strips run down columns, so that neighbouring invocations read neighbouring texels.
  int i = int(gl_GlobalInvocationID.x), layer = int(gl_GlobalInvocationID.z);
  int first = u_tile_rows.x + int(gl_GlobalInvocationID.y) * u_strip;
  if (i >= size || first >= u_tile_rows.y) return;
  int last = min(u_tile_rows.y, first + u_strip);
  uint low = 0xFFFFFFFFu, high = 0u;
  int run_bin = -1;
  uint run_units = 0u;
  for (int j = first; j < last; ++j) {
    float density = imageLoad(density_field, ivec3(i, j, layer)).x;
    ivec3 at = face_texel(ivec3(i, j, layer));
    if (u_stage == 0) {
      low = min(low, sortable_bits(density));
      high = max(high, sortable_bits(density));
      continue;
    }
    // The histogram slot a texel adds its weight to (stages 1, 3, 6, 7, 8; -1: none).
    int slot = -1;
    if (u_stage >= 6) {
      // The band of the texel's centre, as the CPU reference (coverage_threshold.cpp).
      vec3 direction = texel_direction(at.z, at.x, at.y, size);
      int band = band_of(band_coordinate(direction, u_bands), u_bands);
      int coarse = min(band_bins - 1, int((density - u_density_min) * u_band_scale));
      if (u_stage == 6) {
        slot = band * band_bins + coarse;
      } else if (u_stage == 7) {
        if (coarse == int(band_crossing[band].x)) {
          float band_low = uintBitsToFloat(band_crossing[band].y);
          slot = band * band_bins +
                 clamp(int((density - band_low) * (u_band_scale * float(band_bins))), 0, band_bins - 1);
        }
      } else if (density > smooth_band_threshold(direction)) {
        slot = band;
      }
    } else {
      ivec2 b = bins_of(density);
      if (u_stage == 5) {
        if (b.x < u_coarse || (b.x == u_coarse && b.y < u_fine)) high = max(high, sortable_bits(density));
        continue;
      }
      if (u_stage == 1) slot = b.x;
      if (u_stage == 3 && b.x == u_coarse) slot = b.y;
      if (u_stage == 2 && b.x == u_coarse) list_member(density, texel_weight(at.x, at.y, size));
      if (u_stage == 4 && b.x == u_coarse && b.y == u_fine) list_member(density, texel_weight(at.x, at.y, size));
    }
    if (slot < 0) continue;
    // A run is flushed once it reaches 2^31 units; a texel is below 2^31, so the 32-bit run
    // sum never wraps.
    if (slot != run_bin || run_units >= 0x80000000u) {
      if (run_bin >= 0) ADD_UNITS64(histogram, run_bin, run_units);
      run_bin = slot;
      run_units = 0u;
    }
    run_units += texel_weight(at.x, at.y, size);
  }
  if (u_stage == 0) {
    atomicMin(scalars[0], low);
    atomicMax(scalars[1], high);
  } else if (u_stage == 5) {
    if (high != 0u) atomicMax(scalars[2], high);
  } else if (run_bin >= 0) {
    ADD_UNITS64(histogram, run_bin, run_units);
  }
}
