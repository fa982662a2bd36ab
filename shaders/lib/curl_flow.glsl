// The flow that warps the cloud cover: the curl of a latitude-mixed Worley potential.
#ifndef NEPHELE_CURL_FLOW_GLSL
#define NEPHELE_CURL_FLOW_GLSL
#include "prelude.glsl"
#include "worley_fbm.glsl"
#include "portable_math.glsl"

// The storm-track envelope of the vortices, A = 1 - f (1 - g) with
//   g = exp(-((z^2 - z_t^2) / sigma)^2),  z_t = sin 50 deg, sigma = 0.25,
// and f = params.storm_tracks: A is 1 in the storm tracks near 50 N and 50 S (between 35
// and 66 degrees g > 1/e) and falls to 1 - f at the equator. A polynomial of z^2 under the
// exponential, it is smooth on the whole sphere, the poles included. f = 0: A = 1 (no focus).
// Returns (A, dA/dz).
vec2 storm_track_envelope(float z, float focus) {
  const float track = 0.58682409f;  // sin^2(50 deg)
  const float width = 0.25f;
  float u = (z * z - track) / width;
  float g = exp(-u * u);
  return vec2(1.0f - focus * (1.0f - g), focus * g * (-2.0f * u / width) * 2.0f * z);
}

// The latitude derivative of the zonal profile Z, whose term P Z in the stream function gives
// the zonal winds u = -s P Z'(lat): for `cells` circulation cells per hemisphere (1 .. 3),
//   Z'(lat) = 3 cos(lat) prod_k (1 - z^2 / sin^2(90 deg k / cells)),  k = 1 .. cells - 1,
// easterly (for P > 0) from the equator to the first root, then alternating: 3 cells (Earth:
// Hadley, Ferrel, polar) give trade easterlies below 30 degrees, westerlies from 30 to 60 and
// polar easterlies beyond. Z is the integral, a polynomial of z, so the flow is smooth at the
// poles, where cos(lat) makes the wind vanish. 3 at the equator, as sin 3 lat's derivative.
// cells 0: Z = m, the hemisphere mix itself (sfsim; dm_dlatitude passed in).
float zonal_profile_derivative(float z, float cos_latitude, int cells, float dm_dlatitude) {
  float s = z * z;
  if (cells == 0) return dm_dlatitude;
  if (cells == 2) return 3.0f * cos_latitude * (1.0f - 2.0f * s);
  if (cells == 3) return 3.0f * cos_latitude * (1.0f - 4.0f * s) * (1.0f - s * (4.0f / 3.0f));
  return 3.0f * cos_latitude;
}

// The flow (times s) and, in w, its cyclonic depth (n: unit vector, z north). The stream
// function is
//   phi = P Z + A (-w1 (1 + m)/2 + w2 (1 - m)/2),  m = sin(a lat),  A = storm_track_envelope,
// Z the zonal profile (zonal_profile_derivative).
// w1 and w2 enter with opposite signs, as the Coriolis parameter changes sign at the equator:
// around their peaks (the feature points) the flow turns counter-clockwise in the north and
// clockwise in the south seen from outside, the sense of cyclones. The latitude terms give
// zonal winds u = -s (P Z'(lat) - A m'(lat) (w1 + w2)/2) (plus A's small term); the mix's
// term subtracts the noise mean (the smooth w averages about 0.30 at lambda 0.3, 1 - F1 about
// 0.47) times m', so for the trade winds P Z' must exceed it. The velocity is
//   v = s n x grad phi,
// tangent to the sphere and divergence-free on it. At the poles the direction north is
// undefined; there the latitude terms are dropped. For odd a (the default 3) m is a polynomial
// in z (sin 3 lat = 3z - 4z^3) and the term vanishes there smoothly; otherwise the mix has a
// conical tip at the poles and the flow a singular spin (docs/algorithm.md, "Poles").
// The cyclonic depth c = A (w1 (1 + m)/2 + w2 (1 - m)/2) is the stream function's vortex
// part with the sign of the Coriolis parameter: a geostrophic stream function is the pressure
// anomaly over rho f, so c is largest in the lows (the cyclones) and smallest in the highs;
// the density pass adds it to tie cloudiness to the cyclones (docs/climate.md).
// w1 and w2 are smooth_worley_fbm with lambda = params.smoothing (0: 1 - F1, whose gradient
// jumps across Voronoi borders).
// `offset` shifts the noise of both potentials (sphere radii): they are sampled at n + offset.
// The host keeps it below one lattice period (docs/numerics.md, "Far offsets"), so that float
// keeps its precision however far the user's offset is.
// The flow of the potentials w1 and w2 (each vec4(gradient, value) at n): curl_flow_shifted's
// formula, shared with the flow that moves (moving_flow.glsl), whose potentials change in time.
vec4 curl_flow_of_potentials(vec3 n, vec4 w1, vec4 w2, IN(CurlParams) params) {
  float z = clamp(n.z, -1.0f, 1.0f);
  float latitude = portable_asin(z);
  float a = params.mix_frequency;
  float m = sin(a * latitude);
  float dm_dlatitude = a * cos(a * latitude);
  vec3 north = vec3(0.0f, 0.0f, 1.0f) - z * n;
  float north_length = length(north);  // cos(latitude)
  north = north_length > 1.0e-6f ? north / north_length : vec3(0.0f);
  // The tracks follow the season (--month): A(z - s) moves both north by about s / cos 50 deg.
  vec2 envelope = storm_track_envelope(z - params.storm_track_shift, params.storm_tracks);
  float vortices = 0.5f * (1.0f - m) * w2.w - 0.5f * (1.0f + m) * w1.w;
  float zonal = zonal_profile_derivative(z, north_length, params.zonal_cells, dm_dlatitude);
  vec3 gradient = envelope.x * ((0.5f * (1.0f - m)) * vec3(w2) - (0.5f * (1.0f + m)) * vec3(w1)) +
                  (params.prevailing * zonal - envelope.x * 0.5f * (w1.w + w2.w) * dm_dlatitude +
                   envelope.y * north_length * vortices) *
                      north;
  float cyclonic = envelope.x * (0.5f * (1.0f + m) * w1.w + 0.5f * (1.0f - m) * w2.w);
  return vec4(params.strength * cross(n, gradient), cyclonic);
}

vec4 curl_flow_shifted(vec3 n, IN(CurlParams) params, vec3 offset) {
  return curl_flow_of_potentials(n, smooth_worley_fbm(n + offset, params.potential_north, params.smoothing),
                                 smooth_worley_fbm(n + offset, params.potential_south, params.smoothing), params);
}

vec3 curl_velocity_shifted(vec3 n, IN(CurlParams) params, vec3 offset) {
  return vec3(curl_flow_shifted(n, params, offset));
}

vec3 curl_velocity(vec3 n, IN(CurlParams) params) {
  return curl_velocity_shifted(n, params, vec3(0.0f));
}

#endif
