// The textures of the ray marcher (shaders/lib/cloud_march.glsl) at their units, shared by the
// passes that include it (render/clouds.comp, render/layer_shadows.comp), which pass them to the
// marcher's functions by name; their C++ twins are the classes of src/shader_math/hooks.hpp.
#include "../lib/prelude.glsl"

layout(binding = 1) uniform NoiseVolume noise_volume;
layout(binding = 2) uniform WeatherField weather_field;
layout(binding = 4) uniform TerrainTexture terrain_heights;  // terrain.glsl's height field and ceiling
// What covers the ground (land_cover.glsl): lakes, rivers, towns, a layer per level.
layout(binding = 8) uniform LandCoverTexture land_cover;
// The convective clouds' density volumes, volume c in z-layers [c N, (c + 1) N) (N^3 each).
layout(binding = 5) uniform ConvectiveVolumes convective_volumes;
// The shadow maps of the layers with layers above them (render/layer_shadows.comp).
layout(binding = 6) uniform ShadowMaps layer_shadows;
// The sky's shadow map (crepuscular rays; render/layer_shadows.comp with layer -1), layer 0.
layout(binding = 7) uniform ShadowMaps sky_shadow;

#include "../lib/cloud_march.glsl"
