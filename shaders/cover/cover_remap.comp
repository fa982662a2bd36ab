#version 450
// Pass 4b: density to coverage in [0, 1] with the solid-angle-calibrated threshold: one for
// the sphere (u_bands 0), or one that follows the latitude profile (band_thresholds.glsl).
// With the profile, the pass also adds the cloudy texels' solid angles to their band's sum
// (BandCloudy), the achieved fractions, so that they need no pass of their own: each
// invocation walks a strip of u_strip texels down a column and adds runs of one band at once
// (as the reductions of coverage_histogram.comp).
// The pass also writes the cloud's optical thickness, log-normal by the texel's rank in density
// among its band's cloudy texels (cloud_properties.glsl, band_tails.glsl), and clears the density
// pass's cloud-top height where the texel stays clear: both 0 there. A cloudy texel's cover shows the
// share of its excess over the threshold that the density pass's contrast gives (dim shallow
// cumulus in the trades: cover_density.glsl's cover_contrast).
layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;
layout(r32f, binding = 0) uniform readonly image2DArray density_field;
layout(r32f, binding = 1) uniform writeonly image2DArray cover_field;
layout(r32f, binding = 2) uniform writeonly image2DArray optical_thickness_field;
layout(r32f, binding = 3) uniform image2DArray cloud_top_field;  // km; the density pass's
layout(r32f, binding = 4) uniform readonly image2DArray cover_contrast_field;  // the density pass's
#include "../lib/cover_density.glsl"
#include "../lib/cloud_properties.glsl"
#include "band_tails.glsl"
#include "../lib/cube_faces.glsl"
#include "band_thresholds.glsl"
#include "texel_weights.glsl"
#include "cube_tile.glsl"

uniform float u_threshold;
uniform float u_density_max;
uniform float u_softness;
uniform float u_tau_median;
uniform float u_tau_spread;
// Per band, a 64-bit sum of texel weight units (cleared by the host), as stage 8 of
// coverage_histogram.comp, which measures the same on any density map.
layout(std430, binding = 9) buffer BandCloudy { uint band_cloudy[]; };
uniform int u_strip;

void main() {
  int size = u_face_size;
  int i = int(gl_GlobalInvocationID.x), layer = int(gl_GlobalInvocationID.z);
  int first = u_tile_rows.x + int(gl_GlobalInvocationID.y) * u_strip;
  if (i >= size || first >= u_tile_rows.y) return;
  int last = min(u_tile_rows.y, first + u_strip);
  int run_band = -1;
  uint run_units = 0u;
  for (int j = first; j < last; ++j) {
    ivec3 texel = ivec3(i, j, layer);
    ivec3 at = face_texel(texel);
    float density = imageLoad(density_field, texel).x;
    float threshold = u_threshold;
    vec3 direction = texel_direction(at.z, at.x, at.y, size);
    if (u_bands > 0) {
      threshold = smooth_band_threshold(direction);
      int band = band_of(band_coordinate(direction, u_bands), u_bands);
      // A run is flushed once it reaches 2^31 units; a texel is below 2^31, so the 32-bit run
      // sum never wraps.
      if (density > threshold) {
        if (band != run_band || run_units >= 0x80000000u) {
          if (run_band >= 0) ADD_UNITS64(band_cloudy, run_band, run_units);
          run_band = band;
          run_units = 0u;
        }
        run_units += texel_weight(at.x, at.y, size);
      }
    }
    float contrast = imageLoad(cover_contrast_field, texel).x;
    float cover = contrasted_cover(density, threshold, u_density_max, u_softness, contrast);
    imageStore(cover_field, texel, vec4(cover, 0.0f, 0.0f, 0.0f));
    bool cloudy = density > threshold;
    float tau = cloudy ? optical_thickness_from_rank(
                             cloudy_rank(density_tail(direction, density), density_tail(direction, threshold)),
                             u_tau_median, u_tau_spread)
                       : 0.0f;
    imageStore(optical_thickness_field, texel, vec4(tau, 0.0f, 0.0f, 0.0f));
    if (!cloudy) imageStore(cloud_top_field, texel, vec4(0.0f));
  }
  if (run_band >= 0) ADD_UNITS64(band_cloudy, run_band, run_units);
}
