#version 450
// The tileable noise volume the cloud densities read: R = shape noise (inverted Worley fBm,
// 4 cells per period, 3 octaves), G = detail noise (8 cells per period, 3 octaves), both
// rank-equalised on the host; B = the octave mean of gradient noise behind Webanck's G3 (4 cells
// per period, octaves 0-2 of the 8 of persistence 0.52, lacunarity 2; the host standardises it
// to mean 0 and variance 1 over the volume, so that normal_cdf of it is near uniform as G3), A = W3 (4 cells, 2 octaves of complemented Worley,
// persistence 0.33, lacunarity 3). docs/layers.md states what the bake leaves out.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
layout(rgba32f, binding = 0) uniform writeonly image3D noise_volume;
#include "../lib/worley_fbm.glsl"
#include "../lib/webanck_forms.glsl"

uniform uint u_seed;

void main() {
  ivec3 voxel = ivec3(gl_GlobalInvocationID);
  int size = imageSize(noise_volume).x;
  if (any(greaterThanEqual(voxel, ivec3(size)))) return;
  vec3 p = (vec3(voxel) + 0.5f) / float(size);
  FbmParams shape = FbmParams(4.0f, 3, 2.0f, 0.5f, u_seed, ivec3(4));
  FbmParams detail = noise_volume_detail_fbm(u_seed);
  FbmParams g3 = FbmParams(4.0f, 3, 2.0f, 0.52f, u_seed ^ 0x27d4eb2fu, ivec3(4));
  FbmParams w3 = FbmParams(4.0f, 2, 3.0f, 0.33f, u_seed ^ 0x165667b1u, ivec3(4));
  float g3_mean = perlin_fbm_mean(p, g3);
  imageStore(noise_volume, voxel, vec4(inverted_worley_fbm(p, shape).w, inverted_worley_fbm(p, detail).w, g3_mean,
                                       worley_unit(worley_fbm_mean(p, w3), true)));
}
