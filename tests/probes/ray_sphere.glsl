// Probe of lib/ray_sphere.glsl (shared GLSL/C++ subset; tests/test_shader_probes.cpp).
#ifndef __cplusplus
#include "../lib/ray_sphere.glsl"
#endif
vec4 probe_ray_sphere(mat4 x) {
  if (int(x[0].x) == 0) return vec4(ray_sphere(vec3(x[1]), vec3(x[2]), vec3(x[3]), x[0].y), 0.0f, 0.0f);
  return ray_shell(vec3(x[1]), vec3(x[2]), vec3(x[3]), x[0].y, x[0].z, x[0].w);
}
