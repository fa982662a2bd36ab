// Equirectangular (plate carree) columns: longitude -180 deg at the left edge of column 0,
// pixel centres at (i + 0.5) / width of the full turn.
#ifndef NEPHELE_EQUIRECT_MAPPING_GLSL
#define NEPHELE_EQUIRECT_MAPPING_GLSL
#include "prelude.glsl"

float equirect_longitude(int column, int width) {
  return (2.0f * 3.14159265358979f) * ((float(column) + 0.5f) / float(width)) - 3.14159265358979f;
}

// Direction for a column and a row's (cos, sin) of geocentric latitude, in ECEF axes.
vec3 equirect_direction(int column, int width, vec2 latitude_cos_sin) {
  float longitude = equirect_longitude(column, width);
  return vec3(latitude_cos_sin.x * cos(longitude), latitude_cos_sin.x * sin(longitude),
              latitude_cos_sin.y);
}

#endif
