#pragma once
// The C++ twins of the textures and images that the GLSL library (shaders/lib) takes as
// parameters, with the GLSL texture and image functions it calls on them: the cube map of
// cube_sampling.glsl, the curl spline of curl_spline.glsl, the velocity sources of
// warp_step.glsl's templates, the textures of cloud_march.glsl and terrain.glsl and the density
// volume of model_march.glsl. Shared by
// shader_math.hpp (declarations) and shader_math.cpp (the one compiled copy of the functions).
#include <cmath>
#include <cstddef>
#include <vector>

#include "shader_math/glsl_cpp.hpp"

namespace nephele::glsl {

#include "lib/parameters.glsl"

// A cube map in host memory, vec4 per texel, faces in GL order, rows from t = 0. Or, without
// `texels`, one channel in separate faces (a cover too large for the GPU, mapped from files:
// cover/streamed_equirect.cpp): row j of face f at face_rows[f] + (j - first_row[f]) size.
struct CubeSource {
  int size = 0;
  const vec4* texels = nullptr;
  const float* const* face_rows = nullptr;
  const int* first_row = nullptr;
  vec4 fetch(int face, int i, int j) const {
    if (texels) return texels[(static_cast<size_t>(face) * size + j) * size + i];
    return vec4(face_rows[face][static_cast<size_t>(j - first_row[face]) * size + i], 0.0f, 0.0f, 0.0f);
  }
};
// cube_sampling.glsl's parameter type and its image functions (GLSL's imageCube: layer = face).
using CubeImage = const CubeSource&;
inline ivec2 imageSize(IN(CubeSource) cube) { return ivec2(cube.size); }
inline vec4 imageLoad(IN(CubeSource) cube, ivec3 p) { return cube.fetch(p.z, p.x, p.y); }

// The curl spline's coefficient grid in host memory (curl_spline.glsl): vec4 per node, faces in GL
// order, each face (cells + 2 SPLINE_MARGIN)^2 nodes, rows from t = 0, as the GPU's 2D array
// texture reads back.
struct SplineSource {
  int cells = 0;
  const vec4* texels = nullptr;
  int layers = 6;                             // 6 per time node (the moving flow's grids)
  vec4 fetch(int layer, int i, int j) const;  // defined after curl_spline.glsl (SPLINE_MARGIN)
};
// curl_spline.glsl's parameter type and its image functions (a 2D array: layer = face + 6 node).
using SplineImage = const SplineSource&;
ivec3 imageSize(IN(SplineSource) spline);  // defined after curl_spline.glsl (SPLINE_MARGIN)
inline vec4 imageLoad(IN(SplineSource) spline, ivec3 p) { return spline.fetch(p.z, p.x, p.y); }

// The renderer's noise volume in host memory (cloud_march.glsl's NoiseVolume): RGBA per texel,
// every mip level (level k of size >> k texels per side, x fastest, then y, then z), sampled as
// GLSL's textureLod with GL_LINEAR_MIPMAP_LINEAR filtering and GL_REPEAT wrapping (OpenGL 4.5
// section 8.14: lerps along x, y, z, then between the levels floor(lod) and floor(lod) + 1).
struct VolumeSource {
  int size = 0;
  std::vector<std::vector<vec4>> levels;
  vec4 sample_lod(vec3 x, float lod) const;
};
// cloud_march.glsl's parameter type and its textureLod().
using NoiseVolume = VolumeSource;
inline vec4 textureLod(IN(VolumeSource) volume, vec3 x, float lod) { return volume.sample_lod(x, lod); }

// A 2D array texture of one channel in host memory (cloud_march.glsl's WeatherField, the
// weather field): values[(layer * size + row) * size + column], sampled as GLSL's texture() with
// GL_LINEAR filtering and GL_CLAMP_TO_EDGE wrapping.
struct LayeredSource {
  int size = 0;
  int layers = 0;
  const float* values = nullptr;
  float sample(vec2 uv, int layer) const;
};
// cloud_march.glsl's parameter types (the weather field, the shadow maps) and their texture():
// the layer is the nearest integer to p.z, clamped to the layers (OpenGL 4.5 section 8.14.2).
using WeatherField = LayeredSource;
using ShadowMaps = LayeredSource;
inline vec4 texture(IN(LayeredSource) layers, vec3 p) {
  return vec4(layers.sample(vec2(p.x, p.y), static_cast<int>(std::floor(p.z + 0.5f))));
}

// A cloud model's density volume in host memory (model_march.glsl's DensityVolume): one float
// per voxel, x fastest, sampled as GLSL's texture() with GL_LINEAR and GL_CLAMP_TO_EDGE.
struct DensitySource {
  int size = 0;
  const float* values = nullptr;
  float sample(vec3 uvw) const;
};
// model_march.glsl's parameter type and its texture() (the density in every channel).
using DensityVolume = DensitySource;
inline vec4 texture(IN(DensitySource) density, vec3 uvw) { return vec4(density.sample(uvw)); }

// A small 2D table of vec4 in host memory (atmosphere.glsl's ScatteringTable and
// TransmittanceTable): texels[row * width + column], rows from t = 0, sampled as GLSL's
// textureLod() at level 0 with GL_LINEAR filtering and GL_CLAMP_TO_EDGE wrapping.
struct TableSource {
  int width = 0;
  int height = 0;
  const vec4* texels = nullptr;
  vec4 sample(vec2 uv) const;
};
using ScatteringTable = TableSource;
using TransmittanceTable = TableSource;
inline vec4 textureLod(IN(TableSource) table, vec2 uv, float) { return table.sample(uv); }

// The convective clouds' density volumes (cloud_march.glsl's ConvectiveVolumes): `count`
// volumes of size^3 floats one after the other, as the z-layers of one 3D texture of size x size
// x (count size) on the GPU. texture() samples the stack with GL_LINEAR and GL_CLAMP_TO_EDGE; the
// marcher's convective_density keeps z within one volume's texel centres, so each volume is
// read on its own.
struct ConvectiveSource {
  int size = 0;
  int count = 0;
  const float* values = nullptr;
  float sample(vec3 stack) const;
};
using ConvectiveVolumes = ConvectiveSource;
inline vec4 texture(IN(ConvectiveSource) volumes, vec3 stack) { return vec4(volumes.sample(stack)); }
inline ivec3 textureSize(IN(ConvectiveSource) volumes, int) {
  return ivec3(volumes.size, volumes.size, volumes.size * volumes.count);
}

// The ground's two textures in host memory (terrain.glsl's TerrainTexture: the red and green
// channels of one texture on the GPU): one-layer sources of the same size,
// regional::terrain_source of a TerrainGrid.
struct TerrainSource {
  LayeredSource heights;
  LayeredSource ceilings;
};
using TerrainTexture = TerrainSource;
inline vec4 texture(IN(TerrainSource) terrain, vec2 uv) {
  return vec4(terrain.heights.sample(uv, 0), terrain.ceilings.sample(uv, 0), 0.0f, 0.0f);
}

// The land cover in host memory (land_cover.glsl's LandCoverTexture: the red and green channels
// of one texture array on the GPU): the water distance and built-up fraction, a layer per level
// (regional::LandCoverGrid's arrays). Sampled like the weather field (the layer is the nearest
// integer to p.z).
struct LandCoverSource {
  LayeredSource water;
  LayeredSource urban;
};
using LandCoverTexture = LandCoverSource;
inline vec4 texture(IN(LandCoverSource) land, vec3 p) {
  const int layer = static_cast<int>(std::floor(p.z + 0.5f));
  return vec4(land.water.sample(vec2(p.x, p.y), layer), land.urban.sample(vec2(p.x, p.y), layer), 0.0f, 0.0f);
}

// The textures of cloud_march.glsl in host memory, held together for the tests: the noise
// volume, the weather field, the ground's height field and ceiling, the convective clouds'
// volumes and the layers' shadow maps (the marcher's functions take each by name).
struct MarchSources {
  VolumeSource noise;
  LayeredSource weather;
  TerrainSource terrain;
  LandCoverSource land;  // none by default (TerrainParams::land 0 never samples it)
  ConvectiveSource convective;
  // The shadow maps (cloud_march.glsl's layer_shadows): one layer per map; none by default.
  LayeredSource shadows;
  // The sky's shadow map (sky_shadow): one layer; none by default.
  LayeredSource sky_shadow;
};

// The velocity sources of the warp's stepping rules: the sampled cube map, the procedural curl,
// the curl spline, or any callable vec3(vec3) (the analytic flows of the tests). Declared before warp_step.glsl
// so that its templates find them for callables, whose namespace ADL would not search.
vec3 warp_velocity(vec3 w, IN(CubeSource) source);
vec3 warp_velocity(vec3 w, IN(CurlParams) curl);
vec3 warp_velocity(vec3 w, IN(SplineSource) spline);
template <class F>
vec3 warp_velocity(vec3 w, const F& velocity) {
  return velocity(w);
}

}  // namespace nephele::glsl

#include "shader_math/hook_macros.hpp"
