#version 450
// Pass 3: K steps along the curl flow, each texel following its own trajectory.
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(rgba32f, binding = 0) uniform readonly imageCube identity_field;
layout(rgba32f, binding = 1) uniform readonly imageCube curl_field;
layout(rgba32f, binding = 2) uniform writeonly imageCube warp_field;

#define CUBE_SOURCE_PARAM
#define CUBE_SOURCE_ARG
#define CUBE_FETCH(face, i, j) imageLoad(curl_field, ivec3(i, j, face))
#define CUBE_SIZE imageSize(curl_field).x
#include "../lib/warp_step.glsl"

uniform int u_steps;
uniform float u_step_size;

void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID);
  int size = imageSize(warp_field).x;
  if (texel.x >= size || texel.y >= size) return;
  vec3 start = imageLoad(identity_field, texel).xyz;
  imageStore(warp_field, texel, vec4(integrate_warp(start, u_steps, u_step_size), 0.0f));
}
