// The latitude profile's thresholds (src/cover/gpu_reductions.cpp computes them): one per
// band, read at the four band centres around a texel and blended by Catmull-Rom, so that the
// threshold varies smoothly with latitude (no steps at band edges). Used by the remap pass and
// by the reduction that measures each band's achieved fraction.
#include "../lib/latitude_bands.glsl"

layout(std430, binding = 6) readonly buffer BandThresholds { float band_threshold[]; };
uniform int u_bands;  // 0: one threshold for the sphere (--profile flat)

float smooth_band_threshold(vec3 direction) {
  float c = band_coordinate(direction, u_bands);
  ivec4 k = band_neighbours(c, u_bands);
  vec4 values = vec4(band_threshold[k.x], band_threshold[k.y], band_threshold[k.z], band_threshold[k.w]);
  return dot(catmull_rom_weights(band_fraction(c, u_bands)), values);
}
