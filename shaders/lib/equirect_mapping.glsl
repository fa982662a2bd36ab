// Equirectangular (plate carree) columns: longitude -180 deg at the left edge of column 0,
// pixel centres at (i + 0.5) / width of the full turn.
#ifndef NEPHELE_EQUIRECT_MAPPING_GLSL
#define NEPHELE_EQUIRECT_MAPPING_GLSL
#include "prelude.glsl"
#include "portable_math.glsl"

float equirect_longitude(int column, int width) {
  return (2.0f * 3.14159265358979f) * ((float(column) + 0.5f) / float(width)) - 3.14159265358979f;
}

// Direction for a column and a row's (cos, sin) of geocentric latitude, in ECEF axes.
vec3 equirect_direction(int column, int width, vec2 latitude_cos_sin) {
  float longitude = equirect_longitude(column, width);
  return vec3(latitude_cos_sin.x * cos(longitude), latitude_cos_sin.x * sin(longitude),
              latitude_cos_sin.y);
}

// Texture coordinates of a unit direction in such a map (ECEF axes, z north): longitude -180
// deg at u = 0, north at v = 0; the inverse of the two above, up to the rows' geodetic latitude.
vec2 equirect_uv(vec3 n) {
  float longitude = atan(n.y, n.x);
  float latitude = portable_asin(clamp(n.z, -1.0f, 1.0f));  // drivers' asin differs near the poles
  return vec2(longitude / (2.0f * 3.14159265358979f) + 0.5f, 0.5f - latitude / 3.14159265358979f);
}

#endif
