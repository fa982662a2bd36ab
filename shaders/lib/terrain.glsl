// The ground of the views near the ground: a height field over the Earth sphere, its ray
// intersection and normal (docs/terrain.md; what covers it is land_cover.glsl). Points q are relative to the centre of the
// sphere that osculates the WGS84 ellipsoid at the viewpoint, in the camera's east-north-up
// axes; the height field's horizontal coordinate of q is earth_radius * normalize(q).xy, metres
// on the tangent plane at the camera. The heights are the parameter `terrain` (TerrainTexture),
// sampled at uv in [0, 1]^2, bilinear, clamped to the edge; u east, v north:
//   red    altitude (m above the sphere)
//   green  the ceiling: at each texel the highest altitude within a window of texels around it
//          (regional::terrain_ceilings), so that, bilinear, it bounds the ground within
//          TerrainParams::reach of uv (docs/terrain.md)
#ifndef NEPHELE_TERRAIN_GLSL
#define NEPHELE_TERRAIN_GLSL
#include "prelude.glsl"
#include "render_types.glsl"
#include "ray_sphere.glsl"

// March steps along a ray at most: a ray grazing the ground all the way needs about 100 steps
// to 200 m, 530 more at 1% of the distance to 39 km, then 1 per texel (390 m) beyond.
const int TERRAIN_MARCH_STEPS = 2048;
const int TERRAIN_BISECTIONS = 16;     // halvings of the step that crossed the surface

// The height field's horizontal coordinate (m) of a point.
vec2 terrain_plane(vec3 q, float earth_radius) { return earth_radius * vec2(normalize(q)); }

// Altitude of the ground above the sphere at a horizontal coordinate: the height field within
// its square, the sphere itself (sea level) outside it and without terrain.
float terrain_altitude(vec2 xy, IN(TerrainParams) t, IN(TerrainTexture) terrain) {
  if (t.enabled == 0 || abs(xy.x) > t.extent || abs(xy.y) > t.extent) return 0.0f;
  return texture(terrain, 0.5f + 0.5f * xy / t.extent).x;
}

// The highest the ground gets within t.reach (horizontally) of a horizontal coordinate: the
// ceiling texture, and sea level outside the square (the clamped edge is no lower than what
// the window saw there, since clamping moves a point towards the square).
float terrain_ceiling(vec2 xy, IN(TerrainParams) t, IN(TerrainTexture) terrain) {
  return max(texture(terrain, 0.5f + 0.5f * xy / t.extent).y, 0.0f);
}

// Height of a point above the ground below it (negative underground).
float terrain_clearance(vec3 q, float earth_radius, IN(TerrainParams) t, IN(TerrainTexture) terrain) {
  return length(q) - earth_radius - terrain_altitude(terrain_plane(q, earth_radius), t, terrain);
}

// Distance along the unit direction d from o (relative to the centre) to the first ground
// point, at most `limit`; -1 when the ray reaches neither the terrain nor the sphere by then.
// Within the shell below the highest terrain the ray steps by half its clearance (at least 2 m
// plus 1% of the distance, so that rays grazing flat ground for long get through; at most one
// texel, so that no texel is skipped), then bisects the step that crossed the surface. Where
// the ray is above the ceiling it may step further, up to t.reach, as long as it stays above
// the ceiling: the altitude along a straight ray is convex, so over a step L it falls by at most
// L times its present rate of fall; no ground within reach is skipped. A ray still above the
// ground after the last step has grazed it all along and counts as meeting it there. loops:
// the iterations it took.
float terrain_hit(vec3 o, vec3 d, float earth_radius, float limit, IN(TerrainParams) t, OUT(int) loops, IN(TerrainTexture) terrain) {
  loops = 0;
  vec2 sphere = ray_sphere(o, d, vec3(0.0f), earth_radius);
  float ground = sphere.x < sphere.y && sphere.x > 0.0f && sphere.x <= limit ? sphere.x : -1.0f;
  if (t.enabled == 0) return ground;
  vec2 shell = ray_sphere(o, d, vec3(0.0f), earth_radius + t.top);
  if (shell.x > shell.y || shell.y <= 0.0f) return ground;
  float s = max(shell.x, 0.0f);
  float end = min(shell.y, ground > 0.0f ? ground : limit);
  float previous = s;
  for (int i = 0; i < TERRAIN_MARCH_STEPS && s <= end; ++i) {
    loops += 1;
    float h = terrain_clearance(o + s * d, earth_radius, t, terrain);
    if (h <= 0.0f) {
      // The surface lies between the previous sample (above) and this one (below).
      float a = previous;
      float b = s;
      for (int k = 0; k < TERRAIN_BISECTIONS; ++k) {
        loops += 1;
        float c = 0.5f * (a + b);
        if (terrain_clearance(o + c * d, earth_radius, t, terrain) > 0.0f) a = c; else b = c;
      }
      return b;
    }
    previous = s;
    float step = min(max(0.5f * h, 2.0f + 0.01f * s), t.texel);
    if (t.reach > 0.0f) {
      vec3 q = o + s * d;
      float r = length(q);
      // 2 m below the ceiling for the float rounding of the altitude at the Earth's radius.
      float room = r - earth_radius - terrain_ceiling(terrain_plane(q, earth_radius), t, terrain) - 2.0f;
      float fall = max(-dot(d, q) / r, 1.0e-6f);
      if (room > 0.0f) step = max(step, min(t.reach, room / fall));
    }
    s += step;
  }
  return s <= end ? s : ground;
}

// 1 where the ground point q (on the ground, outward normal `normal`) sees the sun in the unit
// direction `sun`, 0 where the terrain hides it: a march towards the sun from 5 m off the
// surface (four times the altitudes' float rounding at the Earth's radius, so that the point
// does not find itself). loops: the iterations it took.
float terrain_sunlit(vec3 q, vec3 normal, vec3 sun, float earth_radius, IN(TerrainParams) t, OUT(int) loops, IN(TerrainTexture) terrain) {
  loops = 0;
  if (t.enabled == 0) return 1.0f;
  float hit = terrain_hit(q + 5.0f * normal, sun, earth_radius, 1.0e7f, t, loops, terrain);
  return hit > 0.0f ? 0.0f : 1.0f;
}

// Outward unit normal of the ground at q (a point on it): the sphere's radial direction tilted
// by the height field's gradient (central differences one texel apart).
vec3 terrain_normal(vec3 q, float earth_radius, IN(TerrainParams) t, IN(TerrainTexture) terrain) {
  vec3 up = normalize(q);
  if (t.enabled == 0) return up;
  vec2 xy = terrain_plane(q, earth_radius);
  vec2 dx = vec2(t.texel, 0.0f);
  vec2 dy = vec2(0.0f, t.texel);
  float gx = (terrain_altitude(xy + dx, t, terrain) - terrain_altitude(xy - dx, t, terrain)) / (2.0f * t.texel);
  float gy = (terrain_altitude(xy + dy, t, terrain) - terrain_altitude(xy - dy, t, terrain)) / (2.0f * t.texel);
  // The grid's east and north axes made tangent at q.
  vec3 east = normalize(vec3(1.0f, 0.0f, 0.0f) - up.x * up);
  vec3 north = normalize(vec3(0.0f, 1.0f, 0.0f) - up.y * up);
  return normalize(up - gx * east - gy * north);
}

#endif
