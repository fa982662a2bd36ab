// The weather systems of the global cover (docs/climate.md, "Weather systems"): extratropical
// cyclones with their comma cloud, the ITCZ's broken line of convective clusters, fields of trade
// cumulus and cirrus streaks. Each is a field in [0, 1] with a flat top and a steep, noise-frayed
// edge; the density pass multiplies the warped noise by 1 + 0.5 w (cover_density.glsl's
// with_systems), so that the calibration, which ranks the densities, lays the systems' cloud first
// and fills each band's remaining target from the noise.
// Positions are radians of arc on the unit sphere (z north); the cyclones' places at a moment are
// the host's (cover/weather_systems.hpp), so that every frame is computed on its own.
#ifndef NEPHELE_WEATHER_SYSTEMS_GLSL
#define NEPHELE_WEATHER_SYSTEMS_GLSL
#include "prelude.glsl"
#include "hash.glsl"
#include "parameters.glsl"
#include "portable_math.glsl"
#include "worley.glsl"
#include "worley_fbm.glsl"
#include "perlin.glsl"
#include "cloud_properties.glsl"

#define MAX_CYCLONES 32

// One extratropical cyclone at a moment. Its frame: x east, y towards the nearer pole, so that the
// southern hemisphere's cyclones are the mirror images of the northern ones (they turn clockwise).
struct Cyclone {
  vec3 centre;     // unit vector of the low's centre
  vec3 east;       // unit tangent east at the centre
  vec3 pole;       // unit tangent towards the nearer pole at the centre
  float radius;    // the comma head's radius, radians of arc
  float wrap;      // how far the head winds around the centre, radians (grows as the low occludes)
  float strength;  // 0 .. 1 over the life cycle (growth, maturity, decay)
};

// The ITCZ is no straight line of evenly spread systems. On any day it meanders by a few degrees
// of latitude, and its clusters gather into superclusters a few thousand km long, separated by
// stretches with little deep convection: the envelopes of convectively coupled waves (easterly
// waves of 2000-4000 km, Reed, Norquist and Recker 1977, "The structure and properties of African
// wave disturbances as observed during Phase III of GATE", Mon. Wea. Rev. 105; superclusters of
// several thousand km in which clusters live and die, Nakazawa 1988, "Tropical super clusters
// within intraseasonal variations over the western Pacific", J. Meteor. Soc. Japan 66; Mapes and
// Houze 1993). Both are functions of longitude along the line: sums of the zonal waves of
// wavenumbers LINE_FIRST_WAVENUMBER to LINE_FIRST_WAVENUMBER + LINE_WAVES - 1 (wavelengths of
// 6700 to 4000 km at the equator; superclusters about 3200 km long on average) with random complex
// amplitudes, `meander` and `envelope`, scaled so that each sum has a root mean square of exactly
// 1 around a latitude circle (the waves are orthogonal there). A term is dot(c, (cos m lon,
// sin m lon)) = |c| cos(m lon - arg c). `applies` 0: no waves (a line at its own latitude, every
// place as active). Evaluated at a system's point, so that each system is present or absent
// whole.
// The monsoons: over land in the summer hemisphere the rain belt follows the sun further from the
// equator than over the oceans (docs/climate.md, "The monsoons"). The host gives the line's shift
// from its mean latitude as a function of longitude, a mean and the zonal waves of wavenumbers 1 to
// MONSOON_WAVES (those whose powers line_waves computes on its way to its own), in sin(latitude),
// fixed to the map (0 without a land mask or a month).
const int LINE_WAVES = 5;
const int LINE_FIRST_WAVENUMBER = 6;
const int MONSOON_WAVES = LINE_FIRST_WAVENUMBER + LINE_WAVES - 1;
struct LineWaves {
  vec2 meander[LINE_WAVES];
  vec2 envelope[LINE_WAVES];
  vec2 monsoon[MONSOON_WAVES];  // the monsoons' shift's waves (sin(latitude)), wavenumbers 1 ..
  float monsoon_mean;           // and its mean
  float monsoon_reach;          // an upper bound of its size anywhere, radians of latitude (and so of sin)
  float meander_z;  // the meander's amplitude in sin(latitude) (its radians times cos(line))
  float dormant;    // the share of places filled outside the superclusters, relative to inside
  float applies;    // 1: the waves apply; 0: none (GLSL reserves "active")
  float spcz;       // the SPCZ's share of places on its line relative to the ITCZ's (spcz_presence; 0: none)
  float spcz_shift;  // its line's seasonal shift, radians of latitude (northward > 0)
};
// The line's meander (radians of latitude for a unit of its sum; the sum clamped to
// +-LINE_MEANDER_LIMIT) and the superclusters: a place is inside one where the envelope's sum
// exceeds 0, outside where it is below -0.6, with a smooth step between (about 0.5, 0.27 and 0.23
// of the line for a Gaussian sum), and outside one ITCZ_DORMANT of the places are filled.
const float ITCZ_MEANDER = 0.026f;  // 1.5 degrees
const float LINE_MEANDER_LIMIT = 2.5f;
const float ITCZ_DORMANT = 0.2f;
const uint ITCZ_WAVES_LAYER = 37u;
LineWaves no_line_waves() {
  LineWaves waves;
  for (int k = 0; k < LINE_WAVES; ++k) {
    waves.meander[k] = vec2(0.0f);
    waves.envelope[k] = vec2(0.0f);
  }
  for (int k = 0; k < MONSOON_WAVES; ++k) waves.monsoon[k] = vec2(0.0f);
  waves.monsoon_mean = 0.0f;
  waves.monsoon_reach = 0.0f;
  waves.meander_z = 0.0f;
  waves.dormant = 1.0f;
  waves.applies = 0.0f;
  waves.spcz = 0.0f;
  waves.spcz_shift = 0.0f;
  return waves;
}
// The waves of `seed` for a line at latitude `line` at time 0: complex amplitudes with components
// uniform in [-1/2, 1/2), normalised so that sum |c|^2 / 2 = 1, and neither monsoons nor SPCZ. The
// host draws them once for a cover, adds the monsoons of its land mask and month (and with a mask
// the SPCZ) and moves them to the frame's time (cover/weather_systems.cpp); the probes draw them here.
LineWaves line_waves_of(uint seed, float line) {
  LineWaves waves = no_line_waves();
  uvec3 key = noise_key(seed, ITCZ_WAVES_LAYER);
  float meander_power = 0.0f, envelope_power = 0.0f;
  for (int k = 0; k < LINE_WAVES; ++k) {
    vec3 a = hash_to_unit3(pcg3d(uvec3(uint(k), 0u, 0u) ^ key)), b = hash_to_unit3(pcg3d(uvec3(uint(k), 1u, 0u) ^ key));
    waves.meander[k] = vec2(a.x, a.y) - vec2(0.5f);
    waves.envelope[k] = vec2(a.z, b.x) - vec2(0.5f);
    meander_power += dot(waves.meander[k], waves.meander[k]);
    envelope_power += dot(waves.envelope[k], waves.envelope[k]);
  }
  float meander_norm = inversesqrt(0.5f * meander_power), envelope_norm = inversesqrt(0.5f * envelope_power);
  for (int k = 0; k < LINE_WAVES; ++k) {
    waves.meander[k] *= meander_norm;
    waves.envelope[k] *= envelope_norm;
  }
  waves.meander_z = ITCZ_MEANDER * cos(line);
  waves.dormant = ITCZ_DORMANT;
  waves.applies = 1.0f;
  return waves;
}
vec2 complex_product(vec2 a, vec2 b) { return vec2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x); }
// The sums at the unit direction p: the meander and the envelope, each of root mean square 1 around
// a latitude circle, and the monsoons' shift in sin(latitude): e^(i m lon) from p's longitude
// without an arctangent, by powers of e^(i lon), each power serving every sum of its wavenumber.
vec3 line_waves(vec3 p, IN(LineWaves) waves) {
  vec2 turn = normalize(vec2(p.x, p.y) + vec2(1.0e-12f, 0.0f));
  vec2 power = turn;
  vec3 sums = vec3(0.0f, 0.0f, waves.monsoon_mean);
  for (int m = 1; m < LINE_FIRST_WAVENUMBER; ++m) {
    sums.z += dot(waves.monsoon[m - 1], power);
    power = complex_product(power, turn);
  }
  for (int k = 0; k < LINE_WAVES; ++k) {
    sums += vec3(dot(waves.meander[k], power), dot(waves.envelope[k], power),
                 dot(waves.monsoon[LINE_FIRST_WAVENUMBER - 1 + k], power));
    power = complex_product(power, turn);
  }
  return sums;
}
// From the sums: the meander in units of its amplitude, the line's shift in sin(latitude) (the
// meander's and the monsoons') and the superclusters' activity in [0, 1].
float line_meander(vec3 sums) { return clamp(sums.x, -LINE_MEANDER_LIMIT, LINE_MEANDER_LIMIT); }
float line_shift(vec3 sums, IN(LineWaves) waves) { return waves.meander_z * line_meander(sums) + sums.z; }
float supercluster_activity(vec3 sums) { return smoothstep(-0.6f, 0.0f, sums.y); }
struct WeatherSystems {
  Cyclone cyclones[MAX_CYCLONES];
  int cyclone_count;
  float itcz_latitude;  // radians, the ITCZ's centre line (follows --month)
  float itcz;           // strength of its convective clusters, 0: none
  LineWaves itcz_waves;  // its meander and superclusters at the moment (the host's line_waves_of, moved)
  float trade_cumulus;  // strength of the trade cumulus fields, 0: none
  float cirrus;         // strength of the cirrus streaks, 0: none
  float shallow_trades;  // strength of the trades' shallow unorganised cloud (cloud_properties.glsl), 0: none
  float cells;          // strength of the stratocumulus decks' and cold air's convective cells, 0: none
  float streets;        // strength of the cold air's cloud streets, 0: none
  uint seed;            // the belts' noise (cluster places, cumulus cells, cirrus); per cloud layer
};

// A band with a flat top and a steep edge: 1 for |offset| up to 0.6 half_width, 0 from half_width.
float band_profile(float offset, float half_width) {
  return 1.0f - smoothstep(0.6f, 1.0f, abs(offset) / half_width);
}

// p in the cyclone's frame, in head radii (x east, y poleward); far away (1e3) on the far side.
vec2 cyclone_frame(vec3 p, IN(Cyclone) cyclone) {
  if (dot(p, cyclone.centre) < 0.5f) return vec2(1.0e3f);
  vec3 d = p - cyclone.centre;
  return vec2(dot(d, cyclone.east), dot(d, cyclone.pole)) / cyclone.radius;
}

// The cold front's band in the cyclone's frame (head radii): from its tail's end, three radii
// equatorward and west of the low, to its join with the head east of the low.
const vec2 COLD_FRONT_TAIL_END = vec2(-0.7f, -3.0f);
const vec2 COLD_FRONT_JOIN = vec2(1.0f, -0.6f);

// The comma cloud of a cyclone in its frame (head radii; the northern hemisphere's orientation),
// after the conceptual model of satellite meteorology (Carlson 1980, "Airflow through midlatitude
// cyclones and the comma cloud pattern", Mon. Wea. Rev. 108; Browning 1997): the cold front's
// band trails from east of the low three radii towards the equator and west, sharp on its rear
// edge where the dry slot follows it; at the join it becomes the head, a logarithmic spiral that
// winds `wrap` radians anticlockwise around the low, broad on its poleward side (the warm front's
// cloud shield) and thinning to the hook. The low's centre and the dry slot are clear. `edge` in
// [-1, 1] (the cover's own noise) moves the band across by up to 0.6 of its half width (breaking
// its narrow rear side where the noise is extreme), so that the edges are as ragged as the noise
// and move with it.
float comma_cloud(vec2 xy, float wrap, float edge) {
  const vec2 tail_end = COLD_FRONT_TAIL_END;
  const vec2 join = COLD_FRONT_JOIN;
  vec2 axis = join - tail_end;
  float along_tail = clamp(dot(xy - tail_end, axis) / dot(axis, axis), 0.0f, 1.0f);
  vec2 from_axis = xy - (tail_end + along_tail * axis);
  vec2 ahead = normalize(vec2(axis.y, -axis.x));  // east-south-east: ahead of the cold front
  float tail_half = mix(0.12f, 0.35f, along_tail);
  float across = (dot(from_axis, ahead) >= 0.0f ? 1.0f : -1.0f) * length(from_axis) + edge * 0.6f * tail_half;
  float tail_width = across > 0.0f ? 1.3f * tail_half : 0.7f * tail_half;
  float tail = band_profile(across, tail_width) * smoothstep(0.0f, 0.2f, along_tail);

  const float two_pi = 6.28318530717959f;
  const float r_hook = 0.3f;
  float r_join = length(join);
  float theta_join = atan(join.y, join.x);
  float k = log(r_join / r_hook) / max(wrap, 0.1f);  // r(phi) = r_join exp(-k phi), phi in [0, wrap]
  float r = max(length(xy), 1.0e-4f);
  float turned = atan(xy.y, xy.x) - theta_join;
  float phi0 = turned - two_pi * floor(turned / two_pi);  // [0, 2 pi)
  float head = 0.0f;
  for (int turn = 0; turn < 2; ++turn) {
    float phi = phi0 - two_pi * float(turn);
    float along = phi / max(wrap, 0.1f);
    if (along < -0.15f || along > 1.0f) continue;
    float half_width = mix(0.45f, 0.2f, clamp(along, 0.0f, 1.0f));
    // > 0: poleward of the arm (the shield)
    float offset = log(r / (r_join * exp(-k * phi))) + edge * 0.6f * half_width;
    float width = offset > 0.0f ? 1.3f * half_width : 0.8f * half_width;
    float arm = band_profile(offset, width) * smoothstep(-0.15f, 0.05f, along) *
                (1.0f - smoothstep(0.75f, 1.0f, along));
    head = max(head, arm);
  }
  return max(tail, head);
}

// A cyclone's cloud at p: its comma scaled by its strength.
float cyclone_cloud(vec3 p, IN(Cyclone) cyclone, float edge) {
  vec2 xy = cyclone_frame(p, cyclone);
  if (dot(xy, xy) > 16.0f) return 0.0f;  // the comma lies within 3.1 head radii of the low
  return cyclone.strength * comma_cloud(xy, cyclone.wrap, edge);
}

// The cyclones whose comma may reach p, within 4 head radii (cyclone_cloud's reach): bit i for
// cyclone i. The loops over the cyclones visit only these (for each set bit, lowest first), so
// that SIMD lanes (llvmpipe) pass through a loop as often as their busiest lane needs, a cyclone
// or two, rather than through every cyclone's comma at every texel.
uint cyclones_near(vec3 p, IN(WeatherSystems) systems) {
  uint near = 0u;
  for (int i = 0; i < systems.cyclone_count && i < MAX_CYCLONES; ++i) {
    vec2 xy = cyclone_frame(p, systems.cyclones[i]);
    if (dot(xy, xy) <= 16.0f) near |= 1u << uint(i);
  }
  return near;
}

// Round clouds in cells of a random lattice (Worley F1): a cell's cloud has a radius of `radius`
// plus up to `spread` (in cells) by the cell's hash, and one cell in `empty` has none. The edge
// is as steep as band_profile's and moved by `edge` (a tenth of a cell at most). `searched` as
// worley_f1_searched's: 0 where the caller draws no cloud (none then).
float cell_clouds(vec3 p, float frequency, uint seed, uint layer, float radius, float spread, float empty,
                  float edge, int searched) {
  vec3 scaled = p * frequency;
  vec4 f1 = worley_f1_searched(scaled, ivec3(0), noise_key(seed, layer), searched);
  // The nearest feature point's cell names the cloud.
  ivec3 cell = nearest_cell(scaled, f1);
  vec3 h = hash_to_unit3(pcg3d(uvec3(cell) ^ noise_key(seed, layer + 1u)));
  if (h.y < empty) return 0.0f;
  float size = radius + spread * h.x;
  return 1.0f - smoothstep(0.6f * size, size, f1.w + 0.1f * edge);
}

// The radius of a convective system from a uniform hash u in [0, 1): tropical convective systems of
// all sizes, from single towers to mesoscale systems 2000 km across, cover about the same area in
// each logarithmic interval of size (Machado and Rossow 1993, "Structural characteristics and
// radiative properties of tropical cloud clusters", Mon. Wea. Rev. 121), so the radii's density is
// r^-3 between r_min and r_max: r = r_min / sqrt(1 - u (1 - (r_min / r_max)^2)).
float equal_area_radius(float u, float r_min, float r_max) {
  float q = r_min / r_max;
  return r_min / sqrt(1.0f - u * (1.0f - q * q));
}

// The unit vector east at the unit direction p (an arbitrary horizontal one at the poles).
vec3 local_east(vec3 p) { return normalize(vec3(-p.y, p.x, 0.0f) + vec3(1.0e-6f, 0.0f, 0.0f)); }

// The anvils of deep convection: it spreads out under the tropopause into a shield of cirrus far
// wider than its convective core (Houze 2004, "Mesoscale convective systems", Rev. Geophys. 42:
// anvils hundreds of kilometres across), drawn out westward by the upper troposphere's easterlies
// over the ITCZ: an ellipse `spread` times the system's radius across, `stretch` times longer
// east-west, centred `lag` radii west of the system (vec3(spread, stretch, lag);
// spread 0: no anvil). The towers' spread over about five times their cores' area (spread^2
// stretch = 4.9): half of the warm pool's moderately cold cloud (below 235 K, the anvils' level)
// lies in clusters over 1e5 km^2 where half of its very cold cloud (below 208 K, the cores) lies in
// clusters over 2e4 km^2 (Mapes and Houze 1993). The mesoscale systems' discs, 320-800 km across,
// are such shields already; their anvils are only the shields' ragged western edge, as far as
// their search reaches (convective_distances).
const vec3 SYSTEM_ANVIL = vec3(1.2f, 1.2f, 0.1f);
const vec3 TOWER_ANVIL = vec3(1.8f, 1.5f, 0.1f);
const vec3 NO_ANVIL = vec3(0.0f);

// The share of places with a system at the unit direction p, for a line at latitude `line`: `filled`
// on the line, falling off with the offset o = (latitude - line) / width as (1 - o^2 / 4)^2 (half at
// o = 1.08, none from o = 2, so that the systems end at a known distance from the line; a Gaussian
// of about the width without its exponential). Taken in the sine of the latitude, the offset
// (sin lat - sin line) / cos line, which errs by 0.002 rad at 0.2 from a line within 10 degrees of
// the equator, so that the points searched need no arcsine: convective_presence_of makes
// (sin line, width cos line, filled) once for them.
vec3 convective_presence_of(float line, float width, float filled) {
  return vec3(sin(line), width * cos(line), filled);
}
float convective_presence(vec3 p, vec3 presence) {
  float offset = (p.z - presence.x) / presence.y;
  float bump = max(1.0f - 0.25f * offset * offset, 0.0f);
  return presence.z * bump * bump;
}

// The South Pacific Convergence Zone (Vincent 1994, "The South Pacific Convergence Zone (SPCZ): a
// review", Mon. Wea. Rev. 122): the tropics' other line of deep convection, a band 200-400 km broad
// from the warm pool near the Solomon Islands east-south-east past Fiji, Samoa and Tonga and the
// Cook Islands, petering out near 25 S, 120 W; present all year, strongest and furthest south in
// austral summer (the host's LineWaves.spcz and spcz_shift). Its mean line runs from
// SPCZ_LATITUDES.x at SPCZ_LONGITUDES.x to SPCZ_LATITUDES.y at SPCZ_LONGITUDES.y, latitude = west +
// (east - west)(1 - (1 - s)^SPCZ_BEND) over s in [0, 1] along the longitudes: diagonal at its
// tropical end (9 S at 160 E, 16 S at 175 W) and flattening eastward (20 S at 160 W).
const vec2 SPCZ_LONGITUDES = vec2(2.6179939f, 4.1887902f);  // 150 E and 240 E (120 W), radians
const vec2 SPCZ_LATITUDES = vec2(-0.10471976f, -0.43633231f);  // 6 S and 25 S
const float SPCZ_BEND = 1.6f;
// Along its line the SPCZ joins the warm pool's convection west of 150 E (s from -0.12 to 0.05)
// and peters out over the eastern third (s from 0.6 to 1).
float spcz_extent(float s) { return smoothstep(-0.12f, 0.05f, s) * (1.0f - smoothstep(0.6f, 1.0f, s)); }
// The place along the line, s, of the unit direction p by its longitude (0 at SPCZ_LONGITUDES.x,
// 1 at .y; beyond either end outside [0, 1], within half a turn of the line's middle).
float spcz_along(vec3 p) {
  const float two_pi = 6.28318530717959f;
  float east = atan(p.y, p.x + 1.0e-12f) - SPCZ_LONGITUDES.x;
  float span = SPCZ_LONGITUDES.y - SPCZ_LONGITUDES.x;
  east -= two_pi * floor((east - 0.5f * span) / two_pi + 0.5f);  // within half a turn of the middle
  return east / span;
}
// The mean line's latitude (radians) at s, ends held beyond [0, 1], moved by `shift`.
float spcz_latitude(float s, float shift) {
  float bent = 1.0f - pow(1.0f - clamp(s, 0.0f, 1.0f), SPCZ_BEND);
  return mix(SPCZ_LATITUDES.x, SPCZ_LATITUDES.y, bent) + shift;
}
// Whether any of the SPCZ's systems may reach the unit direction p: within SPCZ_REACH of latitude
// of its mean line at p's longitude (held at the ends) and within SPCZ_REACH_ALONG of its extent.
// What a system and its anvil reach lies within 0.342 of the mean line across it, as the ITCZ's
// (ITCZ_REACH: the meander, the points' spread, the anvils and the warp); the line's slope is at
// most 0.34 (latitude by east distance), so that across it 0.342 is at most 0.342 / cos(atan 0.34)
// = 0.36 of latitude; and along it within 0.342 / cos(25 S) = 0.38 of longitude, 0.24 of its span,
// of where its extent ends (s -0.12 and 1). (None north of 23.6 N or south of 60 S: the line with
// its seasonal shift of at most 5 degrees lies between 1 S and 30 S.)
// spcz_place gives p's place along the line, spcz_along, where they may reach it and SPCZ_FAR
// elsewhere, so that its callers need no second arctangent.
const float SPCZ_REACH = 0.37f;
const vec2 SPCZ_REACH_ALONG = vec2(-0.37f, 1.25f);
const float SPCZ_FAR = -1.0e3f;
float spcz_place(vec3 p, IN(LineWaves) waves) {
  if (waves.spcz <= 0.0f || p.z > 0.4f || p.z < -0.87f) return SPCZ_FAR;
  float s = spcz_along(p);
  if (s < SPCZ_REACH_ALONG.x || s > SPCZ_REACH_ALONG.y) return SPCZ_FAR;
  return abs(asin(p.z) - spcz_latitude(s, waves.spcz_shift)) < SPCZ_REACH ? s : SPCZ_FAR;
}
bool spcz_near(vec3 p, IN(LineWaves) waves) { return spcz_place(p, waves) != SPCZ_FAR; }
// The SPCZ's presence (as convective_presence, with the ITCZ's `presence`'s width and filling) at
// the unit direction p, at place `s` along the line (spcz_along), about its line meandering by
// the waves' meander `meander` (line_meander at p's longitude: the line's waves are functions of
// longitude, and the SPCZ takes the ITCZ's there), times its strength and extent along the line.
float spcz_presence(vec3 p, float s, vec3 presence, IN(LineWaves) waves, float meander) {
  float line = spcz_latitude(s, waves.spcz_shift) + ITCZ_MEANDER * meander;
  vec3 own = vec3(sin(line), presence.y * cos(line), waves.spcz * spcz_extent(s) * presence.z);
  return convective_presence(p, own);
}

// The share of places with a system at p (convective_presence) about the meandering line, and
// near the SPCZ the larger of that and the SPCZ's (spcz_presence), times 1 inside the
// superclusters and `dormant` outside: the SPCZ's systems gather in the superclusters of their
// longitude, as the intraseasonal oscillation's active phase over the western and central Pacific
// enhances the SPCZ's convection with the ITCZ's (Matthews 2012, "A multiscale framework for the
// origin and variability of the South Pacific Convergence Zone", QJRMS 138). The waves' sums are computed only where the
// share can be above 0 and above `below`, the caller's hash (a system is present where its hash is
// below the share; 0 there otherwise): the line shifts by at most meander_z LINE_MEANDER_LIMIT and
// the share is at most the presence's `filled` (and the monsoons shift it by at most their reach).
float waved_presence(vec3 p, vec3 presence, IN(LineWaves) waves, float below) {
  if (waves.applies == 0.0f) return convective_presence(p, presence);
  float reach = 2.0f * presence.y + waves.meander_z * LINE_MEANDER_LIMIT + waves.monsoon_reach;
  float s = spcz_place(p, waves);
  if (below >= presence.z || (abs(p.z - presence.x) >= reach && s == SPCZ_FAR)) return 0.0f;
  vec3 sums = line_waves(p, waves);
  float filled = mix(waves.dormant, 1.0f, supercluster_activity(sums));
  float share = convective_presence(p - vec3(0.0f, 0.0f, line_shift(sums, waves)), presence);
  if (s != SPCZ_FAR) share = max(share, spcz_presence(p, s, presence, waves, line_meander(sums)));
  return filled * share;
}

// Where the waves move (LineWaves), a system's share of places changes with time, and a system
// whose hash it passes would appear or vanish at once, a whole disc from one frame to the next.
// Instead it grows from a point as the share rises past its hash: its radius is the full one times
// the share's excess over the hash in units of SYSTEM_GROWTH (up to 1). At a supercluster's edge
// the share rises from 0.2 to 1 over about 470 km (the envelope's sum by 0.6 at its root mean
// square slope of 8.1 a radian), which the envelope passes in 11 hours at 12 m/s: a system grows
// over about 3 hours (an hour where the envelope is steepest), as mesoscale convective systems
// grow over some hours (Houze 2004), and fades the same way. Inside a supercluster a quarter of
// the systems (hashes within 0.25 below the share) are smaller than full, outside all are (the
// share is 0.2): convection away from the superclusters is weaker. Without waves (the trades'
// clumps, a share fixed in time), every present system has its full radius.
const float SYSTEM_GROWTH = 0.25f;
float system_growth(float excess, IN(LineWaves) waves) {
  return waves.applies == 0.0f ? 1.0f : min(excess / SYSTEM_GROWTH, 1.0f);
}

// A lattice cell's system's own hashes, each uniform in [0, 1): x its radius (equal_area_radius), y
// its presence (convective_cell), z free for a pattern's own use (the flowers' maturity).
vec3 system_hashes(ivec3 cell, uvec3 size_key) { return hash_to_unit3(pcg3d(uvec3(cell) ^ size_key)); }

// The system of lattice cell `cell` (convective_distances' lattice, its keys noise_key(seed, layer)
// and noise_key(seed, layer + 1)): its point's offset from the cell's lower corner (xyz) and its
// radius in cells (w), 0 where the cell has no system.
vec4 convective_cell(ivec3 cell, uvec3 key, uvec3 size_key, vec2 radii, vec3 presence, IN(LineWaves) waves) {
  vec3 feature = wrapped_feature_offset(cell, key);
  vec3 h = system_hashes(cell, size_key);
  // (A presence of a width beyond the sphere's, presence_everywhere, is its z everywhere.)
  float here = presence.y < 1.0e5f ? waved_presence(normalize(vec3(cell) + feature), presence, waves, h.y) : presence.z;
  if (h.y >= here) return vec4(feature, 0.0f);
  return vec4(feature, equal_area_radius(h.x, radii.x, radii.y) * system_growth(here - h.y, waves));
}

// A table of a lattice's cells (tabled_convective_distances): every cell a search from a point of
// the unit sphere reaches, from -(n + 1) to n + 1 along each axis for n cells per radius (a
// point's cell is within [-n, n], its neighbours one further), x fastest.
int convective_table_side(float frequency) { return 2 * int(frequency) + 3; }
int convective_table_index(float frequency, ivec3 cell) {
  int side = convective_table_side(frequency), centre = side / 2;
  ivec3 at = cell + ivec3(centre);
  return (at.z * side + at.y) * side + at.x;
}
// The cell of entry `index` of such a table (convective_table_index's inverse).
ivec3 convective_table_cell(float frequency, int index) {
  int side = convective_table_side(frequency), centre = side / 2;
  return ivec3(index % side, (index / side) % side, index / (side * side)) - ivec3(centre);
}

// A search may read its cells from a table that a pass made for the frame (the density pass's
// ITCZ, CONVECTIVE_CELL_TABLES: convective_cell of every cell of its lattices, itcz_cells.comp),
// so that a texel reads each of its 27 cells where it would hash it, find its presence from the
// line's waves and draw its radius, each the same for every texel around it (about 0.9 of the
// 5.5 s of the density pass at 1024 per face on llvmpipe). `table`: the entry of its first cell
// among the tables of the shader (which TABLED_CONVECTIVE_CELL(seed, entry) reads for the cloud
// layer of `seed`), or NO_CELL_TABLE: computed, as C++ and the other shaders always do.
const int NO_CELL_TABLE = -1;
#ifndef CONVECTIVE_CELL_TABLES
#define CONVECTIVE_CELL_TABLES 0
#endif

// p's distance to the system of `cell` (offset from p's cell, `f` p's place in its own) with the
// cell's system `system` (convective_cell), in units of its radius, and to its anvil (as
// convective_distances), taken into `nearest` where smaller.
void nearer_system(vec4 system, ivec3 offset, vec3 f, vec3 east, vec3 anvil, INOUT(vec2) nearest) {
  if (system.w <= 0.0f) return;
  vec3 to_point = vec3(offset) + vec3(system) - f;
  float r = system.w;
  nearest.x = min(nearest.x, length(to_point) / r);
  if (anvil.x <= 0.0f) return;
  float along = -dot(to_point, east);  // p's distance east of the point
  vec3 across = -to_point - along * east;
  float lagged = (along + anvil.z * r) / anvil.y;
  nearest.y = min(nearest.y, sqrt(lagged * lagged + dot(across, across)) / (anvil.x * r));
}

// Convective systems on a lattice of `frequency` cells per radius (noise layer `layer` for the
// points, layer + 1 for their sizes and presence): at most one at each cell's feature point, a disc
// of radius equal_area_radius(hash, radii) cells, present where a second hash is below `presence`
// (convective_presence_of) of the point's direction (its share of places with a system). Returns the smallest distance from
// p to a system's point in units of its radius (x), and to an anvil's centre in units of its
// half-axes (y; 1e30 without an `anvil`), over the first `searched` of the 27 cells around p
// (neighbour_offset; NEIGHBOUR_CELLS, or 0: SKIPPABLE), which hold every point within a cell, or
// over the NEAR_CELLS (near_offset), which hold every point within half a cell: each
// system is a whole disc (the nearest point's system alone would be cut along its Voronoi cell's
// border into straight edges) where it reaches no further than the search: with the 27 cells,
// radii up to 0.5 cells keep the discs (out to 1.8 radii with the noise, 0.9 cells) and anvils of
// (spread stretch + lag) r 1.3 up to 1 cell whole (the systems': (1.2 x 1.2 + 0.1) 0.5 x 1.3 = 1.0;
// the towers': (1.8 x 1.5 + 0.1) 0.27 x 1.3 = 0.98); with the 8, discs reaching half a cell. 1e30
// where none is near or `searched` is 0. tabled_convective_distances reads the cells from `table`
// (convective_distances: none).
vec2 tabled_convective_distances(vec3 p, float frequency, uint seed, uint layer, vec2 radii, vec3 presence,
                                 IN(LineWaves) waves, vec3 anvil, int searched, int table) {
  vec3 scaled = p * frequency;
  vec3 base = floor(scaled);
  ivec3 cell = ivec3(base);
  vec3 f = scaled - base;
  uvec3 key = noise_key(seed, layer), size_key = noise_key(seed, layer + 1u);
  vec3 east = local_east(p);
  vec2 nearest = vec2(1.0e30f);
  for (int k = 0; k < searched; ++k) {
    ivec3 offset = searched == NEAR_CELLS ? near_offset(k, f) : neighbour_offset(k);
#if CONVECTIVE_CELL_TABLES
    // (A literal table folds this choice away: the compiler inlines every function.)
    vec4 system = table != NO_CELL_TABLE
                      ? TABLED_CONVECTIVE_CELL(seed, table + convective_table_index(frequency, cell + offset))
                      : convective_cell(cell + offset, key, size_key, radii, presence, waves);
#else
    UNUSED_PARAMETER(table);
    vec4 system = convective_cell(cell + offset, key, size_key, radii, presence, waves);
#endif
    nearer_system(system, offset, f, east, anvil, nearest);
  }
  return nearest;
}
vec2 convective_distances(vec3 p, float frequency, uint seed, uint layer, vec2 radii, vec3 presence,
                          IN(LineWaves) waves, vec3 anvil, int searched) {
  return tabled_convective_distances(p, frequency, seed, layer, radii, presence, waves, anvil, searched, NO_CELL_TABLE);
}

// A convective system's cloud at distance d (in its radii) with the cover's noise as `edge` in
// [-1, 1]: the outline moved by up to `reach` of the radius either way, so that it follows the
// noise's cloud and frays at the noise's scales (the cores by CORE_EDGE_REACH: far enough to take
// the noise's shapes; the anvils, spread by the wind aloft, by ANVIL_EDGE_REACH), and sharp: from
// none to full over the outer CONVECTIVE_RIM of the radius (deep convection's edges are steps of
// optical thickness).
const float CORE_EDGE_REACH = 0.8f;
const float ANVIL_EDGE_REACH = 0.3f;
const float CONVECTIVE_RIM = 0.15f;
// The same with a rim of `rim` of the radius (in (0, 1]): the cloud fades from full at 1 - rim
// to none at 1, moved as the outline by the noise.
float rimmed_cloud(float d, float edge, float reach, float rim) {
  return 1.0f - smoothstep(1.0f - rim, 1.0f, d - reach * edge);
}
float convective_cloud(float d, float edge, float reach) { return rimmed_cloud(d, edge, reach, CONVECTIVE_RIM); }

// The ITCZ (Waliser and Gautier 1993, "A satellite-derived climatology of the ITCZ", J. Climate 6):
// mesoscale convective systems 320-800 km across on a lattice of 8 cells per radius (about 800 km
// apart), in every place on its line inside the superclusters and fewer away from it
// (convective_presence, a width of 4 degrees); and single towers and small clusters 55-145 km
// across on a lattice three times finer, in one place in two on the line and fewer over a width of
// 6 degrees (scattered convection over the warm pool), with anvils of five times their area
// (TOWER_ANVIL). Both follow the line's meander and the monsoons; the mesoscale systems fill
// ITCZ_DORMANT as many places outside the superclusters (LineWaves), while the towers are as
// common outside them as inside (scattered convection away from the systems). Both draw their radii from equal_area_radius, so that together they
// cover about equal areas per interval of size from 50 to 900 km; half of the very cold cloudiness
// lies in clusters over 20 000 km^2 (160 km across; Mapes and Houze 1993, "Cloud clusters and
// superclusters over the oceanic warm pool", Mon. Wea. Rev. 121).
const float ITCZ_CELLS = 8.0f;
const uint ITCZ_LAYER = 11u;  // and 12
const vec2 ITCZ_RADII = vec2(0.2f, 0.5f);
const float ITCZ_FILLED = 1.0f;
const float ITCZ_TOWER_CELLS = 24.0f;
const uint ITCZ_TOWER_LAYER = 24u;  // and 25
const vec2 ITCZ_TOWER_RADII = vec2(0.1f, 0.27f);
const float ITCZ_TOWER_FILLED = 0.5f;
// The towers' presence's width (radians, 6 degrees).
const float ITCZ_TOWER_WIDTH = 0.1f;
// Inside a supercluster the clusters' anvils and stratiform cloud merge into one band along the
// line (Mapes and Houze 1993: superclusters' cold cloud shields span thousands of km), ITCZ_LINE_WIDTH
// either side of it (2.5 degrees: 550 km across, flat over its middle 330 km), its edges moved by
// the cover's noise by half that: anvil cloud, thin and grey, through which the systems' bright
// cores show.
const float ITCZ_LINE_WIDTH = 0.044f;
// The band is deep cloud at 0.8 of a system's strength: the stratiform regions of mesoscale
// convective systems, thick layer cloud under the anvil that gives 40 % of their rain (Houze 2004),
// less bright than the convective cores but far brighter than thin anvil cirrus. At half a
// system's strength (a factor of 1.25 on the density) the band left no trace on a 512 map: it
// did not lift the trades' dark sea over its latitudes' thresholds (docs/climate.md, "The ITCZ's line").
const float ITCZ_LINE_DEPTH = 0.8f;
// The band is the systems' shields merged: deep around each mesoscale system and thinner between
// them, a string of beads rather than a bar of one width. Its depth falls from ITCZ_LINE_DEPTH
// within ITCZ_BEAD_REACH.x of the nearest system's radius to ITCZ_BEAD_GAP of it from
// ITCZ_BEAD_REACH.y (the systems, 320-800 km across and about 800 km apart, leave gaps of up to
// two or three of their radii).
const vec2 ITCZ_BEAD_REACH = vec2(1.2f, 2.5f);
const float ITCZ_BEAD_GAP = 0.6f;
float itcz_beads(float distance) {
  return mix(1.0f, ITCZ_BEAD_GAP, smoothstep(ITCZ_BEAD_REACH.x, ITCZ_BEAD_REACH.y, distance));
}
// The systems' reach from the ITCZ's mean line (radians), beyond which none is drawn: the line
// meanders by at most LINE_MEANDER_LIMIT x ITCZ_MEANDER = 0.065; a system's point lies within
// 2 x 0.07 of it and its anvil reaches 1.0 / 8 cells further, and the warp moves the point drawn by
// at most 0.008 sqrt(2) PERLIN_BOUND = 0.012 (convective_warp): 0.065 + 0.14 + 0.125 + 0.012 =
// 0.342. A tower's point lies within 2 x 0.1 of the meandering line and its anvil 0.98 / 24
// further: 0.318 with the warp, and their search is left out beyond ITCZ_TOWER_REACH. The monsoons
// move the line further by at most their reach (LineWaves' monsoon_reach), which both add.
const float ITCZ_REACH = 0.35f;
const float ITCZ_TOWER_REACH = 0.32f;

// The systems' outlines are irregular below their own scale too (a tower's dome, the lobes of a
// cluster's cells), which the cover's noise, whose large scales carry most of its variance, leaves
// nearly round: they are drawn at the unit direction p displaced along the sphere by a field of
// Perlin noise of CONVECTIVE_WARP_CELLS cells per radius (about 66 km), east and north, times
// CONVECTIVE_WARP radians (51 km; the field's components rarely exceed 1/2), and renormalised.
// `components` 2, or 0 where no system is drawn (SKIPPABLE): p itself.
const float CONVECTIVE_WARP_CELLS = 96.0f;
const float CONVECTIVE_WARP = 0.008f;
const uint CONVECTIVE_WARP_LAYER = 26u;  // and 27, one a component
// The unit direction p displaced along the sphere by `amount` radians times a field of Perlin noise
// of `cells` cells per radius, east and north (noise layers `layer` and layer + 1), renormalised;
// `components` 2, or 0 (SKIPPABLE): p itself.
vec3 tangent_warp(vec3 p, float cells, float amount, uint seed, uint layer, int components) {
  vec2 warp = vec2(0.0f);
  for (int k = 0; k < components; ++k) warp[k] = perlin_noise(p * cells, ivec3(0), noise_key(seed, layer + uint(k)));
  vec3 east = local_east(p);
  return normalize(p + amount * (warp.x * east + warp.y * cross(p, east)));
}
vec3 convective_warp(vec3 p, uint seed, int components) {
  return tangent_warp(p, CONVECTIVE_WARP_CELLS, CONVECTIVE_WARP, seed, CONVECTIVE_WARP_LAYER, components);
}

// The latitude (radians) of the ITCZ's meandering line at the unit direction p, for a mean line at
// `itcz_latitude` and its `waves`.
float itcz_line_latitude(vec3 p, float itcz_latitude, IN(LineWaves) waves) {
  vec3 sums = line_waves(p, waves);
  return itcz_latitude + ITCZ_MEANDER * line_meander(sums) + sums.z / cos(itcz_latitude);
}

// The towers' waves: the line's meander and monsoons without its superclusters (an envelope of 0
// is active everywhere: supercluster_activity(0) = 1).
LineWaves without_superclusters(LineWaves waves) {
  for (int k = 0; k < LINE_WAVES; ++k) waves.envelope[k] = vec2(0.0f);
  return waves;
}

// The band's width along the line, as a share of ITCZ_LINE_WIDTH at the unit direction `now`: the
// merged shields swell around a supercluster's strongest clusters and narrow between them, from
// ITCZ_SWELL.x to ITCZ_SWELL.y (for noise values beyond two deviations; mostly 0.6-1.1) with
// gradient noise of ITCZ_SWELL_CELLS cells a radius (swellings some 600 km long) of the belts'
// `seed`, taken at the equator's point of `now`'s longitude, so that the width is a function of the
// place along the line (a noise of the latitude too would break the band's edge into islands). A
// band of one width everywhere drew each supercluster as a bar with parallel edges, which no
// satellite image shows.
const float ITCZ_SWELL_CELLS = 10.0f;
const vec2 ITCZ_SWELL = vec2(0.35f, 1.35f);
const uint ITCZ_SWELL_LAYER = 39u;
float itcz_swell(vec3 now, uint seed) {
  vec3 along = normalize(vec3(now.x, now.y, 0.0f) + vec3(1.0e-6f, 0.0f, 0.0f));  // safe at the poles
  float n = perlin_noise(along * ITCZ_SWELL_CELLS, ivec3(0), noise_key(seed, ITCZ_SWELL_LAYER)) / PERLIN_OCTAVE_SIGMA;
  return mix(ITCZ_SWELL.x, ITCZ_SWELL.y, smoothstep(-2.0f, 2.0f, n));
}

// The SPCZ's band (a zone 200-400 km broad, Vincent 1994): SPCZ_LINE_WIDTH either side of its
// line, flat over its middle 230 km, as the ITCZ's (ITCZ_LINE_WIDTH) elsewhere. It is deep cloud
// as bright as a front's band (SPCZ_LINE_DEPTH, the comma clouds' 1), not the ITCZ's shields'
// half: beyond the warm pool the SPCZ is a band of cloud where the troughs and fronts of the
// southern storm track stall and feed its convection (Vincent 1994; Matthews 2012), drawn on
// satellite images as a continuous band thousands of km long rather than a string of clusters.
const float SPCZ_LINE_WIDTH = 0.03f;
const float SPCZ_LINE_DEPTH = 1.0f;
// Outside the superclusters the SPCZ keeps SPCZ_BAND_DORMANT of its band: the storm track's
// troughs that feed it come whatever the tropical envelope (Matthews 2012), which gates its
// systems (spcz_presence) and the ITCZ's band wholly.
const float SPCZ_BAND_DORMANT = 0.5f;
// The superclusters' band's deep cloud at the unit direction `now` (itcz_systems), in [0, 1]:
// ITCZ_LINE_DEPTH over the band, its width swelling with the belts' `seed` (itcz_swell); and the
// SPCZ's where near it, SPCZ_LINE_DEPTH times its strength and extent, in the same superclusters
// (spcz_presence) and SPCZ_BAND_DORMANT of that outside them.
float itcz_line_band(vec3 now, float itcz_latitude, IN(LineWaves) waves, float edge, uint seed) {
  vec3 sums = line_waves(now, waves);
  float offset = (now.z - sin(itcz_latitude) - line_shift(sums, waves)) / cos(itcz_latitude);
  float swell = itcz_swell(now, seed);
  float width = ITCZ_LINE_WIDTH * swell;
  float activity = supercluster_activity(sums);
  float band = activity * ITCZ_LINE_DEPTH * band_profile(offset + 0.5f * width * edge, width);
  float s = spcz_place(now, waves);
  if (s != SPCZ_FAR) {
    float across = asin(now.z) - spcz_latitude(s, waves.spcz_shift) - ITCZ_MEANDER * line_meander(sums);
    float spcz_width = SPCZ_LINE_WIDTH * swell;
    band = max(band, mix(SPCZ_BAND_DORMANT, 1.0f, activity) * SPCZ_LINE_DEPTH * waves.spcz * spcz_extent(s) *
                         band_profile(across + 0.5f * spcz_width * edge, spcz_width));
  }
  return band;
}

// The ITCZ's two lattices, each a table of its cells where the density pass makes them
// (CONVECTIVE_CELL_TABLES): the mesoscale systems and the towers, with their cells per radius,
// noise layers, radii, presence about a mean line at `itcz_latitude` and waves (the towers'
// without the superclusters). A table is named by its first entry: the systems' 19^3 cells
// (convective_table_side of 8 cells per radius), then the towers' 51^3 (of 24).
const int ITCZ_SYSTEMS_TABLE = 0;
const int ITCZ_TOWERS_TABLE = 19 * 19 * 19;
const int ITCZ_TABLE_CELLS = ITCZ_TOWERS_TABLE + 51 * 51 * 51;
float itcz_lattice_cells(int table) { return table == ITCZ_SYSTEMS_TABLE ? ITCZ_CELLS : ITCZ_TOWER_CELLS; }
uint itcz_layer(int table) { return table == ITCZ_SYSTEMS_TABLE ? ITCZ_LAYER : ITCZ_TOWER_LAYER; }
vec2 itcz_radii(int table) { return table == ITCZ_SYSTEMS_TABLE ? ITCZ_RADII : ITCZ_TOWER_RADII; }
vec3 itcz_presence(int table, float itcz_latitude) {
  return table == ITCZ_SYSTEMS_TABLE ? convective_presence_of(itcz_latitude, 0.07f, ITCZ_FILLED)
                                     : convective_presence_of(itcz_latitude, ITCZ_TOWER_WIDTH, ITCZ_TOWER_FILLED);
}
LineWaves itcz_table_waves(int table, IN(LineWaves) waves) {
  return table == ITCZ_SYSTEMS_TABLE ? waves : without_superclusters(waves);
}
// The system of `cell` of the ITCZ's lattice `table` (convective_cell): the tables' entries.
vec4 itcz_cell(int table, ivec3 cell, float itcz_latitude, IN(LineWaves) waves, uint seed) {
  uint layer = itcz_layer(table);
  return convective_cell(cell, noise_key(seed, layer), noise_key(seed, layer + 1u), itcz_radii(table),
                         itcz_presence(table, itcz_latitude), itcz_table_waves(table, waves));
}
// The cell of the ITCZ's tables' entry `index` (in [0, ITCZ_TABLE_CELLS)): xyz, and its table in w.
ivec4 itcz_table_cell(int index) {
  int table = index < ITCZ_TOWERS_TABLE ? ITCZ_SYSTEMS_TABLE : ITCZ_TOWERS_TABLE;
  return ivec4(convective_table_cell(itcz_lattice_cells(table), index - table), table);
}
// The distances of itcz_systems from one of its lattices (convective_distances).
vec2 itcz_distances(int table, vec3 p, float itcz_latitude, IN(LineWaves) waves, uint seed, int searched) {
  vec3 anvil = table == ITCZ_SYSTEMS_TABLE ? SYSTEM_ANVIL : TOWER_ANVIL;
  return tabled_convective_distances(p, itcz_lattice_cells(table), seed, itcz_layer(table), itcz_radii(table),
                                     itcz_presence(table, itcz_latitude), itcz_table_waves(table, waves), anvil,
                                     searched, table);
}

// The ITCZ's convective systems: (the systems' and towers' cloud and the superclusters' band's deep
// cloud, the systems' anvils and the band's shield), both in [0, 1], with the line's `waves`; the
// shield is the band's anvil cloud, whole where its deep cloud is ITCZ_LINE_DEPTH or more. The
// systems are drawn at p, the air's origin of geocentric `latitude`, carried by the flow as the
// rest of the cloud (none beyond ITCZ_REACH of the mean line, or near the SPCZ's, spcz_near); the
// `band` is itcz_line_band at the texel's own direction: the ITCZ is where the trades converge,
// which the flow's air passes through rather than carries along (and the moving flow's two layers
// share it, so the caller computes it once).
vec2 itcz_systems(vec3 p, float band, float latitude, float itcz_latitude, IN(LineWaves) waves, uint seed, float edge) {
  float off_line = abs(latitude - itcz_latitude) - waves.monsoon_reach;
  bool spcz = spcz_near(p, waves);
  bool near = off_line < ITCZ_REACH || spcz;
  int searched = SKIPPABLE(near, NEIGHBOUR_CELLS);
  int towers_searched = SKIPPABLE(off_line < ITCZ_TOWER_REACH || spcz, NEIGHBOUR_CELLS);
  p = convective_warp(p, seed, SKIPPABLE(near, 2));
  vec2 systems = itcz_distances(ITCZ_SYSTEMS_TABLE, p, itcz_latitude, waves, seed, searched);
  vec2 towers = itcz_distances(ITCZ_TOWERS_TABLE, p, itcz_latitude, waves, seed, towers_searched);
  float shield = min(band / ITCZ_LINE_DEPTH, 1.0f);
  if (!near) return vec2(band, shield);
  return vec2(max(convective_cloud(min(systems.x, towers.x), edge, CORE_EDGE_REACH), band * itcz_beads(systems.x)),
              max(convective_cloud(min(systems.y, towers.y), edge, ANVIL_EDGE_REACH), shield));
}

// The trades' cumulus organise on the mesoscale into four patterns that an eye tells apart on
// satellite images (Stevens et al. 2020, "Sugar, gravel, fish and flowers: Mesoscale cloud
// patterns in the trade winds", QJRMS 146): sugar, a fine dusting of dim cumulus far below a
// texel with no organisation; gravel, clumps and arcs of cumulus some tens of km across, brighter
// than sugar; fish, skeletal bands of cloud about a thousand km long, separated from the rest by
// clear sky; and flowers, bouquets of stratiform cloud 50-200 km across, bright, well apart from
// each other. Each pattern holds over areas of 10^5-10^6 km^2 for a day or more and all four are
// common (Bony et al. 2020, "Sugar, gravel, fish, and flowers: dependence of mesoscale patterns
// of trade-wind clouds on environmental conditions", GRL 47). trade_regimes gives the patterns'
// weights (sugar, gravel, fish, flowers), summing to 1, from two Perlin fields of
// TRADE_REGIME_CELLS cells per radius (regions about 1300 km across), each split at its median
// (0: the noise is symmetric), so that each pattern holds about a quarter of the trades, with
// blends over TRADE_REGIME_BLEND of the fields' values (their spread is 0.27: about a fifth of the
// trades lie in a blend of two patterns). `fields` 2, or 0 where the caller needs no weights
// (SKIPPABLE: both fields 0, each pattern a quarter).
const float TRADE_REGIME_CELLS = 5.0f;
const float TRADE_REGIME_BLEND = 0.06f;
const uint TRADE_REGIME_LAYER = 29u;  // and 30
vec4 trade_regimes(vec3 p, uint seed, int fields) {
  vec2 ab = vec2(0.0f);
  for (int k = 0; k < fields; ++k)
    ab[k] = perlin_noise(p * TRADE_REGIME_CELLS, ivec3(0), noise_key(seed, TRADE_REGIME_LAYER + uint(k)));
  float organised = smoothstep(-TRADE_REGIME_BLEND, TRADE_REGIME_BLEND, ab.x);  // gravel or flowers
  float stratiform = smoothstep(-TRADE_REGIME_BLEND, TRADE_REGIME_BLEND, ab.y);  // fish or flowers
  return vec4((1.0f - organised) * (1.0f - stratiform), organised * (1.0f - stratiform),
              (1.0f - organised) * stratiform, organised * stratiform);
}

// The patterns' clumps, each in [0, 1]: whole discs of radii of density r^-3 on a lattice
// (convective_distances over the NEAR_CELLS, in every place in `filled` of them; `searched` 0
// where the caller draws none; the flowers: discs on the sphere, surface_disc_clouds), their
// edges frayed by the cover's noise (`edge`, up to TRADE_CLUMP_EDGE_REACH of a radius, the
// flowers' FLOWER_EDGE_REACH), soft where the cloud is thin and sharp where thick (the rims
// below). Whole discs: a clump cut along
// its Voronoi cell's border with an empty or smaller neighbour (cell_clouds) shows straight edges
// and corners, shards rather than clouds, once the cover resolves them. Gravel's and fish's radii
// stay below 0.38 cells, so that with the fray (1.3 times) they reach at most 0.494 cells and the 8
// nearest cells hold them (the flowers' search reaches further, surface_disc_clouds). Gravel: clumps of cumulus 40-80 km across (radii 0.2-0.38 of cells of 106 km,
// 60 a radius), nine places in ten. Flowers: bouquets 100-175 km across (radii 0.22-0.38 of cells
// of 228 km, FLOWER_CELLS a radius, 0.8 a cell^2), drawn at the point displaced by Perlin noise of 80
// cells a radius by up to about 20 km (tangent_warp), so that their outlines are lobed. Fish:
// bands 750-970 km long and a quarter as wide (radii 0.3-0.38 of cells of 1270 km, 5 a radius,
// with the point's z (north) component stretched fourfold, which draws them out along the latitude
// circles, along the trade winds), eight places in ten, bent by a displacement of up to about 50
// km at 320 km. The displacements' gradients stay below about 0.7 (0.006 x 80 and 0.015 x 20 times
// the Perlin noise's slope of about 1.5), so they fold nothing.
const uint GRAVEL_LAYER = 13u;        // and 14
const uint FLOWERS_LAYER = 15u;       // and 16
const uint FISH_LAYER = 31u;          // and 32
const uint FLOWERS_WARP_LAYER = 33u;  // and 34
const uint FISH_WARP_LAYER = 35u;     // and 36
const float FISH_STRETCH = 4.0f;
const float TRADE_CLUMP_EDGE_REACH = 0.3f;
// The flowers' lattice: 50-200 km across (Stevens et al. 2020), their upper half, well apart (a
// bouquet to a cell). In the lower half, 40 cells a radius, a 512 cover (25 km texels) drew them
// as dots of two or three texels, an even confetti over the trades; at 28 it draws blobs of four to
// seven, a bouquet's size apart.
const float FLOWER_CELLS = 28.0f;
const vec2 FLOWER_RADII = vec2(0.22f, 0.38f);
// The bouquets are flat sheets under the trade inversion, drawn as discs on the sphere
// (surface_disc_clouds) from the feature points within FLOWER_SHELL cells of it: 2 x 0.4 = 0.8
// bouquets a cell^2, which cover 0.8 pi E[r^2] = 0.2 of a flower region (radii of density r^-3 on
// 0.22-0.38: E[r^2] = 0.080 cells^2), about 0.16 once they overlap and fade over their rims. The
// lattice's balls cut by the sphere covered their volume share, 4/3 pi E[r^3] = 0.1, the least of
// the organised patterns, where the flowers and fish are the cloudiest of the four (Bony et al.
// 2020; Schulz et al. 2021).
const float FLOWER_SHELL = 0.4f;
// The bouquets' outlines move with the cover's noise by up to FLOWER_EDGE_REACH of their radius,
// between the deep convection's cores (CORE_EDGE_REACH, cumuliform) and their anvils
// (ANVIL_EDGE_REACH, sheets spread by the wind): flowers are cumulus whose tops spread into
// stratiform sheets under the trade inversion (Stevens et al. 2020). With the clumps' 0.3 their
// outlines were smooth, convex pebbles at 1024 per face.
const float FLOWER_EDGE_REACH = 0.5f;
// A presence of `filled` everywhere (convective_presence_of a line whose width is beyond the sphere).
vec3 presence_everywhere(float filled) { return vec3(0.0f, 1.0e6f, filled); }
// The rims, as shares of a clump's radius over which its cloud fades out (rimmed_cloud): gravel's
// broken shallow cumulus thin out over the outer 0.7 of a clump (15-28 km at its radii, from 0.1 to
// 0.9 over 9-17 km: a texel or two of a 1024 cover), fish's cloud over 0.4 (its bands' sides over 40-50 km), and flowers'
// stratiform sheets end within 0.15 (8-13 km, about a texel of a 1024 cover), as the deep convection's: in a
// satellite image edges are sharp where the cloud is optically thick and soft where thin (issue 30;
// the patterns' reflectance rises from gravel to fish and flowers, Bony et al. 2020).
const float GRAVEL_RIM = 0.7f;
const float FISH_RIM = 0.4f;
const float FLOWER_RIM = CONVECTIVE_RIM;
// A clump's rim where the cover's texels (texel_arc radians across) are too coarse for it: at least
// CLUMP_RIM_TEXELS texels of a clump of `radius` cells of `frequency` a radius, at most the whole
// radius. A texel's cover is its area's: a clump's edge is no sharper than the texel it falls in,
// whatever the clump's size, and a rim of under a texel draws the clumps at a coarse cover as
// hard-edged dots of a texel or two, flat white confetti (the 512 map), where a satellite's pixel
// sees a bouquet's edge blend into the sea. The flowers take each bouquet's own radius; gravel and
// fish, whose search gives no clump's radius (convective_distances), their lattice's mean.
// texel_arc 0: the clumps' own rims.
const float CLUMP_RIM_TEXELS = 1.0f;
float resolved_rim(float rim, float frequency, float radius, float texel_arc) {
  float texel = CLUMP_RIM_TEXELS * texel_arc * frequency / radius;
  return clamp(max(rim, texel), rim, 1.0f);
}
float trade_clump(vec3 p, float frequency, uint seed, uint layer, vec2 radii, float filled, float rim, float edge,
                  float texel_arc, int searched) {
  float d = convective_distances(p, frequency, seed, layer, radii, presence_everywhere(filled), no_line_waves(), NO_ANVIL,
                                 searched)
                .x;
  return rimmed_cloud(d, edge, TRADE_CLUMP_EDGE_REACH, resolved_rim(rim, frequency, 0.5f * (radii.x + radii.y), texel_arc));
}
// The clumps' strength by pattern, which lifts their density (the belts' weight times it) and
// sets their brightness (cloud_properties.glsl's cumulus_organisation): gravel's cumulus, broken
// and shallow, a little above sugar; fish and flowers, whose tops spread into stratiform sheets
// under the trade inversion (Stevens et al. 2020), bright.
const vec3 TRADE_PATTERN_STRENGTH = vec3(0.45f, 0.8f, 1.0f);  // gravel, fish, flowers
// A flower's peak: the bouquets of a field are seen at every stage of their life, from the
// gravel-like clusters that aggregate into them, through the mature bouquet whose stratiform sheet
// spreads under the trade inversion, to its thinning remains (Dauhut et al. 2023, "Flower
// trade-wind clouds are shallow mesoscale convective systems", QJRMS 149), and cumulus fields are
// optically thicker the more they cluster (Alinaghi et al. 2023, arXiv:2309.08346), so their
// brightness differs from one to the next. Each bouquet's peak is uniform (its third hash,
// system_hashes) from FLOWER_FAINTEST, gravel's strength, to 1: a field of equal white bouquets
// read as confetti on the 512 map.
const float FLOWER_FAINTEST = TRADE_PATTERN_STRENGTH.x;
// Discs on the sphere: the cloud at p of the discs centred on the sphere's points nearest the
// feature points of a lattice of `frequency` cells per radius (one a cell, convective_cell's,
// everywhere) that lie within `shell` cells of it, of the cells' radii (`radii`, density r^-3):
// x the largest of their outlines (rimmed_cloud of p's distance in the disc's radii, frayed by
// `rims`.x, the cover's noise, times .y of a radius, each fading over the rim .z or its own
// radius's resolved_rim at texels of .w radians), y the largest of the outlines times each disc's
// peak, uniform from `faintest` to 1 (its third hash). A ball of the lattice cut by the sphere
// shows as a disc only where its point lies near the sphere, mostly smaller than its radius; these
// show whole, 2 x shell of them a cell^2. A point at height h above the sphere (radius
// `frequency` in cells) whose disc's centre lies a chord c from p is sqrt(h^2 + (1 + h /
// frequency) c^2) from it, so a disc reaches p only from a point within sqrt(shell^2 + (1 + shell
// / frequency) reach^2) cells (reach: the frayed outline's furthest, (1 + .y) radii.y): the 27
// cells around p (`searched` NEIGHBOUR_CELLS, or 0: SKIPPABLE, no cloud) hold every point within a
// cell, so that keeps the discs whole while it is at most 1, and only the cells whose box lies
// within that along each axis are hashed (13.8 of the 27 on average for the flowers).
vec2 surface_disc_clouds(vec3 p, float frequency, uint seed, uint layer, vec2 radii, float shell, vec4 rims,
                         float faintest, int searched) {
  vec3 scaled = p * frequency;
  vec3 base = floor(scaled);
  ivec3 cell = ivec3(base);
  vec3 f = scaled - base;
  uvec3 key = noise_key(seed, layer), size_key = noise_key(seed, layer + 1u);
  float reach = (1.0f + rims.y) * radii.y;
  float within = sqrt(shell * shell + (1.0f + shell / frequency) * reach * reach);
  // The cells whose boxes lie within `within` of p along each axis, 2 or 3 an axis (none where
  // nothing is searched), as loops of varying counts: llvmpipe ends a loop when the last lane of a
  // group leaves it, where a test inside the loop only masks lanes and the cell is hashed anyway
  // (docs/performance.md, "The wider search as a loop").
  ivec3 lo = max(ivec3(-1), ivec3(floor(f - vec3(within))));
  ivec3 hi = searched > 0 ? min(ivec3(1), ivec3(floor(f + vec3(within)))) : lo - ivec3(1);
  vec2 cloud = vec2(0.0f);
  for (int z = lo.z; z <= hi.z; ++z)
    for (int y = lo.y; y <= hi.y; ++y)
      for (int x = lo.x; x <= hi.x; ++x) {
        ivec3 offset = ivec3(x, y, z);
        vec4 system = convective_cell(cell + offset, key, size_key, radii, presence_everywhere(1.0f), no_line_waves());
        vec3 point = scaled + vec3(offset) + vec3(system) - f;
        float height = length(point);
        if (abs(height - frequency) > shell) continue;
        float d = length(point * (frequency / height) - scaled) / system.w;
        float outline = rimmed_cloud(d, rims.x, rims.y, resolved_rim(rims.z, frequency, system.w, rims.w));
        float peak = mix(faintest, 1.0f, system_hashes(cell + offset, size_key).z);
        cloud = max(cloud, vec2(outline, outline * peak));
      }
  return cloud;
}
float gravel_clumps(vec3 p, uint seed, float edge, float texel_arc, int searched) {
  return trade_clump(p, 60.0f, seed, GRAVEL_LAYER, vec2(0.2f, 0.38f), 0.9f, GRAVEL_RIM, edge, texel_arc, searched);
}
// The flowers at p: x their outlines, y their cloud with each bouquet's peak (surface_disc_clouds).
vec2 flower_clumps(vec3 p, uint seed, float edge, float texel_arc, int searched) {
  vec3 q = tangent_warp(p, 80.0f, 0.006f, seed, FLOWERS_WARP_LAYER, SKIPPABLE(searched > 0, 2));
  return surface_disc_clouds(q, FLOWER_CELLS, seed, FLOWERS_LAYER, FLOWER_RADII, FLOWER_SHELL,
                             vec4(edge, FLOWER_EDGE_REACH, FLOWER_RIM, texel_arc), FLOWER_FAINTEST, searched);
}
float fish_clumps(vec3 p, uint seed, float edge, float texel_arc, int searched) {
  vec3 q = tangent_warp(p, 20.0f, 0.015f, seed, FISH_WARP_LAYER, SKIPPABLE(searched > 0, 2));
  return trade_clump(vec3(q.x, q.y, FISH_STRETCH * q.z), 5.0f, seed, FISH_LAYER, vec2(0.3f, 0.38f), 0.8f, FISH_RIM,
                     edge, texel_arc, searched);
}

// The trade cumulus' belt at geocentric `latitude` (radians): from about 6 to 30 degrees where
// the trades blow (Nuijens et al. 2014, "The distribution and variability of low-level cloud in
// the North Atlantic trades", QJRMS 140), full from 8 to 26.
float trade_cumulus_belt(float latitude) {
  float a = abs(latitude);
  return smoothstep(0.06f, 0.14f, a) * (1.0f - smoothstep(0.45f, 0.58f, a));
}

// The organised patterns' share of the trades' shallow cloud at a point of geocentric `latitude`
// with the patterns' weights `regimes` there (trade_regimes): 1 less sugar's weight, in the trade
// cumulus' belt, times their strength (--trade-cumulus; without their clumps nothing organises
// the cloud), in [0, 1] (cover_density.glsl's cover_contrast dims the cloud between the clumps).
float organised_trades(vec4 regimes, float latitude, float strength) {
  return clamp(strength, 0.0f, 1.0f) * trade_cumulus_belt(latitude) * (1.0f - regimes.x);
}

// The trades' patterns' weights at p where the belts draw them (trade_regimes; each a quarter
// elsewhere, where nothing uses them: outside the trade cumulus' belt or without its strength), so
// that the clumps (trade_cumulus) and the organised share (organised_trades) take one evaluation.
vec4 belt_regimes(vec3 p, float latitude, IN(WeatherSystems) systems, uint seed) {
  return trade_regimes(p, seed, SKIPPABLE(systems.trade_cumulus > 0.0f && trade_cumulus_belt(latitude) > 0.0f, 2));
}

// The trades' organised cumulus at p, in [0, 1]: each pattern's clumps by its weight and strength,
// in the trade cumulus' belt (trade_cumulus_belt), gravel's patchy where the cover's noise is low.
// Sugar draws no clumps: its cloud is the noise's dim shallow cloud (cover_density.glsl's
// cover_contrast). A pattern absent from a group of lanes costs no search. `regimes`: the patterns'
// weights at p (trade_regimes, or belt_regimes).
float trade_cumulus(vec3 p, float latitude, uint seed, float edge, vec4 regimes, float texel_arc) {
  float belt = trade_cumulus_belt(latitude);
  // Gravel's fields are patchy where the noise is low; flowers and fish fill their regions.
  float patchy = smoothstep(-0.4f, 0.2f, edge);
  float gravel = gravel_clumps(p, seed, edge, texel_arc, SKIPPABLE(belt > 0.0f && regimes.y > 0.0f, NEAR_CELLS));
  float fish = fish_clumps(p, seed, edge, texel_arc, SKIPPABLE(belt > 0.0f && regimes.z > 0.0f, NEAR_CELLS));
  float flowers =
      flower_clumps(p, seed, edge, texel_arc, SKIPPABLE(belt > 0.0f && regimes.w > 0.0f, NEIGHBOUR_CELLS)).y;
  float clumps = max(max(TRADE_PATTERN_STRENGTH.x * regimes.y * gravel * patchy, TRADE_PATTERN_STRENGTH.y * regimes.z * fish),
                     TRADE_PATTERN_STRENGTH.z * regimes.w * flowers);
  return belt > 0.0f ? belt * clumps : 0.0f;
}

// Cirrus streaks (docs/climate.md, "Cirrus streaks"): cirrus is "detached clouds in the form of
// white, delicate filaments or white or mostly white patches or narrow bands" (WMO International
// Cloud Atlas), and from above it lies in long bands and streaks drawn out along the upper-level
// wind, on the equatorward side of the jets (Conover 1960): streaks many times longer than wide.
// Inverted Worley fBm (2 octaves, gain 1/2) of CIRRUS_CELLS cells per radius (about 1600 km) at
// the point with its z (north) component stretched CIRRUS_STRETCH-fold has cells that narrow
// across the latitude circles by sqrt(sin^2 lat + s^2 cos^2 lat), 10 at the equator, 7.1 at 45
// degrees and 5.1 at 60: cut at CIRRUS_STREAK_EDGES, each feature point's peak is a streak some
// 1000-1500 km long and 100-250 km wide, the second octave's finer ones beside and within them.
// They lie in the storm tracks (35-65 degrees), along the jets, in sheets where a gradient noise
// of CIRRUS_SHEET_CELLS cells per radius (z stretched twofold) is high: cirrus comes in regions,
// not as an even dust of streaks. The flow bends them as it carries the air (they are drawn at its
// origin). Not in the deep tropics: there the upper-level cirrus is the deep convection's outflow,
// anvils spread from the systems (Houze 2004; the ITCZ's and SPCZ's anvils, itcz_systems), and
// the stretched lattice, narrowest at the equator, drew rows of parallel streaks 160 km apart that
// the flow's vortices combed into arcs, a grain over the trades' grey haze.
const float CIRRUS_CELLS = 4.0f;
const float CIRRUS_STRETCH = 10.0f;
const int CIRRUS_OCTAVES = 2;
const vec2 CIRRUS_STREAK_EDGES = vec2(0.45f, 0.75f);
const float CIRRUS_SHEET_CELLS = 3.0f;
const vec2 CIRRUS_SHEET_EDGES = vec2(0.0f, 0.2f);
const uint CIRRUS_SHEET_LAYER = 38u;
// The cirrus streaks' gate at geocentric `latitude` (radians): the storm tracks.
float cirrus_gate(float latitude) {
  float a = abs(latitude);
  return smoothstep(0.55f, 0.7f, a) * (1.0f - smoothstep(1.05f, 1.2f, a));
}
// The streaks' noise at p, in [1 - sqrt(3), 1] (1 on the feature points): `octaves` octaves
// (CIRRUS_OCTAVES, or 0: none, SKIPPABLE, and then 0) of the stretched inverted Worley fBm.
float cirrus_streak_noise(vec3 p, uint seed, int octaves) {
  FbmParams noise = make_fbm_params(CIRRUS_CELLS, octaves, 2.0f, 0.5f, seed ^ 0x2545F491u, ivec3(0));
  return inverted_worley_fbm(vec3(p.x, p.y, CIRRUS_STRETCH * p.z), noise).w;
}
// The sheets that hold the streaks, in [0, 1]: `noises` 1, or 0 (SKIPPABLE: 0 everywhere).
float cirrus_sheets(vec3 p, uint seed, int noises) {
  float sheets = -1.0f;
  for (int k = 0; k < noises; ++k)
    sheets = perlin_noise(CIRRUS_SHEET_CELLS * vec3(p.x, p.y, 2.0f * p.z), ivec3(0), noise_key(seed, CIRRUS_SHEET_LAYER));
  return smoothstep(CIRRUS_SHEET_EDGES.x, CIRRUS_SHEET_EDGES.y, sheets);
}
float cirrus_streaks(vec3 p, float latitude, uint seed) {
  float gate = cirrus_gate(latitude);
  // The sheets where the gate is open, and the streaks' searches in the sheets, none elsewhere
  // (SKIPPABLE: a group of lanes outside them runs one masked pass of the loops).
  float sheets = cirrus_sheets(p, seed, SKIPPABLE(gate > 0.0f, 1));
  float streaks = cirrus_streak_noise(p, seed, SKIPPABLE(gate > 0.0f && sheets > 0.0f, CIRRUS_OCTAVES));
  if (gate <= 0.0f) return 0.0f;
  return gate * sheets * smoothstep(CIRRUS_STREAK_EDGES.x, CIRRUS_STREAK_EDGES.y, streaks);
}

// Mesoscale cellular convection (docs/climate.md, "Cells"): marine boundary-layer cloud organises
// into cells some 30 times wider than the layer is deep (Agee, Chen and Dowell 1973, "A review of
// mesoscale cellular convection", BAMS 54), 10-50 km in the subtropics (Wood and Hartmann 2006,
// "Spatial variability of liquid water path in marine low cloud", J. Climate 19). Closed cells,
// cloudy cells with narrow clear rims, fill the cores of the subtropical stratocumulus decks over
// the coolest water; open cells, rings of cloud around clear centres, their fringes, where the
// deck breaks up towards the trades (Wood 2012), and the cold air behind the cyclones' cold fronts,
// where polar air streams over warmer sea. Both are Voronoi cells of a random lattice: closed
// cells 160 per radius (about 37 km across where the sphere cuts a cell), open cells 80 (about
// 75 km, in a deeper boundary layer).
const float CLOSED_CELLS = 160.0f;
const float OPEN_CELLS = 80.0f;
const uint CLOSED_CELLS_LAYER = 17u;
const uint OPEN_CELLS_LAYER = 18u;
const uint DECK_PATCHES_LAYER = 19u;
const uint STREETS_LAYER = 22u;  // the streets' phases (after the pockets' 20 and 21)
const uint STREET_PEARLS_LAYER = 23u;  // the clouds along them
// The patterns' means over the sphere (tests/test_weather_systems.cpp measures them), which the
// modulation subtracts so that the cells move cloud within a region rather than add it.
const float CLOSED_CELLS_MEAN = 0.77f;
const float OPEN_CELLS_MEAN = 0.47f;          // without the walls' clumps (open_cells' clumps 0)
const float OPEN_CELLS_CLUMPED_MEAN = 0.393f;  // with them (clumps 1)
// The patterns' amplitudes in the density's factor 1 + m (cover_density.glsl's with_cells): the
// closed cells' rims at 0.77 of the density against 1.07 inside (thinner, greyer cloud, clear
// only where the deck is thin), the open cells' walls of mean strength at 1.13 (from 1 for the
// weakest to 1.26 where rings meet) against their centres' 0.88;
// both steps (0.30 and 0.25 of the density) more than the noise's own spread of 16 %, so that the
// pattern prints where the cells are.
const float CLOSED_CELLS_CONTRAST = 0.3f;
const float OPEN_CELLS_CONTRAST = 0.25f;

// The feature point of the k-th of the NEIGHBOUR_CELLS cells around `cell` (worley.glsl's
// neighbour_offset), from the cell's lower corner.
vec3 neighbour_feature(ivec3 cell, int k, uvec3 key) {
  ivec3 offset = neighbour_offset(k);
  return vec3(offset) + wrapped_feature_offset(cell + offset, key);
}

// The distances (cells) from `scaled` to the border of its Voronoi cell in the lattice `key`, within
// the surface whose unit normal is `normal`: to the nearest (x) and the second nearest (y) of the
// lines where the bisector planes between the cell's feature point a and its neighbours' b cut the
// surface's tangent plane (both are small near a vertex, where three cells meet), and in z a
// number in [0, 1) of the nearest line's pair of cells, the same from either side of it (one for
// each wall between two cells). The plane's distance (|p - b|^2 - |p - a|^2) / (2 |b - a|) is
// divided by the sine of its normal's angle with the surface normal (at least 0.2), so that cells
// which the sphere cuts obliquely get rims as wide as the others' (F2 - F1 narrows them towards
// nothing). Exact where the cell's point and its Voronoi neighbours lie in the 27 cells around p
// (nearly everywhere).
// `searched`: the neighbour cells searched, NEIGHBOUR_CELLS; 0 where the caller needs no border
// (it gets 1e30, far from any), which lets a group of SIMD lanes none of which needs it skip the
// search (prelude.glsl, SKIPPABLE).
vec3 cell_borders(vec3 scaled, vec3 normal, uvec3 key, int searched) {
  vec3 base = floor(scaled);
  ivec3 cell = ivec3(base);
  vec3 f = scaled - base;
  int nearest = 0;
  float f1 = 1.0e30f;
  vec3 a = vec3(0.0f);
  for (int k = 0; k < searched; ++k) {
    vec3 to_feature = neighbour_feature(cell, k, key) - f;
    float d2 = dot(to_feature, to_feature);
    if (d2 < f1) {
      f1 = d2;
      nearest = k;
      a = to_feature;
    }
  }
  vec2 borders = vec2(1.0e30f);
  int across = nearest;
  // The neighbours' points hashed again rather than kept from the first loop in an array, which a
  // loop of a count the compiler cannot know would index in memory.
  for (int k = 0; k < searched; ++k) {
    if (k == nearest) continue;
    vec3 to_feature = neighbour_feature(cell, k, key) - f;
    vec3 ab = to_feature - a;
    float length_ab = length(ab);
    float plane = (dot(to_feature, to_feature) - f1) / (2.0f * length_ab);
    float along_normal = dot(ab, normal) / length_ab;
    float sine = sqrt(max(1.0f - along_normal * along_normal, 0.0f));
    float border = plane / max(sine, 0.2f);
    if (border < borders.x) across = k;
    borders = vec2(min(borders.x, border), min(borders.y, max(borders.x, border)));
  }
  // The pair's sum and the absolute difference of its cells name it whichever side p is on.
  ivec3 one = cell + neighbour_offset(nearest), other = cell + neighbour_offset(across);
  uvec3 pair = pcg3d(uvec3(one + other) ^ (uvec3(abs(one - other)) << 16u) ^ key);
  return vec3(borders, float(pair.x >> 8u) * (1.0f / 16777216.0f));
}

// The distance to the nearest border alone (cell_borders' x).
float cell_border(vec3 scaled, vec3 normal, uvec3 key, int searched) {
  return cell_borders(scaled, normal, key, searched).x;
}

// Closed cells at p: 1 inside the cells, 0 on their clear rims (within 0.03 of a cell of the border);
// `searched` as cell_border's (1 where 0).
float closed_cells(vec3 p, uint seed, int searched) {
  return smoothstep(0.03f, 0.08f, cell_border(p * CLOSED_CELLS, p, noise_key(seed, CLOSED_CELLS_LAYER), searched));
}

// Open cells at p: the cloud of the walls along the cells' borders, 0 in their clear centres (at
// most 1.5); `searched` as cell_borders' (0 where 0). Satellite images of open cells show rings of
// cumulus of varying brightness, thickest where the rings meet and broken in places (Agee et al.
// 1973; Wood and Hartmann 2006), not a net of one width and brightness:
// - each wall between two cells has a strength of its own, open_cell_wall(u) for its number u
//   (cell_borders' z, uniform in [0, 1)): none for one wall in twenty, 0.55 to 1.45 for most;
//   its half-width is 0.07 + 0.03 of that strength (cells), and its cloud that strength;
// - where three cells meet the walls' cloud gathers: within about a fifth of a cell of the
//   vertex up to 0.4 more cloud and 0.05 more half-width;
// - along the walls the cloud clumps: Perlin noise of OPEN_CELL_CLUMPS features a cell, of
//   unit-variance value z, scales the walls' strength by 1 + 0.8 z `clumps` (0 where the cover
//   does not resolve the clumps, which would alias into speckle; open_cell_modulation's weight).
const float OPEN_CELL_CLUMPS = 6.0f;
const uint OPEN_CELL_CLUMPS_LAYER = 28u;
float open_cell_wall(float u) { return smoothstep(0.05f, 0.25f, u) * (0.55f + 0.9f * u); }
float open_cells(vec3 p, uint seed, float clumps, int searched) {
  vec3 borders = cell_borders(p * OPEN_CELLS, p, noise_key(seed, OPEN_CELLS_LAYER), searched);
  float clump = 0.0f;
  for (int k = 0; k < (clumps > 0.0f ? min(searched, 1) : 0); ++k)
    clump = perlin_noise(p * (OPEN_CELLS * OPEN_CELL_CLUMPS), ivec3(0), noise_key(seed, OPEN_CELL_CLUMPS_LAYER)) /
            PERLIN_OCTAVE_SIGMA;
  float vertex = 1.0f - smoothstep(0.05f, 0.25f, borders.y);
  float wall = open_cell_wall(borders.z);
  float half_width = 0.07f + 0.03f * wall + 0.05f * vertex;
  float cloud = clamp(wall * (1.0f + 0.8f * clumps * clump) + 0.4f * vertex, 0.0f, 1.5f);
  return cloud * (1.0f - smoothstep(half_width - 0.04f, half_width + 0.04f, borders.x));
}

// How far a cover of texels `texel_arc` radians across resolves cells of `frequency` per radius:
// 0 below 2.5 texels a cell, where a point sample of the pattern (walls and rims a quarter of a
// cell wide) would alias into speckle and broken lines, 1 from five.
float cells_resolved(float frequency, float texel_arc) {
  return smoothstep(2.5f, 5.0f, 1.0f / (frequency * texel_arc));
}

// The strength of a stratocumulus deck at p in [0, 1]. With a land/ocean mask (surface_weight > 0)
// from the bias's deck term `surface` (surface_bias.hpp's surface_terms), full from 0.4 (off the
// west coasts: cloud_properties' decks); without one,
// patches some 2000 km across (Perlin noise of 3 cells per radius) in the decks' belt around 22
// degrees, the belt of surface_bias.cpp (Klein and Hartmann 1993).
float deck_strength(vec3 p, float latitude, uint seed, float surface, float surface_weight) {
  if (surface_weight > 0.0f) return clamp(surface / 0.4f, 0.0f, 1.0f);
  float belt = (abs(latitude) - 0.384f) / 0.157f;  // (|lat| - 22 degrees) / 9 degrees
  float band = exp(-belt * belt);
  if (band < 0.02f) return 0.0f;
  float patches = perlin_noise(p * 3.0f, ivec3(0), noise_key(seed, DECK_PATCHES_LAYER));
  return band * clamp((patches + 0.1f) / 0.4f, 0.0f, 1.0f);
}

// The distance behind the cold front's band in the cyclone's frame (head radii; negative ahead).
float behind_cold_front(vec2 xy) {
  vec2 axis = COLD_FRONT_JOIN - COLD_FRONT_TAIL_END;
  vec2 ahead = normalize(vec2(axis.y, -axis.x));
  return -dot(xy - COLD_FRONT_TAIL_END, ahead);
}

// The cold air behind a cyclone's cold front, in its frame (head radii, as comma_cloud): from 0.6
// to 2.5 radii behind the front's band, along its tail, equatorward of the low and beyond its
// head, where open cells fill the polar air (the cold-air outbreak's "popcorn" behind the dry
// slot) and, furthest behind the front, cloud streets (street_share).
float cold_sector(vec2 xy) {
  const vec2 tail_end = COLD_FRONT_TAIL_END;
  vec2 axis = COLD_FRONT_JOIN - tail_end;
  float along = dot(xy - tail_end, axis) / dot(axis, axis);
  float behind = behind_cold_front(xy);
  return smoothstep(0.6f, 1.0f, behind) * (1.0f - smoothstep(2.0f, 2.5f, behind)) * smoothstep(-0.1f, 0.2f, along) *
         (1.0f - smoothstep(0.8f, 1.1f, along)) * (1.0f - smoothstep(-0.6f, 0.0f, xy.y)) *
         smoothstep(0.8f, 1.2f, length(xy));
}

// The share of a cold sector's air in cloud streets at xy (the cyclone's frame): the air
// furthest behind the front, which has crossed the least warm sea since it left the cold ground,
// is in rolls; from 1.3 to 1.8 head radii behind the front they give way to the open cells that
// fill the rest, nearer the front (streets turn into cells downstream: Liu et al. 2004,
// "Simulation of cloud streets and cellular convection in a cold-air outbreak", GRL 31; the
// life cycle of EUMeTrain's satellite manual).
float street_share(vec2 xy) { return smoothstep(1.3f, 1.8f, behind_cold_front(xy)); }

// The cyclones' cold air at p: x the largest cold sector, by each one's strength, times the sea's
// share of the place `sea` in [0, 1] (1 without a land/ocean mask: over land the cold air's
// convection is the day's cumulus, not the marine boundary layer's cells and rolls); y the share of
// its air in streets (street_share). `near`: cyclones_near(p, systems), which cyclone_systems at
// the same point takes too.
vec2 cold_air(vec3 p, IN(WeatherSystems) systems, uint near, float sea) {
  vec2 air = vec2(0.0f);
  for (; near != 0u; near &= near - 1u) {
    int i = findLSB(near);
    vec2 xy = cyclone_frame(p, systems.cyclones[i]);
    if (dot(xy, xy) < 16.0f) {
      float cold = systems.cyclones[i].strength * cold_sector(xy);
      if (cold > air.x) air = vec2(cold, street_share(xy));
    }
  }
  return vec2(air.x * clamp(sea, 0.0f, 1.0f), air.y);
}
float cold_sectors(vec3 p, IN(WeatherSystems) systems) {
  return cold_air(p, systems, cyclones_near(p, systems), 1.0f).x;
}

// The storm tracks' cold air between the cyclones at the unit direction p of geocentric
// `latitude` (radians), in [0, 1]: where the flow's wind there (`wind`, tangent) blows towards the
// equator, the air does not rise (the flow's cyclonic depth `cyclonic` below the ascent that deepens
// the cloud, cloud_properties.glsl's ASCENT_ONSET to ASCENT_FULL) and the surface is sea (`sea` in
// [0, 1]; 1 without a land/ocean mask). Polar air streaming equatorward over warmer sea is the
// cold-air outbreak whose boundary layer convects into open cells (Agee et al. 1973); over the
// Southern Ocean open cells lie across the whole storm track, mostly in post-frontal cold air
// (Lang et al. 2022, "A climatology of open and closed mesoscale cellular convection over the
// Southern Ocean derived from Himawari-8 observations", ACP 22), more often than closed cells,
// and where the air is much colder than the sea (Lang et al. 2024, ACP 24), and the storm tracks
// hold the most open cells on Earth (Muhlbauer et al. 2014, ACP 14). The cyclones' own cold
// sectors (cold_sector) lie behind their cold fronts only; this is the rest of that air, between
// the systems. The storm tracks: 35-40 to 60-66 degrees, their poleward edge the ocean's polar
// front (Lang et al. 2022). The equatorward share is the wind's direction's component towards
// the equator, through a smoothstep from -0.2 to 0.4: full in air streaming within about 66
// degrees of due equatorward, none in air streaming poleward (warm advection, where closed
// cells and stratiform cloud lie: Lang et al. 2024).
float storm_track_cold_air(vec3 p, float latitude, vec3 wind, float cyclonic, float sea) {
  float a = abs(latitude);
  float belt = smoothstep(0.61f, 0.70f, a) * (1.0f - smoothstep(1.05f, 1.15f, a));
  vec3 north = vec3(0.0f, 0.0f, 1.0f) - p.z * p;  // the local north, of length cos(latitude)
  float scale = length(wind) * length(north);
  float equatorward = scale > 1.0e-12f ? -sign(p.z) * dot(wind, north) / scale : -1.0f;  // calm: none
  return clamp(sea, 0.0f, 1.0f) * belt * (1.0f - smoothstep(ASCENT_ONSET, ASCENT_FULL, cyclonic)) *
         smoothstep(-0.2f, 0.4f, equatorward);
}

// Cloud streets: rows of cumulus along the low-level wind over horizontal roll vortices in the
// boundary layer (Etling and Brown 1993, "Roll vortices in the planetary boundary layer: a
// review", Boundary-Layer Meteorol. 65), their spacing two to six boundary-layer depths; in
// satellite images of cold-air outbreaks parallel bands 20-200 km long and 2-10 km wide, wider
// away from the coast (EUMeTrain, "Cloud structure in satellite images"). Here 12 km apart
// (STREETS rows per radius: a 2 km deep layer, aspect ratio 6, as the cold air far from the
// coast has), drawn where the cover's texels resolve them (cells_resolved: from about 2700 texels
// a face).
const float STREETS = 531.0f;
// Phase anchors per radius (about 100 km apart): the streets' length before two merge or one ends.
const float STREET_ANCHORS = 64.0f;
// A street is not a continuous band but a row of separate cumulus, "pearls on a string", each
// over a thermal where the rolls' updrafts converge, spaced along the row at about the rows'
// own spacing (Etling and Brown 1993; Atkinson and Zhang 1996, "Mesoscale shallow convection
// in the atmosphere", Rev. Geophys. 34). Here the row is cut by the positive lobes of Perlin
// noise of a lattice as fine as the rows (street_pearls): clouds about the lattice's 12 km long
// along the row with gaps between them, placed independently on neighbouring rows.
const float STREET_PEARLS = STREETS;
// street_clouds' mean over any region: the rows' 1/2 (their phase is uniform, their profile odd
// about 1/2) times the pearls' 1/2 (Perlin noise is symmetric about 0, their profile odd about
// 1/2), the two independent.
const float STREETS_MEAN = 0.25f;
// The modulation's step: as the closed cells', cloud from between the rows onto them.
const float STREET_CONTRAST = 0.3f;

// Rows across `across` (a unit tangent at the unit vector p, perpendicular to the wind): 1 on a
// row, 0 between. A phasor noise (Tricard et al. 2019, "Procedural phasor noise", ACM TOG 38(4)):
// each anchor of a lattice of STREET_ANCHORS per radius carries a plane wave across the wind with
// a phase of its own; the waves summed as complex numbers with weights of a smooth partition of
// unity keep one phase and full contrast between anchors, and where neighbours' phases disagree a
// row ends or two merge into one, as streets do. street_phasor is the sum, street_rows the rows.
vec2 street_phasor(vec3 p, vec3 across, uint seed) {
  vec3 x = p * STREET_ANCHORS;
  vec3 base = floor(x);
  vec3 f = x - base;
  vec3 w = f * f * f * (f * (f * 6.0f - 15.0f) + 10.0f);
  uvec3 key = noise_key(seed, STREETS_LAYER);
  vec2 sum = vec2(0.0f);
  for (int k = 0; k < 8; ++k) {
    vec3 corner = vec3(float(k & 1), float((k >> 1) & 1), float((k >> 2) & 1));
    vec3 anchor = base + corner;
    float weight = mix(1.0f - w.x, w.x, corner.x) * mix(1.0f - w.y, w.y, corner.y) * mix(1.0f - w.z, w.z, corner.z);
    float own = hash_to_unit3(pcg3d(uvec3(ivec3(anchor)) ^ key)).x;
    // Whole cycles dropped before the sine and cosine, whose accuracy falls with the argument.
    float phase = 2.0f * PI_F * fract((STREETS / STREET_ANCHORS) * dot(x - anchor, across) + own);
    sum += weight * vec2(cos(phase), sin(phase));
  }
  return sum;
}
float street_rows(vec3 p, vec3 across, uint seed) {
  vec2 sum = street_phasor(p, across, seed);
  float magnitude = length(sum);
  float wave = magnitude > 1.0e-6f ? sum.x / magnitude : 0.0f;
  return smoothstep(-0.6f, 0.6f, wave);
}
// The pearls: 1 in the positive lobes of the noise, 0 in the negative, with edges a third of the
// noise's deviation (PERLIN_OCTAVE_SIGMA, 0.27) wide.
float street_pearls(vec3 p, uint seed) {
  return smoothstep(-0.05f, 0.05f, perlin_noise(p * STREET_PEARLS, ivec3(0), noise_key(seed, STREET_PEARLS_LAYER)));
}
// The streets' clouds: 1 on a pearl of a row, 0 between rows and between pearls.
float street_clouds(vec3 p, vec3 across, uint seed) { return street_rows(p, across, seed) * street_pearls(p, seed); }

// The streets' part of the density's modulation (with_cells' m) at p: `wind` the flow's velocity
// there, `weight` the cold air's share in streets (cold_air's x times y) times their strength,
// texels texel_arc radians across. Zero on average, as the cells'.
float street_modulation(vec3 p, vec3 wind, float weight, uint seed, float texel_arc) {
  float w = weight * cells_resolved(STREETS, texel_arc);
  vec3 along = wind - dot(wind, p) * p;
  float speed = length(along);
  if (w <= 0.0f || speed < 1.0e-6f) return 0.0f;
  return STREET_CONTRAST * w * (street_clouds(p, cross(p, along) / speed, seed) - STREETS_MEAN);
}

// Where a deck of strength d is (its fringe from 0.1, whole from 0.3).
float deck_presence(float deck) { return smoothstep(0.1f, 0.3f, deck); }

// How far a deck of strength d organises its cloud into a bright sheet (cloud_properties.glsl's
// organised_cloud), in [0, 1]: from none at strength 0 to all from DECK_ORGANISED.
const float DECK_ORGANISED = 0.8f;
float deck_organisation(float deck) { return smoothstep(0.0f, DECK_ORGANISED, deck); }

// A deck's strength d with its edge frayed by the cover's noise `edge` in [-1, 1]
// (cover_density.glsl's system_edge): d (1 + DECK_FRAY edge). The strength is a smooth field of
// the place (the land/ocean bias's deck term, or the noise's patches without a mask), whose
// contours are smooth lines across the cloud. Moved by the noise, the deck's edge follows the
// cloud's own texture, as the systems' bands do (comma_cloud's `edge`): the deck reaches further
// where the cloud is thick and withdraws where it is thin, and breaks up into the trades' cumulus
// in patches, as a deck's edge in satellite images does (the stratocumulus-to-cumulus transition;
// Wood 2012, "Stratocumulus clouds", Mon. Wea. Rev. 140). A product, so that no deck appears where
// its strength is 0, and its core (strength 1) stays a deck at any noise (0.25 and more: presence
// 0.84).
const float DECK_FRAY = 0.75f;
float frayed_deck(float deck, float edge) {
  return clamp(deck * (1.0f + DECK_FRAY * clamp(edge, -1.0f, 1.0f)), 0.0f, 1.0f);
}

// The weights of closed (x) and open (y) cells from a deck's strength d and the cold sectors':
// a deck is there from d 0.1 (its fringe, open) and closed from d 0.4 to 0.8 (its core).
vec2 cell_weights(float deck, float cold) {
  float present = deck_presence(deck);
  float closed = smoothstep(0.4f, 0.8f, deck);
  return vec2(closed, max(present - closed, cold));
}

// Pockets of open cells (Stevens et al. 2005, "Pockets of open cells and drizzle in marine
// stratocumulus", BAMS 86): regions of open cells inside a closed deck, sharply bordered, with
// cell interiors depleted of cloud water or clear, long-lived and larger than 1e4 km^2 (Smalley
// et al. 2022, "A Lagrangian analysis of pockets of open cells over the southeastern Pacific",
// ACP 22). Here the places where gradient noise of 8 cells per radius (a wavelength of about 800
// km), frayed by a quarter as much of 32, exceeds 1.65 deviations: irregular pockets a few
// hundred km across on about 5 % of the sphere; 1 inside, 0 outside, the step a tenth of a
// deviation wide. `octaves`: POCKET_OCTAVES, or 0 where no pocket is needed (none then; SKIPPABLE). Inside, the deck's closed weight goes to the open cells (with_pockets) and the
// density thins by POCKET_THINNING of it, so the pockets are darker than the deck around them.
const uint POCKETS_LAYER = 20u;  // and 21 (the borders' noise)
const float POCKET_THINNING = 0.2f;
const int POCKET_OCTAVES = 2;
float open_cell_pockets(vec3 p, uint seed, int octaves) {
  float n = 0.0f, amplitude = 1.0f, frequency = 8.0f;
  for (int octave = 0; octave < octaves; ++octave) {
    n += amplitude * perlin_noise(p * frequency, ivec3(0), noise_key(seed, POCKETS_LAYER + uint(octave)));
    amplitude *= 0.25f;
    frequency *= 4.0f;
  }
  float threshold = 1.65f * PERLIN_OCTAVE_SIGMA * 1.0308f;  // the sum's deviation: sqrt(1 + 1/16)
  return smoothstep(threshold - 0.05f * PERLIN_OCTAVE_SIGMA, threshold + 0.05f * PERLIN_OCTAVE_SIGMA, n);
}

// The cell weights (closed, open) with the closed cells of a pocket (share `pocket`) turned open.
vec2 with_pockets(vec2 weights, float pocket) {
  return vec2(weights.x * (1.0f - pocket), min(1.0f, weights.y + weights.x * pocket));
}

// The cells' modulation of the density at p, zero on average over a region of one weight: the
// closed and the open pattern less their means, by their weights, faded out where the cover's
// texels (texel_arc radians) do not resolve them.
// Its two parts, so that a shader can leave out the pattern a cover does not resolve
// (cover_density.comp: on llvmpipe a branch not taken still runs for its group of lanes).
float closed_cell_modulation(vec3 p, float weight, uint seed, float texel_arc) {
  float closed = weight * cells_resolved(CLOSED_CELLS, texel_arc);
  float cells = closed_cells(p, seed, SKIPPABLE(closed > 0.0f, NEIGHBOUR_CELLS));
  return closed > 0.0f ? closed * CLOSED_CELLS_CONTRAST * (cells - CLOSED_CELLS_MEAN) : 0.0f;
}
float open_cell_modulation(vec3 p, float weight, uint seed, float texel_arc) {
  float open = weight * cells_resolved(OPEN_CELLS, texel_arc);
  float clumps = cells_resolved(OPEN_CELLS * OPEN_CELL_CLUMPS, texel_arc);
  float cells = open_cells(p, seed, clumps, SKIPPABLE(open > 0.0f, NEIGHBOUR_CELLS));
  // The pattern's mean between its two measured ends (within 0.007 of the truth between them).
  float mean = mix(OPEN_CELLS_MEAN, OPEN_CELLS_CLUMPED_MEAN, clumps);
  return open > 0.0f ? open * OPEN_CELLS_CONTRAST * (cells - mean) : 0.0f;
}
float cell_modulation(vec3 p, vec2 weights, uint seed, float texel_arc) {
  return closed_cell_modulation(p, weights.x, seed, texel_arc) + open_cell_modulation(p, weights.y, seed, texel_arc);
}

// How much of a front's cloud survives at p: all of it poleward of 22 degrees, none equatorward of
// 12. A cold front lives on the temperature contrast across it, which fades over the warm
// subtropical sea; its trailing end decays into a shear line of broken low cloud in the trades
// (frontolysis; Bluestein 1993, "Synoptic-Dynamic Meteorology in Midlatitudes" II, on fronts'
// decay), so the commas' tails, three head radii long, stop short of the deep tropics instead of
// reaching the equator from the storm tracks' southern edge. By sin(latitude), |p.z|: sin 12 degrees is
// 0.2079 (below 0.208), sin 22 degrees 0.3746.
float frontal_reach(vec3 p) { return smoothstep(0.208f, 0.3746f, abs(p.z)); }

// The cyclones' cloud at p: the largest of their commas, as far as fronts reach (frontal_reach).
// `near`: cyclones_near(p, systems).
float cyclone_systems(vec3 p, IN(WeatherSystems) systems, uint near, float edge) {
  float cloud = 0.0f;
  for (; near != 0u; near &= near - 1u)
    cloud = max(cloud, cyclone_cloud(p, systems.cyclones[findLSB(near)], edge));
  return cloud * frontal_reach(p);
}

// The belts' weights in the density at p with the noise of `seed`: ITCZ clusters at full weight
// (thick cloud), trade cumulus at 0.6, cirrus and the clusters' anvils at 0.35 (thin: they rise
// little above the threshold and stay grey); x the clusters, y the cumulus, z the cirrus, and w the
// anvils' own field (in [0, 1], unweighted: part of z, told apart for their cloud type).
// `regimes`: the trades' patterns' weights at p (belt_regimes). p is the air's origin; `band` the
// ITCZ's band at the texel's own direction (itcz_band).
const vec3 BELT_WEIGHTS = vec3(1.0f, 0.6f, 0.35f);
vec4 belt_fields(vec3 p, float band, float latitude, IN(WeatherSystems) systems, uint seed, float edge, vec4 regimes,
                 float texel_arc) {
  vec4 fields = vec4(0.0f);
  if (systems.trade_cumulus > 0.0f)
    fields.y = BELT_WEIGHTS.y * systems.trade_cumulus * trade_cumulus(p, latitude, seed, edge, regimes, texel_arc);
  if (systems.cirrus > 0.0f) fields.z = BELT_WEIGHTS.z * systems.cirrus * cirrus_streaks(p, latitude, seed);
  if (systems.itcz > 0.0f) {
    vec2 itcz = systems.itcz * itcz_systems(p, band, latitude, systems.itcz_latitude, systems.itcz_waves, seed, edge);
    fields.x = itcz.x;
    // The systems' anvils are cirrus: thin (the cirrus's weight) and high.
    fields.z = max(fields.z, BELT_WEIGHTS.z * itcz.y);
    fields.w = itcz.y;
  }
  return fields;
}
// The belts' fields over the surface of land/ocean bias `surface` (surface_bias.cpp; 0 without
// a mask): trade cumulus grow in the marine boundary layer (Nuijens et al. 2014), so over the
// subtropical deserts, whose bias is minus their desert weight (about -1 inside the Sahara, -0.3
// in the Sahel in June), their field fades to nothing at a bias of -0.4.
vec4 belts_over_surface(vec4 fields, float surface) {
  fields.y *= 1.0f - smoothstep(0.0f, 0.4f, -surface);
  return fields;
}
// The belts' cloud from their weighted fields: the largest.
float belt_cloud(vec4 fields) { return max(max(fields.x, fields.y), max(fields.z, 0.0f)); }
// The cloud types at a texel from the cyclones' cloud and the belts' weighted fields, each divided
// by its weight so that a system's core is 1 (cloud_properties.glsl's CloudTypes).
CloudTypes cloud_types(float cyclones, vec4 fields) {
  CloudTypes types;
  types.frontal = cyclones;
  types.deep_convection = fields.x / BELT_WEIGHTS.x;
  types.cumulus = fields.y / BELT_WEIGHTS.y;
  types.cirrus = fields.z / BELT_WEIGHTS.z;
  types.anvil = fields.w;
  return types;
}
// How far the systems' own cloud hides the boundary layer's convective cells and streets from
// above, in [0, 1]: the comma clouds' frontal cloud and the ITCZ's convective systems are deep
// (tops from 6 km to the tropopause, cloud_properties.glsl's cloud_top_km) and optically thick, so
// that a satellite sees their tops and not the cells below them; the cells show in the cold air
// behind the fronts and on the decks, where nothing covers the boundary layer (Agee et al. 1973).
float cells_hidden(IN(CloudTypes) types) { return clamp(max(types.frontal, types.deep_convection), 0.0f, 1.0f); }
// The ITCZ's band at the texel's own direction `now` with the cover's noise as `edge` (belt_fields).
float itcz_band(vec3 now, IN(WeatherSystems) systems, float edge) {
  return itcz_line_band(now, systems.itcz_latitude, systems.itcz_waves, edge, systems.seed);
}
float belt_systems(vec3 p, vec3 now, float latitude, IN(WeatherSystems) systems, uint seed, float edge, float texel_arc) {
  return belt_cloud(belt_fields(p, itcz_band(now, systems, edge), latitude, systems, seed, edge,
                                belt_regimes(p, latitude, systems, seed), texel_arc));
}

// All systems at the unit direction p of geocentric latitude `latitude` (radians; `now` the
// texel's own direction, belt_fields), with the cover's
// noise as `edge` in [-1, 1] and the belts' noise of systems.seed, for texels texel_arc radians
// across: the larger of the two fields.
float weather_density(vec3 p, vec3 now, float latitude, IN(WeatherSystems) systems, float edge, float texel_arc) {
  return max(cyclone_systems(p, systems, cyclones_near(p, systems), edge),
             belt_systems(p, now, latitude, systems, systems.seed, edge, texel_arc));
}

#endif
