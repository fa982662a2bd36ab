// Latitude bands of the coverage profile (docs/climate.md): `bands` equal bands from the south
// pole to the north pole, a threshold per band, and a threshold that varies smoothly with
// latitude between the band centres (Catmull-Rom, C1; mirrored across the poles).
#ifndef NEPHELE_LATITUDE_BANDS_GLSL
#define NEPHELE_LATITUDE_BANDS_GLSL
#include "prelude.glsl"
#include "portable_math.glsl"

// Position of a unit direction's latitude in band centres: 0 at the centre of the southernmost
// band, bands - 1 at the northernmost, -0.5 and bands - 0.5 at the poles. portable_asin keeps
// the GPU and the C++ twin within float rounding of each other.
float band_coordinate(vec3 direction, int bands) {
  float latitude = portable_asin(clamp(direction.z, -1.0f, 1.0f));
  return (latitude + 1.5707963268f) * (float(bands) / 3.14159265358979f) - 0.5f;
}

// The band a coordinate lies in (the band of a texel is that of its centre).
int band_of(float coordinate, int bands) {
  return clamp(int(floor(coordinate + 0.5f)), 0, bands - 1);
}

// The four band centres around a coordinate, k - 1 .. k + 2 for k = floor(c), mirrored at the
// poles (band -1 is band 0, -2 is band 1, and so on), so that the interpolated threshold is
// even about each pole: its slope there is 0 and the curve is C1 across it.
ivec4 band_neighbours(float coordinate, int bands) {
  int k = int(floor(clamp(coordinate, -0.5f, float(bands) - 0.5f)));
  ivec4 index = ivec4(k - 1, k, k + 1, k + 2);
  ivec4 low = ivec4(-1) - index;                // mirror of negative indices
  ivec4 high = ivec4(2 * bands - 1) - index;    // mirror of indices >= bands
  index = ivec4(index.x < 0 ? low.x : index.x, index.y < 0 ? low.y : index.y,
                index.z < 0 ? low.z : index.z, index.w < 0 ? low.w : index.w);
  return ivec4(index.x >= bands ? high.x : index.x, index.y >= bands ? high.y : index.y,
               index.z >= bands ? high.z : index.z, index.w >= bands ? high.w : index.w);
}

// Catmull-Rom weights of the values at k - 1, k, k + 1, k + 2 for t = c - floor(c) in [0, 1]:
// the cubic through the two middle values with the slopes of the central differences (C1, and
// exact for linear data). The weights sum to 1.
vec4 catmull_rom_weights(float t) {
  float t2 = t * t;
  float t3 = t2 * t;
  return vec4(-0.5f * t3 + t2 - 0.5f * t, 1.5f * t3 - 2.5f * t2 + 1.0f, -1.5f * t3 + 2.0f * t2 + 0.5f * t,
              0.5f * t3 - 0.5f * t2);
}

// The fraction t of the coordinate between the centres k and k + 1 of band_neighbours.
float band_fraction(float coordinate, int bands) {
  float c = clamp(coordinate, -0.5f, float(bands) - 0.5f);
  return c - floor(c);
}

#endif
