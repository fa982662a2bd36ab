#version 450
// The tileable noise volume the cloud densities read: R = shape noise (inverted Worley fBm,
// 4 cells per period, 3 octaves), G = detail noise (8 cells per period, 3 octaves).
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
layout(rg32f, binding = 0) uniform writeonly image3D noise_volume;
#include "../lib/worley_fbm.glsl"

uniform uint u_seed;

void main() {
  ivec3 voxel = ivec3(gl_GlobalInvocationID);
  int size = imageSize(noise_volume).x;
  if (any(greaterThanEqual(voxel, ivec3(size)))) return;
  vec3 p = (vec3(voxel) + 0.5f) / float(size);
  FbmParams shape = FbmParams(4.0f, 3, 2.0f, 0.5f, u_seed, ivec3(4));
  FbmParams detail = FbmParams(8.0f, 3, 2.0f, 0.5f, u_seed ^ 0x5bd1e995u, ivec3(8));
  imageStore(noise_volume, voxel, vec4(inverted_worley_fbm(p, shape).w, inverted_worley_fbm(p, detail).w, 0.0f, 0.0f));
}
