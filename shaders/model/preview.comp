#version 450
// The preview of a cloud model's density volume (src/render/model_preview.cpp): one invocation
// per pixel through shaders/lib/model_march.glsl, whose C++ twin is src/shader_math.
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(rgba32f, binding = 0) uniform writeonly image2D radiance_image;
layout(binding = 1) uniform sampler3D model_density;

#include "../lib/model_march.glsl"

uniform ModelView u_view;
uniform int u_first_row;  // the band of rows this dispatch covers starts here (nephele view)

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy) + ivec2(0, u_first_row);
  ivec2 size = imageSize(radiance_image);
  if (pixel.x >= size.x || pixel.y >= size.y) return;
  imageStore(radiance_image, pixel, model_pixel(pixel, size, u_view, model_density));
}
