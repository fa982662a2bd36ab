#version 450
// Resamples CHANNELS one-channel cube maps (the cover and its optical thickness and cloud top,
// say) to a 2:1 equirectangular map: longitude -180 deg at the left edge and 0 at the centre,
// north up. Row directions come from the host, which converts each row's geodetic latitude to
// the geocentric direction (GeographicLib). One tile of the map at a time, its pixels row by
// row with their channels interleaved, as the image files take them, so that the host reads the
// tile straight into the map.
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
#ifndef CHANNELS
#define CHANNELS 1
#endif
layout(r32f, binding = 0) uniform readonly imageCube source_cubes[CHANNELS];
layout(std430, binding = 3) writeonly buffer EquirectTile { float equirect[]; };
uniform ivec2 u_tile_size;
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
  if (pixel.x >= u_tile_size.x || pixel.y >= u_tile_size.y) return;
  vec3 direction = equirect_direction(u_origin_x + pixel.x, u_width, row_cos_sin[u_origin_y + pixel.y]);
  // The maps are of one size: one footprint serves every channel.
  CubeFootprint footprint = cube_footprint(direction, imageSize(source_cubes[0]).x);
  int first = (pixel.y * u_tile_size.x + pixel.x) * CHANNELS;
  for (int c = 0; c < CHANNELS; ++c) equirect[first + c] = sample_cube_footprint(footprint, source_cubes[c]).x;
}
