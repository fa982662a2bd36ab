// Probe of lib/atmosphere.glsl (shared GLSL/C++ subset; tests/test_library_probes.cpp).
// Lengths in metres; x[0] = (function, earth radius, a, b), x[1..3] points and directions. The
// GLSL side reads the multiple-scattering table bound to texture unit 4 and the transmittance
// table bound to unit 5.
// The functions (x[0].x):
const int PROBE_RAYLEIGH = 0;  // rayleigh_scattering, rayleigh_phase
const int PROBE_SUN_AND_HENYEY_GREENSTEIN = 1;  // solar_irradiance, henyey_greenstein
const int PROBE_AIR_EXTINCTION = 2;
const int PROBE_TRANSMITTANCE_TO_SPACE = 3;
const int PROBE_SKY_SINGLE_SCATTERING = 4;
const int PROBE_SKY_INTEGRAL_STEPS = 5;  // sky_integral_begin, _point, _step, _end
const int PROBE_SKYLIGHT = 6;  // the integral with the sun hidden and the skylight x[0].w (grey)
const int PROBE_SKY_AMBIENT = 7;  // sky_ambient(x[1], x[2])
const int PROBE_OZONE = 8;  // ozone_absorption (scaled by 1e6), ozone_density(a)
const int PROBE_AIR_SCATTERING_AND_CORNETTE_SHANKS = 9;  // air_scattering(a) (1e5), cornette_shanks(x[1].x, x[1].y)
const int PROBE_MULTIPLE_SCATTERING_TRANSFER = 10;  // at altitude a, sun cosine b, albedo x[1].x, counts x[1].yzw (1e3)
const int PROBE_MULTIPLE_SCATTERING_TABLE_ENTRY = 11;  // texel (a, b), albedo x[1].x (1e3)
const int PROBE_MULTIPLE_SCATTERING = 12;  // the table at point x[1], sun x[2] (1e3)
const int PROBE_SKY_SCATTERING = 13;  // sky_scattering as PROBE_SKY_SINGLE_SCATTERING
const int PROBE_TRANSMITTANCE_TABLE_ENTRY = 14;  // texel (a, b)
const int PROBE_TRANSMITTANCE_FROM_TABLE = 15;  // the table from x[1] along x[2]
const int PROBE_TRANSMITTANCE_TABLE_UV = 16;  // the coordinates of r = a, mu = b
const int PROBE_OPTICAL_DEPTH_TO_TOP = 17;  // from x[1] along x[2] in int(a) steps (1e3)
const int PROBE_TABLE_COORDINATE = 18;  // table_coordinate(a, int(b))
const int PROBE_SKY_STEPS_IN_SUNLIGHT = 19;  // as PROBE_SKY_INTEGRAL_STEPS, the sun's transmittance b at every step
#ifndef __cplusplus
layout(binding = 4) uniform sampler2D probe_sky_table;
layout(binding = 5) uniform sampler2D probe_transmittance_table;
#include "../lib/atmosphere.glsl"
#endif
vec4 probe_atmosphere(mat4 x, IN(ScatteringTable) table, IN(TransmittanceTable) transmittance) {
  int f = int(x[0].x);
  float earth_radius = x[0].y;
  if (f == PROBE_RAYLEIGH) return vec4(rayleigh_scattering() * 1.0e5f, rayleigh_phase(x[0].z));
  if (f == PROBE_SUN_AND_HENYEY_GREENSTEIN) return vec4(solar_irradiance(), henyey_greenstein(x[0].z, x[0].w));
  if (f == PROBE_SKY_AMBIENT) return vec4(sky_ambient(vec3(x[1]), vec3(x[2])), 0.0f);
  if (f == PROBE_AIR_EXTINCTION) return vec4(air_extinction(x[0].z) * 1.0e5f, 0.0f);
  if (f == PROBE_OZONE) return vec4(ozone_absorption() * 1.0e6f, ozone_density(x[0].z));
  if (f == PROBE_AIR_SCATTERING_AND_CORNETTE_SHANKS)
    return vec4(air_scattering(x[0].z) * 1.0e5f, cornette_shanks(x[1].x, x[1].y));
  if (f == PROBE_MULTIPLE_SCATTERING_TRANSFER)
    return vec4(multiple_scattering_transfer(transmittance, x[0].z, x[0].w, earth_radius, x[1].x, int(x[1].y), int(x[1].z),
                                             int(x[1].w)) * 1.0e3f, 0.0f);
  if (f == PROBE_MULTIPLE_SCATTERING_TABLE_ENTRY)
    return vec4(multiple_scattering_table_entry(transmittance, int(x[0].z), int(x[0].w), earth_radius, x[1].x) * 1.0e3f, 0.0f);
  if (f == PROBE_MULTIPLE_SCATTERING)
    return vec4(multiple_scattering(table, vec3(x[1]), vec3(x[2]), earth_radius) * 1.0e3f, 0.0f);
  if (f == PROBE_TRANSMITTANCE_TO_SPACE)
    return vec4(transmittance_to_space(vec3(x[1]), vec3(x[2]), earth_radius), 0.0f);
  if (f == PROBE_TRANSMITTANCE_TABLE_ENTRY)
    return vec4(transmittance_table_entry(int(x[0].z), int(x[0].w), earth_radius), 0.0f);
  if (f == PROBE_TRANSMITTANCE_FROM_TABLE)
    return vec4(transmittance_from_table(transmittance, vec3(x[1]), vec3(x[2]), earth_radius), 0.0f);
  if (f == PROBE_TRANSMITTANCE_TABLE_UV) return vec4(transmittance_table_uv(x[0].z, x[0].w, earth_radius), 0.0f, 0.0f);
  if (f == PROBE_OPTICAL_DEPTH_TO_TOP)
    return vec4(optical_depth_to_top(vec3(x[1]), vec3(x[2]), earth_radius, int(x[0].z)) * 1.0e3f, 0.0f);
  if (f == PROBE_TABLE_COORDINATE) return vec4(table_coordinate(x[0].z, int(x[0].w)));
  if (f == PROBE_SKY_STEPS_IN_SUNLIGHT) {
    SkyIntegral s = sky_integral_begin(vec3(x[2]), x[1].w, x[2].w, vec3(x[3]), int(x[3].w));
    for (int i = 0; i < int(x[3].w); ++i)
      sky_integral_step_in_sunlight(s, sky_integral_point(s, vec3(x[1]), vec3(x[2]), i), i, vec3(x[0].w), earth_radius,
                                    1.0f);
    vec3 total, split, transmittance, transmittance_split;
    sky_integral_end(s, total, split, transmittance, transmittance_split);
    return vec4((x[0].z == 0.0f ? total : split) * 1.0e3f, transmittance.y);
  }
  if (f == PROBE_SKY_INTEGRAL_STEPS) {
    // The same integral step by step with the sun's share x[0].w at the odd steps (1 at the
    // others): the in-scattering of part x[0].z (0 total, 1 split, scaled by 1e3) and the total
    // transmittance's green.
    SkyIntegral s = sky_integral_begin(vec3(x[2]), x[1].w, x[2].w, vec3(x[3]), int(x[3].w));
    for (int i = 0; i < int(x[3].w); ++i) {
      sky_integral_step(s, sky_integral_point(s, vec3(x[1]), vec3(x[2]), i), i, vec3(x[3]), earth_radius,
                        i % 2 == 1 ? x[0].w : 1.0f);
    }
    vec3 total, split, transmittance, transmittance_split;
    sky_integral_end(s, total, split, transmittance, transmittance_split);
    return vec4((x[0].z == 0.0f ? total : split) * 1.0e3f, transmittance.y);
  }
  if (f == PROBE_SKYLIGHT) {
    // From x[1] along x[2] over x[1].w metres in int(x[3].w) steps, the sun x[3] hidden at every
    // step: the in-scattering of the skylight alone (scaled by 1e3) and the green transmittance.
    SkyIntegral s = sky_integral_begin(vec3(x[2]), x[1].w, 0.0f, vec3(x[3]), int(x[3].w));
    s.skylight = vec3(x[0].w);
    for (int i = 0; i < int(x[3].w); ++i)
      sky_integral_step(s, sky_integral_point(s, vec3(x[1]), vec3(x[2]), i), i, vec3(x[3]), earth_radius, 0.0f);
    vec3 total, split, transmittance, transmittance_split;
    sky_integral_end(s, total, split, transmittance, transmittance_split);
    return vec4(total * 1.0e3f, transmittance.y);
  }
  // PROBE_SKY_SINGLE_SCATTERING: sky_single_scattering from x[1] along x[2] over x[1].w metres
  // (split at x[2].w) towards the sun x[3] with int(x[3].w) steps; x[0].z picks which of its four
  // results to return (radiances scaled by 1e3 to order one).
  // PROBE_SKY_SCATTERING: the same with the table's multiple scattering.
  vec3 inscatter_total;
  vec3 inscatter_split;
  vec3 transmittance_total;
  vec3 transmittance_split;
  if (f == PROBE_SKY_SCATTERING)
    sky_scattering(table, transmittance, vec3(x[1]), vec3(x[2]), x[1].w, x[2].w, vec3(x[3]), earth_radius,
                   int(x[3].w), inscatter_total, inscatter_split, transmittance_total, transmittance_split);
  else
    sky_single_scattering(vec3(x[1]), vec3(x[2]), x[1].w, x[2].w, vec3(x[3]), earth_radius, int(x[3].w),
                          inscatter_total, inscatter_split, transmittance_total, transmittance_split);
  int part = int(x[0].z);
  if (part == 0) return vec4(inscatter_total * 1.0e3f, 0.0f);
  if (part == 1) return vec4(inscatter_split * 1.0e3f, 0.0f);
  if (part == 2) return vec4(transmittance_total, 0.0f);
  return vec4(transmittance_split, 0.0f);
}
#ifndef __cplusplus
vec4 probe_atmosphere(mat4 x) { return probe_atmosphere(x, probe_sky_table, probe_transmittance_table); }
#endif
