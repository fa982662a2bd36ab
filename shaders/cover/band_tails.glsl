// The densities' tails per latitude band (src/cover/coverage_threshold.cpp, band_tails): for each
// band the share of its solid angle denser than each coarse bin's lower edge, from the
// calibration's histogram (band_bins bins over [min, max]); one band for --profile flat. A
// texel's rank among its band's cloudy texels comes from them (cloud_properties.glsl,
// cloudy_rank), blended linearly between the two band centres around it as the thresholds are.
#include "../lib/latitude_bands.glsl"

layout(std430, binding = 10) readonly buffer BandTails { float band_tail[]; };
uniform int u_tail_bands;
uniform float u_tail_min;    // the histogram's smallest density
uniform float u_tail_scale;  // its bins per unit density (0: every density in bin 0)
const int tail_bins = 256;   // cover::band_bins

// The share of `band` denser than `density`, linear inside a bin (its texels spread evenly).
float tail_in_band(int band, float density) {
  float x = clamp((density - u_tail_min) * u_tail_scale, 0.0f, float(tail_bins));
  int k = min(int(x), tail_bins - 1);
  int at = band * (tail_bins + 1) + k;
  return mix(band_tail[at], band_tail[at + 1], x - float(k));
}

float density_tail(vec3 direction, float density) {
  float c = band_coordinate(direction, u_tail_bands);
  ivec4 k = band_neighbours(c, u_tail_bands);
  return mix(tail_in_band(k.y, density), tail_in_band(k.z, density), band_fraction(c, u_tail_bands));
}
