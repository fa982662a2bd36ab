#version 450
// The guide of the edge-aware upsampling (render/upsample.hpp): for each pixel of a list, the
// distance along its view ray to the ground, or -1 where the ray meets no ground (the sky).
// One invocation per listed pixel through view_ray_end of shaders/lib/cloud_march.glsl, the
// function where the marcher of render/clouds.comp ends its rays, so guide and render agree on
// where the ground is. The marched image's own guide comes from the marcher (clouds.comp); at
// full size only the pixels near an edge of that guide need theirs (render::guide_pixels): the
// terrain march of every pixel of an HD image costs as much as the clouds marched at a quarter
// of its size.
layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;
layout(std430, binding = 0) readonly buffer GuidePixels {
  ivec2 guide_pixels[];
};
layout(std430, binding = 1) writeonly buffer GroundDistances {
  float ground_distances[];
};

#include "march_sources.glsl"

uniform MarchParams u_march;
uniform ivec2 u_image_size;  // the image the listed pixels belong to
uniform int u_pixel_count;

void main() {
  int k = int(gl_GlobalInvocationID.x);
  if (k >= u_pixel_count) return;
  int loops = 0;
  vec2 end = view_ray_end(view_direction(guide_pixels[k], u_image_size, u_march), u_march, loops, terrain_heights);
  ground_distances[k] = end.x;
}
