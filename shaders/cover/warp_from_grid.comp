#version 450
// Pass 3b of the moving flow (--flow moving) for covers finer than --warp-grid: each texel's
// points of the two cloud layers, interpolated from the back-trajectories that moving_warp.comp's
// WARP_GRID variant traced from the nodes of the warp grid (curl_spline.glsl's warp_grid_sample),
// into the maps the density pass reads, as the full warp pass writes them, and in w the noise
// grid's octaves there (docs/numerics.md, "The noise grid").
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(rgba32f, binding = 1) uniform readonly image2DArray warp_grid;  // prefiltered: older 0-5, younger 6-11
layout(rgba32f, binding = 2) uniform writeonly image2DArray warp_field;
layout(rgba32f, binding = 3) uniform writeonly image2DArray young_warp_field;
#include "../lib/curl_spline.glsl"
#include "cube_tile.glsl"

void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID);
  ivec3 extent = imageSize(warp_field);
  if (texel.x >= extent.x || texel.y >= extent.y) return;
  vec3 x = image_texel_direction(texel);
  imageStore(warp_field, texel, warp_grid_sample(x, warp_grid, 0));
  imageStore(young_warp_field, texel, warp_grid_sample(x, warp_grid, 1));
}
