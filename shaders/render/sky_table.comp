#version 450
// The air's multiple-scattering table of the orbit view (atmosphere.glsl's
// multiple_scattering_table_entry, Hillaire 2020's Psi): one invocation per texel, mu_sun across,
// altitude up. src/render/sky_table.cpp makes it once per planet radius.
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(rgba32f, binding = 0) uniform writeonly image2D table_image;
layout(binding = 1) uniform sampler2D transmittance_table;  // the air's transmittance (atmosphere.glsl)
uniform float u_radius;         // planet radius, m
uniform float u_ground_albedo;  // mean albedo under the air

#include "../lib/atmosphere.glsl"

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (texel.x >= MULTIPLE_SCATTERING_TABLE_SIZE || texel.y >= MULTIPLE_SCATTERING_TABLE_SIZE) return;
  vec3 psi = multiple_scattering_table_entry(transmittance_table, texel.x, texel.y, u_radius, u_ground_albedo);
  imageStore(table_image, texel, vec4(psi, 1.0f));
}
