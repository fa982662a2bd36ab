// Probe of lib/cube_sampling.glsl (shared GLSL/C++ subset; tests/test_library_probes.cpp).
// The cube map is CUBE_PROBE_SIZE^2 texels per face, vec4 per texel, faces in GL order and rows
// from j = 0: in GLSL the cube map image at the probe's data binding, in C++ a CubeSource over
// the same floats. x[0] = (function, face, i, j), x[1] = a direction. The functions (x[0].x):
const int PROBE_CUBE_TEXEL_EXTENDED = 0;
const int PROBE_SAMPLE_CUBE_BILINEAR = 1;
const int PROBE_CUBE_FOOTPRINT = 2;  // cube_texel_address(face, i, j, size) as i + 10 j + 100 face, and
                                     // sample_cube_footprint(cube_footprint(x[1], size), source).x in y
const int CUBE_PROBE_SIZE = 4;
#ifndef __cplusplus
layout(rgba32f, binding = 2) uniform readonly imageCube probe_cube;
#include "../lib/cube_sampling.glsl"
#endif
vec4 probe_cube_sampling(mat4 x, CubeImage source) {
  if (int(x[0].x) == PROBE_CUBE_TEXEL_EXTENDED)
    return cube_texel_extended(int(x[0].y), int(x[0].z), int(x[0].w), source);
  if (int(x[0].x) == PROBE_CUBE_FOOTPRINT) {
    int size = imageSize(source).x;
    ivec3 texel = cube_texel_address(int(x[0].y), int(x[0].z), int(x[0].w), size);
    return vec4(float(texel.x + 10 * texel.y + 100 * texel.z),
                sample_cube_footprint(cube_footprint(vec3(x[1]), size), source).x, 0.0f, 0.0f);
  }
  return sample_cube_bilinear(vec3(x[1]), source);  // PROBE_SAMPLE_CUBE_BILINEAR
}
#ifndef __cplusplus
vec4 probe_cube_sampling(mat4 x) { return probe_cube_sampling(x, probe_cube); }
#endif
