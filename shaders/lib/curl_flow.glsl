// The flow that warps the cloud cover: the curl of a latitude-mixed Worley potential.
#ifndef NEPHELE_CURL_FLOW_GLSL
#define NEPHELE_CURL_FLOW_GLSL
#include "prelude.glsl"
#include "worley_fbm.glsl"
#include "portable_math.glsl"


// Stream function (times s) on the unit sphere (n: unit vector, z north):
//   phi = P m - w1 (1 + m)/2 + w2 (1 - m)/2,  m = sin(a lat)
// w1 and w2 enter with opposite signs, as the Coriolis parameter changes sign at the equator:
// around their peaks (the feature points) the flow turns counter-clockwise in the north and
// clockwise in the south seen from outside, the sense of cyclones. The latitude term gives
// zonal winds u = -s (P - (w1 + w2)/2) m'(lat): easterly trade winds where m' > 0 when P
// exceeds the noise mean (the smooth w averages about 0.30 at lambda 0.3, 1 - F1 about 0.47).
// Returns the velocity
//   v = s n x grad phi,
// tangent to the sphere and divergence-free on it. At the poles the direction north is
// undefined; there the latitude term is dropped. For odd a (the default 3) m is a polynomial
// in z (sin 3 lat = 3z - 4z^3) and the term vanishes there smoothly; otherwise the mix has a
// conical tip at the poles and the flow a singular spin (docs/algorithm.md, "Poles").
// w1 and w2 are smooth_worley_fbm with lambda = params.smoothing (0: 1 - F1, whose gradient
// jumps across Voronoi borders).
// `offset` shifts the noise of both potentials (sphere radii): they are sampled at n + offset.
// The host keeps it below one lattice period (docs/numerics.md, "Far offsets"), so that float
// keeps its precision however far the user's offset is.
vec3 curl_velocity_shifted(vec3 n, IN(CurlParams) params, vec3 offset) {
  vec4 w1 = smooth_worley_fbm(n + offset, params.potential_north, params.smoothing);
  vec4 w2 = smooth_worley_fbm(n + offset, params.potential_south, params.smoothing);
  float z = clamp(n.z, -1.0f, 1.0f);
  float latitude = portable_asin(z);
  float a = params.mix_frequency;
  float m = sin(a * latitude);
  float dm_dlatitude = a * cos(a * latitude);
  vec3 north = vec3(0.0f, 0.0f, 1.0f) - z * n;
  float north_length = length(north);
  north = north_length > 1.0e-6f ? north / north_length : vec3(0.0f);
  vec3 gradient = (0.5f * (1.0f - m)) * vec3(w2) - (0.5f * (1.0f + m)) * vec3(w1) +
                  ((params.prevailing - 0.5f * (w1.w + w2.w)) * dm_dlatitude) * north;
  return params.strength * cross(n, gradient);
}

vec3 curl_velocity(vec3 n, IN(CurlParams) params) {
  return curl_velocity_shifted(n, params, vec3(0.0f));
}

#endif
