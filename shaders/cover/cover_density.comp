#version 450
// Pass 4a: cloud density, inverted Worley fBm sampled through the warp, plus the flow's
// cyclonic depth at the texel (the curl field's w) so that cyclones are cloudy.
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(rgba32f, binding = 0) uniform readonly imageCube warp_field;
layout(r32f, binding = 1) uniform writeonly imageCube density_field;
layout(rgba32f, binding = 2) uniform readonly imageCube curl_field;
#include "../lib/cover_density.glsl"

uniform FbmParams u_cover;
uniform vec3 u_noise_offset;  // reduced modulo the lattice period by the host
uniform float u_cyclone_cloudiness;

void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID);
  int size = imageSize(density_field).x;
  if (texel.x >= size || texel.y >= size) return;
  vec3 warped = imageLoad(warp_field, texel).xyz;
  float density = cyclonic_density(cover_density_shifted(warped, u_cover, u_noise_offset),
                                   imageLoad(curl_field, texel).w, u_cyclone_cloudiness);
  imageStore(density_field, texel, vec4(density, 0.0f, 0.0f, 0.0f));
}
