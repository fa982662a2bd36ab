#version 450
// The air's transmittance table of the orbit view (atmosphere.glsl's transmittance_table_entry,
// Bruneton 2017's transmittance texture): one invocation per texel, the distance to the top
// across, the altitude up. src/render/sky_table.cpp makes it once per planet radius.
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(rgba32f, binding = 0) uniform writeonly image2D table_image;
uniform float u_radius;  // planet radius, m

#include "../lib/atmosphere.glsl"

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (texel.x >= TRANSMITTANCE_TABLE_WIDTH || texel.y >= TRANSMITTANCE_TABLE_HEIGHT) return;
  imageStore(table_image, texel, vec4(transmittance_table_entry(texel.x, texel.y, u_radius), 1.0f));
}
