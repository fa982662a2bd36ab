// Ray-sphere intersections for a spherical Earth and atmosphere.
#ifndef NEPHELE_RAY_SPHERE_GLSL
#define NEPHELE_RAY_SPHERE_GLSL
#include "prelude.glsl"

// Distances (near, far) along the unit direction d from o to the sphere of radius r about c;
// near > far when the ray misses. near may be negative when o is inside.
vec2 ray_sphere(vec3 o, vec3 d, vec3 c, float r) {
  vec3 oc = o - c;
  float b = dot(oc, d);
  float q = dot(oc, oc) - r * r;
  float disc = b * b - q;
  if (disc < 0.0f) return vec2(1.0f, -1.0f);
  float s = sqrt(disc);
  return vec2(-b - s, -b + s);
}

// The part of the ray [0, limit] that lies between the spheres of radii r_in < r_out about c:
// up to two intervals (a ray can cross a shell, leave it downwards into the inner sphere, or
// graze it twice near the horizon). Returns (start0, end0, start1, end1); empty intervals have
// start >= end.
vec4 ray_shell(vec3 o, vec3 d, vec3 c, float r_in, float r_out, float limit) {
  vec2 outer = ray_sphere(o, d, c, r_out);
  if (outer.x > outer.y) return vec4(0.0f);
  float a = max(outer.x, 0.0f);
  float b = min(outer.y, limit);
  if (a >= b) return vec4(0.0f);
  vec2 inner = ray_sphere(o, d, c, r_in);
  if (inner.x > inner.y || inner.y <= a || inner.x >= b) return vec4(a, b, 0.0f, 0.0f);
  return vec4(a, max(a, inner.x), min(b, inner.y), b);
}

#endif
