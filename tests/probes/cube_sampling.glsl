// Probe of lib/cube_sampling.glsl (shared GLSL/C++ subset; tests/test_library_probes.cpp).
// The cube map is CUBE_PROBE_SIZE^2 texels per face, vec4 per texel, faces in GL order and rows
// from j = 0: in GLSL the buffer at binding 2, in C++ a CubeSource over the same floats.
const int CUBE_PROBE_SIZE = 4;
#ifdef __cplusplus
#define CUBE_SOURCE_PARAM , IN(CubeSource) source
#define CUBE_SOURCE_ARG , source
#else
layout(std430, binding = 2) readonly buffer ProbeCube { vec4 probe_cube[]; };
#define CUBE_SOURCE_PARAM
#define CUBE_SOURCE_ARG
#define CUBE_FETCH(face, i, j) probe_cube[((face) * CUBE_PROBE_SIZE + (j)) * CUBE_PROBE_SIZE + (i)]
#define CUBE_SIZE CUBE_PROBE_SIZE
#include "../lib/cube_sampling.glsl"
#endif
vec4 probe_cube_sampling(mat4 x CUBE_SOURCE_PARAM) {
  if (int(x[0].x) == 0) return cube_texel_extended(int(x[0].y), int(x[0].z), int(x[0].w) CUBE_SOURCE_ARG);
  return sample_cube_bilinear(vec3(x[1]) CUBE_SOURCE_ARG);
}
#undef CUBE_SOURCE_PARAM
#undef CUBE_SOURCE_ARG
