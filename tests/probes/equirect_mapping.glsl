// Probe of lib/equirect_mapping.glsl (shared GLSL/C++ subset; tests/test_library_probes.cpp).
// x[0] = (function, column, width, 0), x[1] = (cos, sin of the latitude) or a direction. The
// functions (x[0].x):
const int PROBE_EQUIRECT_LONGITUDE = 0;
const int PROBE_EQUIRECT_DIRECTION = 1;
const int PROBE_EQUIRECT_UV = 2;
#ifndef __cplusplus
#include "../lib/equirect_mapping.glsl"
#endif
vec4 probe_equirect_mapping(mat4 x) {
  if (int(x[0].x) == PROBE_EQUIRECT_LONGITUDE)
    return vec4(equirect_longitude(int(x[0].y), int(x[0].z)), 0.0f, 0.0f, 0.0f);
  if (int(x[0].x) == PROBE_EQUIRECT_UV) return vec4(equirect_uv(vec3(x[1])), 0.0f, 0.0f);
  return vec4(equirect_direction(int(x[0].y), int(x[0].z), vec2(x[1])), 0.0f);  // PROBE_EQUIRECT_DIRECTION
}
