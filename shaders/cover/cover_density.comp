#version 450
// Pass 4a: cloud density, inverted Worley fBm sampled through the warp, shaped by the flow's
// cyclonic depth at the texel (the curl field's w: cyclones cloudy) and by the land/ocean bias
// (--surface; a zero weight without one).
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(rgba32f, binding = 0) uniform readonly imageCube warp_field;
layout(r32f, binding = 1) uniform writeonly imageCube density_field;
layout(rgba32f, binding = 2) uniform readonly imageCube curl_field;
layout(binding = 3) uniform sampler2D surface_bias;  // equirect, row 0 north, longitude -180 at s = 0
#include "../lib/cover_density.glsl"
#include "../lib/cube_faces.glsl"
#include "../lib/equirect_mapping.glsl"

uniform FbmParams u_cover;
uniform vec3 u_noise_offset;  // reduced modulo the lattice period by the host
uniform float u_cyclone_cloudiness;
uniform float u_surface_weight;

void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID);
  int size = imageSize(density_field).x;
  if (texel.x >= size || texel.y >= size) return;
  vec3 warped = imageLoad(warp_field, texel).xyz;
  float surface = 0.0f;
  if (u_surface_weight > 0.0f) {
    surface = texture(surface_bias, equirect_uv(texel_direction(texel.z, texel.x, texel.y, size))).x;
  }
  float density = shaped_density(cover_density_shifted(warped, u_cover, u_noise_offset), imageLoad(curl_field, texel).w,
                                 u_cyclone_cloudiness, surface, u_surface_weight);
  imageStore(density_field, texel, vec4(density, 0.0f, 0.0f, 0.0f));
}
