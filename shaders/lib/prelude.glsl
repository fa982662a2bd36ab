// GLSL side of the shared GLSL/C++ subset (the C++ side is src/shader_math/glsl_cpp.hpp).
// Parameter qualifiers are macros so that C++ can pass by reference.
#ifndef NEPHELE_PRELUDE_GLSL
#define NEPHELE_PRELUDE_GLSL
#define IN(T) in T
#define OUT(T) out T
#define INOUT(T) inout T
// Work that a group of SIMD lanes can skip. SIMD CPU drivers (llvmpipe) run an `if`'s body for the
// whole group of lanes with those whose condition fails masked, so a branch rarely taken costs as
// much as one always taken; a loop, though, ends when its last lane leaves it, after one pass with
// every lane masked where none enters. Costly work is therefore a loop whose count is
// SKIPPABLE(condition, count): `count` where the condition holds, 0 elsewhere, so that a group
// where it holds for no lane pays one masked pass instead of `count` (the cells' 27-cell searches
// of weather_systems.glsl). A loop with a constant count gains nothing: the compiler unrolls it
// into straight code, which every group runs. On a GPU it is a branch as any other.
#define SKIPPABLE(condition, count) ((condition) ? (count) : 0)
// A parameter that only some variants of a function use (a shader's #if): nothing in GLSL, and a
// use for C++'s warnings.
#define UNUSED_PARAMETER(name)
// The textures a library function reads, named by what they hold and passed as parameters
// (Bruneton's precomputed_atmospheric_scattering does the same): GLSL samplers here; in C++
// classes that GLSL's texture functions are overloaded for (src/shader_math/hooks.hpp).
#define DensityVolume sampler3D
#define TerrainTexture sampler2D  // the ground's altitude in red, its ceiling in green
#define LandCoverTexture sampler2DArray  // water distance in red, built-up fraction in green, a layer per level
#define NoiseVolume sampler3D        // the renderer's baked noise, mip-mapped, repeating
#define WeatherField sampler2DArray  // a layer per coverage channel
#define ConvectiveVolumes sampler3D  // the convective clouds' density volumes stacked along z
#define ShadowMaps sampler2DArray    // a layer per shadow map
#define ScatteringTable sampler2D    // the air's multiple scattering by sun angle and altitude (atmosphere.glsl)
#define TransmittanceTable sampler2D  // the air's transmittance to its top by altitude and angle (atmosphere.glsl)
// Images read with imageLoad. GLSL takes no format and no `in` on an image parameter: the
// argument's format applies (GLSL 4.50 section 4.4.6.2), and readonly is part of the type here.
#define CubeImage readonly imageCube         // a cube map, face = layer (cube_sampling.glsl)
#define SplineImage readonly image2DArray    // the curl spline's coefficients (curl_spline.glsl)
#endif
