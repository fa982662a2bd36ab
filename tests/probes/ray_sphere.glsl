// Probe of lib/ray_sphere.glsl (shared GLSL/C++ subset; tests/test_library_probes.cpp).
// x[0] = (function, radius (inner), outer radius, limit), x[1] = the origin, x[2] = the
// direction, x[3] = the centre. The functions (x[0].x):
const int PROBE_RAY_SPHERE = 0;
const int PROBE_RAY_SHELL = 1;
#ifndef __cplusplus
#include "../lib/ray_sphere.glsl"
#endif
vec4 probe_ray_sphere(mat4 x) {
  if (int(x[0].x) == PROBE_RAY_SPHERE) return vec4(ray_sphere(vec3(x[1]), vec3(x[2]), vec3(x[3]), x[0].y), 0.0f, 0.0f);
  return ray_shell(vec3(x[1]), vec3(x[2]), vec3(x[3]), x[0].y, x[0].z, x[0].w);  // PROBE_RAY_SHELL
}
