#version 450
// Pass 4b: density to coverage in [0, 1] with the solid-angle-calibrated threshold: one for
// the sphere (u_bands 0), or one that follows the latitude profile (band_thresholds.glsl).
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(r32f, binding = 0) uniform readonly imageCube density_field;
layout(r32f, binding = 1) uniform writeonly imageCube cover_field;
#include "../lib/cover_density.glsl"
#include "../lib/cube_faces.glsl"
#include "band_thresholds.glsl"

uniform float u_threshold;
uniform float u_density_max;

void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID);
  int size = imageSize(cover_field).x;
  if (texel.x >= size || texel.y >= size) return;
  float density = imageLoad(density_field, texel).x;
  float threshold = u_threshold;
  if (u_bands > 0) threshold = smooth_band_threshold(texel_direction(texel.z, texel.x, texel.y, size));
  float cover = cover_from_density(density, threshold, u_density_max);
  imageStore(cover_field, texel, vec4(cover, 0.0f, 0.0f, 0.0f));
}
