#version 450
// Pass 2: the curl vector v = n x grad phi at every texel direction n.
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(rgba32f, binding = 0) uniform readonly imageCube identity_field;
layout(rgba32f, binding = 1) uniform writeonly imageCube curl_field;
#include "../lib/curl_flow.glsl"

uniform CurlParams u_curl;
uniform vec3 u_noise_offset;  // reduced modulo the lattice period by the host

void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID);
  int size = imageSize(curl_field).x;
  if (texel.x >= size || texel.y >= size) return;
  vec3 n = imageLoad(identity_field, texel).xyz;
  imageStore(curl_field, texel, vec4(curl_velocity_shifted(n, u_curl, u_noise_offset), 0.0f));
}
