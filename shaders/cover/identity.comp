#version 450
// Pass 1: W0(v) = v, the unit direction through each texel centre: the start points of the steady
// flow's warp (and of the tests' comparisons); the other passes compute the direction themselves.
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(rgba32f, binding = 0) uniform writeonly image2DArray identity_field;
#include "cube_tile.glsl"

void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID);
  ivec3 extent = imageSize(identity_field);
  if (texel.x >= extent.x || texel.y >= extent.y) return;
  imageStore(identity_field, texel, vec4(image_texel_direction(texel), 0.0f));
}
