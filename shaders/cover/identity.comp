#version 450
// Pass 1: W0(v) = v, the unit direction through each texel centre.
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(rgba32f, binding = 0) uniform writeonly imageCube identity_field;
#include "../lib/cube_faces.glsl"

void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID);
  int size = imageSize(identity_field).x;
  if (texel.x >= size || texel.y >= size) return;
  imageStore(identity_field, texel, vec4(texel_direction(texel.z, texel.x, texel.y, size), 0.0f));
}
