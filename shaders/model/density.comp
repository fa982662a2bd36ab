#version 450
// The density volume of a cloud model (src/model/density_volume.cpp): one work group per listed
// brick of MODEL_BRICK^3 voxels, each voxel blending only the primitives of its brick's list
// (the primitives whose reach R + I touches the brick), so the work follows the overlap.
layout(local_size_x = 8, local_size_y = 8, local_size_z = 8) in;
#include "../lib/implicit_field.glsl"

layout(r32f, binding = 0) uniform writeonly image3D u_density;
layout(std430, binding = 1) readonly buffer Primitives { ModelPrimitive primitives[]; };
// Per job: the brick (x, y, z) and the start and length of its list in `indices`.
layout(std430, binding = 2) readonly buffer Jobs { uvec4 jobs[]; };
layout(std430, binding = 3) readonly buffer Indices { uint indices[]; };

uniform int u_size;
uniform int u_jobs;
uniform int u_blend;
uniform float u_scale;
uniform vec4 u_noise_shape;
uniform vec4 u_noise_extra;
uniform vec2 u_levels;          // (base, top) of model_levels
uniform float u_max_frequency;  // model_turbulence's octave limit for this volume's voxels

void main() {
  int job = int(gl_WorkGroupID.x + gl_WorkGroupID.y * gl_NumWorkGroups.x);
  if (job >= u_jobs) return;
  uvec4 entry = jobs[job];
  uint brick = entry.x;
  int per_axis = (u_size + 7) / 8;
  ivec3 b = ivec3(int(brick) % per_axis, (int(brick) / per_axis) % per_axis, int(brick) / (per_axis * per_axis));
  ivec3 voxel = b * 8 + ivec3(gl_LocalInvocationID);
  if (any(greaterThanEqual(voxel, ivec3(u_size)))) return;
  vec3 p = (vec3(voxel) + 0.5f) / float(u_size);
  vec3 q = p / u_scale;
  float rho = 0.0f;
  for (uint k = 0u; k < entry.z; ++k)
    rho = model_accumulate(rho, p, q, primitives[indices[entry.y + k]], u_blend, u_max_frequency);
  ModelNoise noise;
  noise.shape = u_noise_shape;
  noise.extra = u_noise_extra;
  imageStore(u_density, voxel, vec4(model_finish(rho, p.z, q, u_blend, noise, u_levels, u_max_frequency), 0.0f, 0.0f, 0.0f));
}
