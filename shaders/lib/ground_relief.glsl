// The ground's relief for the orbit view (docs/orbit_view.md, "Relief"): the sun's incidence on
// ground whose slopes come from an elevation map (ETOPO5), so that mountain ranges show their
// sunlit and shaded sides under a low sun as they do in photographs from orbit.
#ifndef NEPHELE_GROUND_RELIEF_GLSL
#define NEPHELE_GROUND_RELIEF_GLSL
#include "prelude.glsl"

// The unit normal of ground whose height rises by slopes.x metres per metre towards the east and
// slopes.y towards the north, at the point whose vertical is the unit vector `up` (Earth-centred,
// Earth-fixed: +Z north). The surface z = h(east, north) has the normal (-h_east, -h_north, 1)
// in (east, north, up). At the poles, where east is undefined, the vertical.
vec3 relief_normal(vec3 up, vec2 slopes) {
  vec3 east = vec3(-up.y, up.x, 0.0f);
  float east_length = length(east);
  if (east_length < 1e-6f) return up;
  east = east / east_length;
  vec3 north = cross(up, east);
  return normalize(up - slopes.x * east - slopes.y * north);
}

// The cosine of the sun's incidence on that ground, 0 where the slope faces away from it.
float relief_sun_cosine(vec3 up, vec2 slopes, vec3 sun) { return max(dot(relief_normal(up, slopes), sun), 0.0f); }

#endif
