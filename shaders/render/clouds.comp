#version 450
// The ray marching pass: one invocation per pixel through the marcher of
// shaders/lib/cloud_march.glsl, whose C++ twin is src/shader_math (tests/test_cloud_march.cpp
// compares the two).
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(rgba32f, binding = 0) uniform writeonly image2D radiance_image;
// Where each pixel's view ray meets the ground (m; -1: the sky), the guide of the upsampling of
// a render at reduced resolution (render/upsample.hpp).
layout(r32f, binding = 1) uniform writeonly image2D ground_distance_image;
// Pixels whose loops ran (or would have run) past LOOP_LIMIT iterations in all (cut short on
// llvmpipe, docs/rendering.md): their count, and one bit per pixel (pixel y width + x is bit
// k % 32 of word k / 32). The host reads both; studies leave those pixels out of a reference.
layout(std430, binding = 3) buffer LoopGuard {
  uint loop_limited_pixels;
  uint loop_limited_bits[];
};

#include "march_sources.glsl"

uniform MarchParams u_march;
// The first row of the band being marched (RenderSettings::first_row; 0 for a whole image).
uniform int u_first_row;
// The march lattice (RenderSettings::march_stride, march_phase): invocation (i, j) marches pixel
// (i s + phase.x, j s + phase.y); stride 1, phase 0: every pixel.
uniform int u_stride;
uniform ivec2 u_phase;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy) * u_stride + u_phase + ivec2(0, u_first_row);
  ivec2 size = imageSize(radiance_image);
  if (pixel.x >= size.x || pixel.y >= size.y) return;
  int loop_count = 0;
  float ground_distance = 0.0f;
  vec4 radiance = render_pixel(pixel, size, u_march, loop_count, ground_distance, noise_volume, weather_field,
                               terrain_heights, land_cover, convective_volumes, layer_shadows, sky_shadow);
  if (loop_limited(loop_count)) {
    atomicAdd(loop_limited_pixels, 1u);
    uint k = uint(pixel.y * size.x + pixel.x);
    atomicOr(loop_limited_bits[k / 32u], 1u << (k % 32u));
  }
  imageStore(radiance_image, pixel, radiance);
  imageStore(ground_distance_image, pixel, vec4(ground_distance, 0.0f, 0.0f, 0.0f));
}
