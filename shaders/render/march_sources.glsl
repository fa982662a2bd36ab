// The textures of the ray marcher (shaders/lib/cloud_march.glsl) and how it reads them, shared by
// the passes that include it (render/clouds.comp, render/layer_shadows.comp); their C++ twin is
// src/shader_math/hook_macros.hpp.
layout(binding = 1) uniform sampler3D noise_volume;
layout(binding = 2) uniform sampler2DArray weather_field;
layout(binding = 4) uniform sampler2D terrain_heights;  // terrain.glsl's height field and ceiling
// The convective clouds' density volumes, volume c in z-layers [c N, (c + 1) N) (N^3 each).
layout(binding = 5) uniform sampler3D convective_volumes;
// The shadow maps of the layers with layers above them (render/layer_shadows.comp).
layout(binding = 6) uniform sampler2DArray layer_shadows;
// The sky's shadow map (crepuscular rays; render/layer_shadows.comp with layer -1), layer 0.
layout(binding = 7) uniform sampler2DArray sky_shadow;

#define MARCH_SOURCES_PARAM
#define MARCH_SOURCES_ARG
#define NOISE_LOD(x, lod) textureLod(noise_volume, x, lod)
#define WEATHER_COVERAGE(uv, channel) texture(weather_field, vec3(uv, float(channel))).x
#define MARCH_TERRAIN_ARG , terrain_heights
#define CONVECTIVE_DENSITY(q, cloud) texture(convective_volumes, convective_texel(q, cloud)).x
#define LAYER_SHADOW(uv, map) texture(layer_shadows, vec3(uv, float(map))).x
#define SKY_SHADOW(uv) texture(sky_shadow, vec3(uv, 0.0f)).x
// Volume c's coordinates q in the stack, z clamped to its own texel centres (so it is read as
// its own texture with GL_CLAMP_TO_EDGE would be, the C++ twin's ConvectiveSource).
vec3 convective_texel(vec3 q, int cloud) {
  ivec3 size = textureSize(convective_volumes, 0);
  float n = float(size.x);
  return vec3(q.x, q.y, (float(cloud) * n + clamp(q.z * n, 0.5, n - 0.5)) / float(size.z));
}
#include "../lib/cloud_march.glsl"
