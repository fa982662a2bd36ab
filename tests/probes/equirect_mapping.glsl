// Probe of lib/equirect_mapping.glsl (shared GLSL/C++ subset; tests/test_shader_probes.cpp).
#ifndef __cplusplus
#include "../lib/equirect_mapping.glsl"
#endif
vec4 probe_equirect_mapping(mat4 x) {
  if (int(x[0].x) == 0) return vec4(equirect_longitude(int(x[0].y), int(x[0].z)), 0.0f, 0.0f, 0.0f);
  if (int(x[0].x) == 2) return vec4(equirect_uv(vec3(x[1])), 0.0f, 0.0f);
  return vec4(equirect_direction(int(x[0].y), int(x[0].z), vec2(x[1])), 0.0f);
}
