// Sun glint: the sunlight the wind-roughened sea reflects towards the viewer, for the orbit view
// (docs/orbit_view.md, "Sun glint"). The sea is a surface of facets whose slopes are Gaussian
// with the mean square slope Cox and Munk measured from photographs of the glint against the
// wind speed (Cox, C. and Munk, W. 1954, "Measurement of the roughness of the sea surface from
// photographs of the sun's glitter", J. Opt. Soc. Am. 44, 838-850: sigma^2 = 0.003 + 0.00512 U,
// isotropic form, U the wind 12.5 m above the sea in m/s); each facet reflects by Fresnel's
// law for water (refractive index 1.334).
#ifndef NEPHELE_SUN_GLINT_GLSL
#define NEPHELE_SUN_GLINT_GLSL
#include "prelude.glsl"
#include "perlin.glsl"

const float WATER_REFRACTIVE_INDEX = 1.334f;

// The sea's own colour, seen from above where the sun does not glint: the light that the water
// scatters back up through the surface, as a diffuse albedo at the RGB channels' 680, 550 and
// 440 nm, pi times the remote-sensing reflectance Rrs of open-ocean water of about 0.1 to 0.3 mg
// m^-3 of chlorophyll (Rrs about 0.0002, 0.0018 and 0.007 per steradian: Morel, A. and
// Maritorena, S. 2001, "Bio-optical properties of oceanic waters: a reappraisal", J. Geophys.
// Res. 106, 7163-7180): deep blue and dark, as the open ocean is in photographs from orbit.
const vec3 SEA_BODY_ALBEDO = vec3(0.0006f, 0.0057f, 0.022f);
// The share of the sky's diffuse light that the surface mirrors (Fresnel's law for water averaged
// over a uniform sky: 0.066; Payne, R. E. 1972, "Albedo of the sea surface", J. Atmos. Sci. 29,
// 959-970, measured 0.06 to 0.07 under overcast skies).
const float SEA_SKY_REFLECTANCE = 0.066f;

// The wind over the sea varies from place to place, and the glint with it: calm water mirrors
// the sun in a small bright spot, a rough sea spreads it wide and dim. The wind field here is a
// vector of two independent fBm of Perlin noise (three octaves, 400 to 100 km, the amplitude
// falling by 2^(-5/6) an octave: the mesoscale wind's k^(-5/3) spectrum, Nastrom and Gage 1985),
// whose length is the speed. For Gaussian components of zero mean the speed is Rayleigh
// distributed, the Weibull distribution of shape 2 that sea-surface wind speeds roughly follow
// (Monahan 2006); scaled so that its mean is the given mean wind.
const int SEA_WIND_OCTAVES = 3;
const float SEA_WIND_WAVELENGTH = 400000.0f;  // m, the first octave's
const float SEA_WIND_GAIN = 0.56123f;         // 2^(-5/6)

// The wind speed (m/s) over the sea at p (m from the planet's centre; points on one radius get
// the same value), for a mean wind `mean_wind`.
float sea_wind_speed(vec3 p, float mean_wind) {
  vec2 wind = vec2(0.0f);
  float amplitude = 1.0f, variance = 0.0f, wavelength = SEA_WIND_WAVELENGTH;
  for (int k = 0; k < SEA_WIND_OCTAVES; ++k) {
    vec3 q = p / wavelength;
    wind += amplitude * vec2(perlin_noise(q, ivec3(0), uvec3(uint(k), 0x51a7u, 0x3e11u)),
                             perlin_noise(q, ivec3(0), uvec3(uint(k), 0x51a7u, 0x9d2fu)));
    variance += amplitude * amplitude;
    amplitude *= SEA_WIND_GAIN;
    wavelength *= 0.5f;
  }
  // Rayleigh: a Gaussian vector of component deviation sigma has mean length sigma sqrt(pi / 2).
  float sigma = PERLIN_OCTAVE_SIGMA * sqrt(variance);
  return mean_wind * length(wind) / (sigma * 1.2533141f);
}

// The mean square slope of the sea surface (both directions together) at wind speed `wind` m/s.
float sea_slope_variance(float wind) { return 0.003f + 0.00512f * max(wind, 0.0f); }

// Fresnel reflectance of water for unpolarised light arriving at cos(incidence) = cos_i
// (the mean of the s and p reflectances; air to water, so no total reflection).
float water_fresnel(float cos_i) {
  float c = clamp(cos_i, 0.0f, 1.0f);
  float n = WATER_REFRACTIVE_INDEX;
  float sin_t2 = (1.0f - c * c) / (n * n);
  float cos_t = sqrt(max(1.0f - sin_t2, 0.0f));
  float rs = (c - n * cos_t) / (c + n * cos_t);
  float rp = (n * c - cos_t) / (n * c + cos_t);
  return 0.5f * (rs * rs + rp * rp);
}

// The probability density of facet slopes (z_x, z_y) = tan(beta) (cos, sin): isotropic Gaussian
// exp(-tan^2 beta / sigma^2) / (pi sigma^2), per unit of slope squared.
float sea_slope_density(float tan2_beta, float variance) { return exp(-tan2_beta / variance) / (3.14159265358979f * variance); }

// The sea's glint BRDF (1/sr) for unit vectors `up` (the local vertical), `view` (towards the
// viewer) and `sun` (towards the sun): the facets whose normal is the half vector h reflect the
// sun into the view, rho(view . h) p(tan beta) / (4 mu mu0 cos^4 beta), with mu = up . view,
// mu0 = up . sun and cos beta = up . h (Cox and Munk 1954, eq. 3; the form of Nakajima and
// Tanaka 1983 and of the 6S code's glint). 0 below the horizon of either direction.
float sun_glint_brdf(vec3 up, vec3 view, vec3 sun, float wind) {
  float mu = dot(up, view), mu0 = dot(up, sun);
  if (mu <= 0.0f || mu0 <= 0.0f) return 0.0f;
  vec3 h = normalize(view + sun);
  float cos_beta = dot(up, h);
  if (cos_beta <= 0.0f) return 0.0f;
  float cos2 = cos_beta * cos_beta;
  float tan2 = (1.0f - cos2) / cos2;
  float density = sea_slope_density(tan2, sea_slope_variance(wind));
  return water_fresnel(dot(view, h)) * density / (4.0f * mu * mu0 * cos2 * cos2);
}

#endif
