#version 450
// The shadow maps of the layers with layers wholly above them and the sky's (cloud_march.glsl's
// shadow_map_texel, docs/rendering.md "Shadows between layers", "Crepuscular rays"): one
// invocation per texel of the map of layer u_layer, once per render before render/clouds.comp
// reads them.
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(r32f, binding = 0) uniform writeonly image2DArray shadow_maps;

#include "march_sources.glsl"

uniform MarchParams u_march;
uniform int u_layer;  // the layer whose map this dispatch fills (its shadow_map is the array layer); -1: the sky's

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  int size = imageSize(shadow_maps).x;
  if (texel.x >= size || texel.y >= size) return;
  vec3 centre = vec3(0.0f, 0.0f, -(u_march.earth_radius + u_march.camera_altitude));
  int loop_count = 0;  // SHADOW_STEPS per layer above: far from llvmpipe's limit
  float depth = shadow_map_texel((vec2(texel) + 0.5f) / float(size), centre, u_layer, loop_count, u_march, noise_volume,
                                 weather_field, convective_volumes);
  int map = u_layer >= 0 ? u_march.layers[u_layer].shadow_map : u_march.sky_shadow_map;
  imageStore(shadow_maps, ivec3(texel, map), vec4(depth));
}
