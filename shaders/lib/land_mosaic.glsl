// The land below the day map's and the relief map's texels, seen from orbit (docs/orbit_view.md,
// "The land's mosaic"). A day map of 20 km texels paints the land in smooth washes; from low orbit
// (pixels of 0.5 km) photographs show woods and open land in patches of a few km, and hills and
// ridges under a low sun. Each texel's colour is taken as a mix of forest and open farmland in the
// share its brightness implies, and a fractal field on the sphere places the forest inside it, so
// that the mosaic's mean over a texel stays the map's colour. Arid land keeps the map's hue and
// varies in brightness; ice keeps the map's colour. The same field, taken as ridged heights, gives
// the relief's slopes below the relief map's texels, as rough as the map around: the woods stand
// on the hills.
#ifndef NEPHELE_LAND_MOSAIC_GLSL
#define NEPHELE_LAND_MOSAIC_GLSL
#include "prelude.glsl"
#include "hash.glsl"
#include "perlin.glsl"
#include "cloud_properties.glsl"
#include "land_cover.glsl"

// The field: three octaves of gradient noise, 12 km, 4 km and 1.3 km, each fading to its mean
// where the footprint grows past it (land_cover.glsl's pattern_detail).
const float MOSAIC_WAVELENGTH = 12000.0f;  // m, the largest patches' wavelength
const float MOSAIC_OCTAVE_RATIO = 3.0f;
const int MOSAIC_OCTAVES = 3;
// The octaves' weights in the forest's field, falling by 0.7 an octave, the finer ones strong
// enough to fray the woods. The field goes on below the finest octave drawn with the same law:
// those octaves (sum of squares 0.25^2 x 0.49 / (1 - 0.49) = 0.06) are never drawn, but the woods
// they would make inside a footprint set how much of it is forest (mosaic_forest).
const vec3 MOSAIC_WEIGHTS = vec3(0.5f, 0.35f, 0.25f);
const float MOSAIC_TAIL_VARIANCE = 0.0600490f;
// The default day map's open farmland: the linear luminance of NASA's Blue Marble (xplanet's
// earth.jpg) over the Beauce (48.2 N, 1.5 E, 5 x 5 texels), the brightest of Europe's farmland.
const float MOSAIC_OPEN_LUMINANCE = 0.116f;
// The forest's share stays inside these bounds: every texel keeps some of both.
const float MOSAIC_FOREST_MIN = 0.1f;
const float MOSAIC_FOREST_MAX = 0.9f;
// Arid land's brightness below a texel: the standard deviation of its factor.
const float MOSAIC_ARID_SPREAD = 0.12f;
// Open land's patchwork (fields of different crops and stages, grouped by farms and soils): the
// standard deviation of its brightness, and the pattern's wavelength (m).
const float MOSAIC_FIELD_SPREAD = 0.15f;
const float MOSAIC_FIELD_WAVELENGTH = 2500.0f;
// A day map whose texels are finer than this resolves the mosaic itself and gets none; from twice
// this the whole mosaic.
const float MOSAIC_MIN_DAY_TEXEL = 3000.0f;
// Hurst exponent of the Earth's relief: its power spectrum falls as k^-beta with beta about 2.1
// from tens of metres to thousands of km (Gagnon, Lovejoy and Schertzer 2006, "Multifractal earth
// topography", Nonlin. Processes Geophys. 13), H = (beta - 1) / 2, so that slopes measured over a
// lag l grow as l^(H - 1) towards small lags.
const float RELIEF_HURST = 0.55f;

// Rec. 709 luminance of linear RGB.
float mosaic_luminance(vec3 c) { return dot(c, vec3(0.2126f, 0.7152f, 0.0722f)); }

// Forest's albedo over open farmland's in summer, per channel (land_cover.glsl's albedos, after
// Oke 1987): about 0.43 in red and green, 0.55 in blue.
vec3 forest_contrast() { return LAND_FOREST / field_mean_albedo(1.0f); }

// The forest's share of a vegetated texel of linear colour `day`: the mix of open farmland (the
// map's MOSAIC_OPEN_LUMINANCE) and forest (forest_contrast of it) that has the texel's luminance.
float mosaic_forest_share(vec3 day) {
  float r = mosaic_luminance(LAND_FOREST) / mosaic_luminance(field_mean_albedo(1.0f));
  float share = (1.0f - mosaic_luminance(day) / MOSAIC_OPEN_LUMINANCE) / (1.0f - r);
  return clamp(share, MOSAIC_FOREST_MIN, MOSAIC_FOREST_MAX);
}

// How much of the land is vegetated, by the texel's hue: green above red (the map's forests and
// farmland: (G - R) / (G + R) 0.1-0.4; its deserts and dry steppe -0.2-0).
float mosaic_vegetation(vec3 day) {
  float greenness = (day.g - day.r) / max(day.g + day.r, 1e-4f);
  return smoothstep(0.0f, 0.1f, greenness);
}

// The field's octave k (0 the largest; 3 the fields' patchwork) and its gradient at p, in its
// lattice units: (gradient, value).
vec4 mosaic_octave(vec3 p, int k) { return perlin_noise_gradient(p, noise_key(0x4d4f5341u, uint(k))); }

// The field and the relief at a point of the ground.
struct MosaicSample {
  float value;       // the forest's field as drawn: woods where it is high
  float deviation;   // its standard deviation over the octaves drawn
  float unresolved;  // and that of the rest of the field, faded or never drawn, inside the footprint
  vec2 relief;       // the relief's slopes below the relief map's texels (east, north; m/m)
};

// The field and the relief at the unit vertical `up` of a planet of `radius` (m), seen with a
// footprint (m), where the relief map's slopes have the root mean square `roughness` over its
// texels (`relief_texel` m) around. The relief: each octave as ridged heights (-|noise|, Musgrave's
// ridged fractal: crests where the noise changes sign) whose slopes have the root mean square of a
// self-affine surface's over a lag of the octave's wavelength, roughness (wavelength /
// lag)^(RELIEF_HURST - 1), the map's lag being its central differences' two texels; none where the
// map is flat (the sea) or at the poles.
MosaicSample mosaic_sample(vec3 up, float radius, float footprint, float roughness, float relief_texel) {
  MosaicSample s;
  s.value = 0.0f;
  s.deviation = 0.0f;
  s.unresolved = 0.0f;
  s.relief = vec2(0.0f);
  vec3 east = vec3(-up.y, up.x, 0.0f);
  float east_length = length(east);
  east = east_length > 1e-6f ? east / east_length : vec3(0.0f);
  vec3 north = cross(up, east);
  float variance = 0.0f, unresolved = MOSAIC_TAIL_VARIANCE;
  float wavelength = MOSAIC_WAVELENGTH;
  for (int k = 0; k < MOSAIC_OCTAVES; ++k) {
    float detail = pattern_detail(footprint, wavelength);
    unresolved += MOSAIC_WEIGHTS[k] * MOSAIC_WEIGHTS[k] * (1.0f - detail * detail);
    if (detail > 0.0f) {
      vec4 octave = mosaic_octave(up * (radius / wavelength), k);
      float w = MOSAIC_WEIGHTS[k] * detail;
      s.value += w * octave.w;
      variance += w * w;
      // Lattice units per m are 1 / wavelength; the octave's slopes scaled to the steepness.
      float steepness = roughness * pow(wavelength / (2.0f * relief_texel), RELIEF_HURST - 1.0f);
      vec2 gradient = vec2(dot(vec3(octave), east), dot(vec3(octave), north));
      s.relief -= sign(octave.w) * detail * steepness / PERLIN_GRADIENT_SIGMA * gradient;
    }
    wavelength /= MOSAIC_OCTAVE_RATIO;
  }
  s.deviation = PERLIN_OCTAVE_SIGMA * sqrt(variance);
  s.unresolved = PERLIN_OCTAVE_SIGMA * sqrt(unresolved);
  return s;
}

// The forest's share of the footprint at a point of the field where the texel's share is
// `share`: the whole field (drawn and unresolved) lies above its (1 - share) quantile there, the
// field taken as normal (a sum of octaves of gradient noise is close to normal). With the drawn
// value v and the unresolved part's deviation u, that is Phi((v - t) / u) for the threshold t of
// the whole field's deviation: over the texel the mean is the share, whatever the footprint, and
// the woods' edges are as soft as the footprint's unseen woods make them.
float mosaic_forest(IN(MosaicSample) s, float share) {
  float whole = sqrt(s.deviation * s.deviation + s.unresolved * s.unresolved);
  float threshold = whole * normal_quantile(1.0f - share);
  return normal_cdf((s.value - threshold) / s.unresolved);
}

// The factor (per channel) by which the land's albedo at the unit vertical `up` of a planet of
// `radius` (m) differs from its day-map texel's linear colour day.rgb (day.a: the share that is
// not ice), seen with a footprint (m) from a map of texels `day_texel` (m) wide, at the field's
// sample s there: the vegetated texel split into forest and open land, arid land brighter and
// darker; 1 where the footprint spans the largest patches, or the map resolves them.
vec3 land_mosaic(vec3 up, vec4 day, float radius, float footprint, float day_texel, IN(MosaicSample) s) {
  float strength = pattern_detail(footprint, MOSAIC_WAVELENGTH) * day.a *
                   clamp(day_texel / MOSAIC_MIN_DAY_TEXEL - 1.0f, 0.0f, 1.0f);
  if (strength <= 0.0f) return vec3(1.0f);
  // Forest and open land in the texel's shares: open c / (1 - F + F r), forest r c / (...).
  float share = mosaic_forest_share(vec3(day));
  vec3 r = forest_contrast();
  vec3 open_factor = vec3(1.0f) / (vec3(1.0f - share) + share * r);
  float fields = 1.0f;
  float field_detail = pattern_detail(footprint, MOSAIC_FIELD_WAVELENGTH);
  if (field_detail > 0.0f)
    fields += field_detail * MOSAIC_FIELD_SPREAD / PERLIN_OCTAVE_SIGMA *
              mosaic_octave(up * (radius / MOSAIC_FIELD_WAVELENGTH), 3).w;
  vec3 vegetated = mix(fields * open_factor, r * open_factor, mosaic_forest(s, share));
  float arid = max(1.0f + MOSAIC_ARID_SPREAD * s.value / max(s.deviation, 1e-6f), 0.5f);
  vec3 factor = mix(vec3(arid), vegetated, mosaic_vegetation(vec3(day)));
  return mix(vec3(1.0f), factor, strength);
}

#endif
