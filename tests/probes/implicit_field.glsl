// Probe of lib/implicit_field.glsl (shared GLSL/C++ subset; tests/test_library_probes.cpp).
// x[0] = (function, a, b, c); x[1..3] as each function needs. The functions (x[0].x):
const int PROBE_FIELD_PARTS = 0;  // wyvill1(a), lipus_blend(b, c, x[1].x), apply_turbulence(x[1].yzw)
const int PROBE_PRIMITIVE_FIELD = 1;  // segment_distance, primitive_distance, primitive_field at (a, b, c)
const int PROBE_MODEL_TURBULENCE = 2;
const int PROBE_MODEL_BLENDS = 3;  // model_accumulate and model_finish with each blend
// model_erode(a, b, c) and model_levels(a, (b, c)); at the point x[1].yzw, with the erosion
// x[2].x and the frequency limit x[2].y: model_turbulence and model_detail of the field x[1].x
const int PROBE_EROSION = 4;
#ifndef __cplusplus
#include "../lib/implicit_field.glsl"
#endif
ModelPrimitive probe_model_primitive(mat4 x) {
  ModelPrimitive prim;
  prim.a = x[1];
  prim.b = x[2];
  prim.kind = vec4(x[3].x, x[3].y, 0.0f, 0.0f);
  prim.noise.shape = vec4(3.0f, x[3].z, 0.6f, 0.5f);
  prim.noise.extra = vec4(2.0f, x[3].w, 7.0f, 0.5f);
  return prim;
}
vec4 probe_implicit_field(mat4 x) {
  int f = int(x[0].x);
  vec3 p = vec3(x[0].y, x[0].z, x[0].w);
  ModelPrimitive prim = probe_model_primitive(x);
  if (f == PROBE_FIELD_PARTS) return vec4(wyvill1(x[0].y), lipus_blend(x[0].z, x[0].w, x[1].x),
                          apply_turbulence(x[1].y, x[1].z, x[1].w), 0.0f);
  if (f == PROBE_PRIMITIVE_FIELD) return vec4(segment_distance(p, vec3(x[1]), vec3(x[2])), primitive_distance(p, prim),
                          primitive_field(p, prim), 0.0f);
  if (f == PROBE_MODEL_TURBULENCE) return vec4(model_turbulence(p, prim.noise, 0.0f), 0.0f, 0.0f, 0.0f);
  if (f == PROBE_EROSION) {
    ModelNoise noise = prim.noise;
    noise.extra.w = x[2].x;
    vec3 q = vec3(x[1].y, x[1].z, x[1].w);
    return vec4(model_erode(x[0].y, x[0].z, x[0].w), model_levels(x[0].y, vec2(x[0].z, x[0].w)),
                model_turbulence(q, noise, x[2].y), model_detail(x[1].x, q, noise, x[2].y));
  }
  // PROBE_MODEL_BLENDS: one primitive folded in with each blend, then finished.
  vec4 r = vec4(0.0f);
  for (int blend = 0; blend < 4; ++blend) {
    float rho = model_accumulate(0.25f, p, p, prim, blend, 0.0f);
    r[blend] = model_finish(rho, p.z, p, blend, prim.noise, vec2(0.0f, 1.0f), 0.0f);
  }
  return r;
}
