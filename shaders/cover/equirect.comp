#version 450
// Resamples a one-channel cube map to a 2:1 equirectangular map: longitude -180 deg at the
// left edge and 0 at the centre, north up. Row directions come from the host, which converts
// each row's geodetic latitude to the geocentric direction (GeographicLib).
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(r32f, binding = 0) uniform readonly imageCube source_cube;
layout(r32f, binding = 1) uniform writeonly image2D equirect;  // one tile of the map
uniform int u_origin_x;  // the tile's place in the whole map
uniform int u_origin_y;
uniform int u_width;     // the whole map's width
layout(std430, binding = 2) readonly buffer RowDirections {
  vec2 row_cos_sin[];  // (cos, sin) of the geocentric latitude of each row
};

#include "../lib/equirect_mapping.glsl"
#include "../lib/cube_sampling.glsl"

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(equirect);
  if (pixel.x >= size.x || pixel.y >= size.y) return;
  vec3 direction = equirect_direction(u_origin_x + pixel.x, u_width, row_cos_sin[u_origin_y + pixel.y]);
  imageStore(equirect, pixel, vec4(sample_cube_bilinear(direction, source_cube).x, 0.0f, 0.0f, 0.0f));
}
