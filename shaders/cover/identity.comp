#version 450
// Pass 1: W0(v) = v, the unit direction through each texel centre.
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(rgba32f, binding = 0) uniform writeonly image2DArray identity_field;
#include "../lib/cube_faces.glsl"
#include "cube_tile.glsl"

void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID);
  ivec3 extent = imageSize(identity_field);
  if (texel.x >= extent.x || texel.y >= extent.y) return;
  ivec3 at = face_texel(texel);
  imageStore(identity_field, texel, vec4(texel_direction(at.z, at.x, at.y, u_face_size), 0.0f));
}
