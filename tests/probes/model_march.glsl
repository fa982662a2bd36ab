// Probe of lib/model_march.glsl (shared GLSL/C++ subset; tests/test_library_probes.cpp). The
// GLSL side reads the density volume bound to unit 4 (1000 m box). The functions (x[0].x):
const int PROBE_RAY_BOX = 0;
const int PROBE_MODEL_EXTINCTION = 1;  // model_extinction, model_light_depth
const int PROBE_MODEL_MARCH = 2;
const int PROBE_MODEL_PIXEL = 3;
const int PROBE_MODEL_RAY = 4;
#ifndef __cplusplus
layout(binding = 4) uniform sampler3D model_density;
#include "../lib/model_march.glsl"
#endif

// Seen from the south, 1.5 box edges out; the sun 40 degrees up in the south-west.
ModelView probe_model_view() {
  ModelView v;
  v.origin = vec3(500.0f, -1500.0f, 450.0f);
  v.forward = vec3(0.0f, 1.0f, 0.0f);
  v.right = vec3(1.0f, 0.0f, 0.0f);
  v.up = vec3(0.0f, 0.0f, 1.0f);
  v.tan_half_fov = 0.4f;
  v.sun = vec3(-0.5416752f, -0.5416752f, 0.6427876f);
  v.sunlight = vec3(1.4f, 1.7f, 1.8f);
  v.ambient = vec3(0.3f, 0.45f, 0.7f);
  v.ground_radiance = vec3(0.05f, 0.05f, 0.045f);
  v.background = vec3(0.1f, 0.15f, 0.3f);
  v.extent = 1000.0f;
  v.extinction = 0.02f;
  v.view_steps = 16;
  v.light_steps = 4;
  return v;
}

// x[0] = (function, a, b, c); x[1..3] points and directions.
vec4 probe_model_march(mat4 x, IN(DensityVolume) density) {
  int f = int(x[0].x);
  ModelView v = probe_model_view();
  vec3 p = vec3(x[1]);
  if (f == PROBE_RAY_BOX) return vec4(ray_box(p, normalize(vec3(x[2])), vec3(0.0f), vec3(1000.0f)), 0.0f, 0.0f);
  if (f == PROBE_MODEL_EXTINCTION)
    return vec4(model_extinction(p, v, density), model_light_depth(p, v, density), 0.0f, 0.0f);
  if (f == PROBE_MODEL_MARCH) return model_march(normalize(vec3(x[2])), x[0].y, v, density);
  if (f == PROBE_MODEL_PIXEL) return model_pixel(ivec2(int(x[0].y), int(x[0].z)), ivec2(16, 12), v, density);
  return vec4(model_ray(vec2(x[0].y, x[0].z), ivec2(16, 12), v), 0.0f);  // PROBE_MODEL_RAY
}

#ifndef __cplusplus
// The GPU probe passes x alone: the volume bound to unit 4.
vec4 probe_model_march(mat4 x) { return probe_model_march(x, model_density); }
#endif
