// Probe of lib/perlin.glsl (shared GLSL/C++ subset; tests/test_library_probes.cpp).
// x[0] = (function, a, b, c), x[1] = the point, x[2] = the period, x[3] = the key. The functions
// (x[0].x):
const int PROBE_WRAP_AXIS_AND_FADE = 0;  // wrap_axis(a, b), perlin_fade(c)
const int PROBE_PERLIN_GRADIENT = 1;
const int PROBE_PERLIN_YZ_WEIGHTS = 2;  // perlin_yz_weights(a, b)
const int PROBE_PERLIN_FACES = 3;  // perlin_face, perlin_along_row
const int PROBE_PERLIN_NOISE = 4;
const int PROBE_PERLIN_NOISE_GRADIENT = 5;  // perlin_noise_gradient (the period unused)
#ifndef __cplusplus
#include "../lib/perlin.glsl"
#endif
vec4 probe_perlin(mat4 x) {
  int f = int(x[0].x);
  vec3 p = vec3(x[1]);
  ivec3 period = ivec3(vec3(x[2]));
  uvec3 key = uvec3(vec3(x[3]));
  if (f == PROBE_WRAP_AXIS_AND_FADE)
    return vec4(float(wrap_axis(int(x[0].y), int(x[0].z))), perlin_fade(x[0].w), 0.0f, 0.0f);
  if (f == PROBE_PERLIN_GRADIENT) return vec4(perlin_gradient(ivec3(p), key), 0.0f);
  if (f == PROBE_PERLIN_YZ_WEIGHTS) return perlin_yz_weights(x[0].y, x[0].z);
  if (f == PROBE_PERLIN_FACES) {
    // The faces at lattice x and x + 1 of the cell (y, z) and the row's value between them at p.x.
    ivec2 ys = ivec2(int(x[0].z), int(x[0].z) + 1);
    ivec2 zs = ivec2(int(x[0].w), int(x[0].w) + 1);
    vec4 w = perlin_yz_weights(p.y, p.z);
    vec2 face0 = perlin_face(int(x[0].y), ys, zs, p.y, p.z, w, key);
    vec2 face1 = perlin_face(int(x[0].y) + 1, ys, zs, p.y, p.z, w, key);
    return vec4(face0, face1.x, perlin_along_row(face0, face1, p.x));
  }
  if (f == PROBE_PERLIN_NOISE_GRADIENT) return perlin_noise_gradient(p, key);
  return vec4(perlin_noise(p, period, key), 0.0f, 0.0f, 0.0f);  // PROBE_PERLIN_NOISE
}
