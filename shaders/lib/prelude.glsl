// GLSL side of the shared GLSL/C++ subset (the C++ side is src/shader_math/glsl_cpp.hpp).
// Parameter qualifiers are macros so that C++ can pass by reference.
#ifndef NEPHELE_PRELUDE_GLSL
#define NEPHELE_PRELUDE_GLSL
#define IN(T) in T
#define OUT(T) out T
#define INOUT(T) inout T
// The textures a library function reads, named by what they hold and passed as parameters
// (Bruneton's precomputed_atmospheric_scattering does the same): GLSL samplers here; in C++
// classes that GLSL's texture functions are overloaded for (src/shader_math/hooks.hpp).
#define DensityVolume sampler3D
#define TerrainTexture sampler2D  // the ground's altitude in red, its ceiling in green
#endif
