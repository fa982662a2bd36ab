#version 450
// Pass 4a: cloud density, inverted Worley fBm sampled through the warp, shaped by the flow's
// cyclonic depth at the texel (the curl field's w: cyclones cloudy) and by the land/ocean bias
// (--surface; a zero weight without one), plus the weather systems (weather_systems.glsl) with
// edges frayed by the same noise and the convective cells of the stratocumulus decks and of the
// cyclones' cold air, and that cold air's cloud streets. The pass also reduces the densities' range into
// DensityRange, which the calibration then needs no pass of its own to find: each invocation
// walks a strip of u_strip texels down a column (as the reductions of coverage_histogram.comp)
// and adds its strip's range with two atomics. (A reduction in shared memory needs a barrier,
// which on llvmpipe cost more than the pass it saved.)
layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;
layout(rgba32f, binding = 0) uniform readonly image2DArray warp_field;
layout(r32f, binding = 1) uniform writeonly image2DArray density_field;
layout(rgba32f, binding = 2) uniform readonly image2DArray curl_field;
// The land/ocean bias's terms (deck, desert, sea; surface_bias.hpp's surface_terms): equirect, row 0
// north, longitude -180 at s = 0.
layout(binding = 3) uniform sampler2D surface_bias;
layout(r32f, binding = 5) uniform writeonly image2DArray cloud_top_field;  // km above sea level
// The share of a cloudy texel's excess over the threshold that its cover shows (cover_density.glsl).
layout(r32f, binding = 6) uniform writeonly image2DArray cover_contrast_field;
// MOVING_LAYERS 1 (--flow moving): two cloud layers of their own noise, warp_field the older's
// points and young_warp_field the younger's, blended with the younger's share u_young_share.
#ifndef MOVING_LAYERS
#define MOVING_LAYERS 0
#endif
#if MOVING_LAYERS
layout(rgba32f, binding = 4) uniform readonly image2DArray young_warp_field;
#endif
// CLOSED_CELLS_DRAWN and OPEN_CELLS_DRAWN (the host's cell_patterns_drawn, cover/weather_systems.hpp):
// 1 where --stratocumulus-cells is above 0 and the cover's texels resolve the pattern. A pattern
// left out costs nothing; one compiled in costs its Worley search at every texel on llvmpipe,
// whatever its weight, since a branch not taken still runs for its whole group of lanes.
#ifndef CLOSED_CELLS_DRAWN
#define CLOSED_CELLS_DRAWN 1
#endif
#ifndef OPEN_CELLS_DRAWN
#define OPEN_CELLS_DRAWN 1
#endif
// STREETS_DRAWN: the cold air's cloud streets, where --cloud-streets is above 0 and the texels
// resolve them (from about 2700 per face).
#ifndef STREETS_DRAWN
#define STREETS_DRAWN 1
#endif
// The ITCZ's cells come from the tables the pass itcz_cells.comp made for the frame: entry e at e
// for the steady flow's one cloud layer, at 2 e + k for the moving flow's layer k (0 the older's
// belts' seed, u_systems.seed; 1 the younger's, u_young_systems_seed).
#define CONVECTIVE_CELL_TABLES 1
layout(std430, binding = 9) readonly buffer ItczCells { vec4 itcz_cells[]; };
#if MOVING_LAYERS
uniform uint u_young_systems_seed;  // the younger layer's belts (u_systems.seed: the older's)
#define TABLED_CONVECTIVE_CELL(seed, entry) itcz_cells[2 * (entry) + ((seed) == u_young_systems_seed ? 1 : 0)]
#else
#define TABLED_CONVECTIVE_CELL(seed, entry) itcz_cells[entry]
#endif
#include "../lib/cover_density.glsl"
#include "../lib/weather_systems.glsl"
#include "../lib/cloud_properties.glsl"
#include "../lib/portable_math.glsl"
#include "../lib/cube_faces.glsl"
#include "../lib/equirect_mapping.glsl"
#include "reduction_words.glsl"
#include "cube_tile.glsl"

// Words 0, 1: sortable bits of the smallest and largest density (reset by the host).
layout(std430, binding = 8) buffer DensityRange { uint density_range[]; };
uniform int u_strip;

uniform FbmParams u_cover;
uniform vec3 u_noise_offset;  // reduced modulo the lattice period by the host
// The noise's octaves that the warp grid carries in the warp fields' w (moving_warp.comp; 0: none,
// and the w then means something else or nothing).
uniform int u_grid_octaves;
uniform float u_cyclone_cloudiness;
uniform float u_surface_weight;
uniform WeatherSystems u_systems;
#if MOVING_LAYERS
uniform FbmParams u_young_cover;  // the younger layer's noise (its own seed)
uniform float u_young_share;
#endif

// The geocentric latitude (radians) of a layer's origin, a unit vector.
float origin_latitude(vec3 origin) { return portable_asin(clamp(origin.z, -1.0f, 1.0f)); }

// The belts' fields at a layer's origin of geocentric `latitude` (belt_fields; `band` the ITCZ's band
// at the texel's own direction, itcz_band) and in `organised` the trades' organised share there
// (organised_trades), from one evaluation of the trades' patterns; texels texel_arc radians across.
vec4 belts_at(vec3 origin, float band, float latitude, uint seed, float edge, float texel_arc, OUT(float) organised) {
  vec4 regimes = belt_regimes(origin, latitude, u_systems, seed);
  organised = organised_trades(regimes, latitude, u_systems.trade_cumulus);
  return belt_fields(origin, band, latitude, u_systems, seed, edge, regimes, texel_arc);
}

// The stratocumulus deck's strength at a layer's origin of geocentric `latitude` (x; from the bias's deck term `deck_term`
// where there is a land/ocean mask, its edge frayed by the cover's noise `edge`) and the
// convective cells' modulation there (y: the patterns drawn), with the cyclones' cold sectors
// `cold` and texels texel_arc radians across; z the open cells' weight, by which their cloud is
// dimmed (cover_density.glsl's cover_contrast), drawn or not (the decks' pockets only where the
// open pattern is drawn, as their thinning).
vec3 cells_at(vec3 origin, float latitude, uint seed, float deck_term, float cold, float texel_arc, float edge) {
  float deck = frayed_deck(deck_strength(origin, latitude, seed, deck_term, u_surface_weight), edge);
  vec2 weights = cell_weights(deck, cold);
  float m = 0.0f;
#if OPEN_CELLS_DRAWN
  // Pockets of open cells in the decks' closed cores, thinner than the deck (without the open
  // pattern they draw nothing).
  float pocket = open_cell_pockets(origin, seed, SKIPPABLE(weights.x > 0.0f, POCKET_OCTAVES));
  m -= POCKET_THINNING * pocket * weights.x;
  weights = with_pockets(weights, pocket);
#endif
#if CLOSED_CELLS_DRAWN
  m += closed_cell_modulation(origin, weights.x, seed, texel_arc);
#endif
#if OPEN_CELLS_DRAWN
  m += open_cell_modulation(origin, weights.y, seed, texel_arc);
#endif
  return vec3(deck, u_systems.cells * m, u_systems.cells * weights.y);
}

void main() {
  int size = u_face_size;
  int i = int(gl_GlobalInvocationID.x), layer = int(gl_GlobalInvocationID.z);
  int first = u_tile_rows.x + int(gl_GlobalInvocationID.y) * u_strip;
  if (i >= size || first >= u_tile_rows.y) return;
  int last = min(u_tile_rows.y, first + u_strip);
  float texel_arc = 2.0f / float(size);  // radians, at a face's centre (the largest texels)
  uint low = 0xFFFFFFFFu, high = 0u;
  for (int j = first; j < last; ++j) {
    ivec3 texel = ivec3(i, j, layer);
    vec4 warp_sample = imageLoad(warp_field, texel);
    vec3 warped = warp_sample.xyz;
    ivec3 at = face_texel(texel);
    vec3 direction = texel_direction(at.z, at.x, at.y, size);
    vec3 surface_terms = u_surface_weight > 0.0f ? texture(surface_bias, equirect_uv(direction)).xyz : vec3(0.0f, 0.0f, 1.0f);
    float surface = surface_terms.x - surface_terms.y;  // the bias b = deck - desert
    float sea = mix(1.0f, surface_terms.z, clamp(u_surface_weight, 0.0f, 1.0f));
    bool gridded = u_grid_octaves > 0;
    float noise = cover_density_from_grid(warped, gridded ? warp_sample.w : 0.0f, u_grid_octaves, u_cover, u_noise_offset);
#if MOVING_LAYERS
    vec4 young_sample = imageLoad(young_warp_field, texel);
    vec3 young_warped = young_sample.xyz;
    noise = noise_blend(noise,
                        cover_density_from_grid(young_warped, gridded ? young_sample.w : 0.0f, u_grid_octaves,
                                                u_young_cover, u_noise_offset),
                        u_young_share);
#endif
    // The cyclones move on their own (the host places them at the frame's time) and are drawn at
    // the air's origin so that the flow deforms them as it does the noise: with two layers at
    // the origin slid from the older's to the younger's by its share, which is continuous as
    // the younger layer becomes the older. The belts' clusters, cumulus and cirrus are carried by
    // the flow as the noise is: drawn at each layer's origin with the layer's own noise and
    // blended as it.
    float edge = system_edge(noise);
    vec3 origin = normalize(warped);
    float older_latitude = origin_latitude(origin);  // each layer's origin's, for its belts and its cells
    float organised;  // the trades' organised share, blended between the layers as the belts
    float band = itcz_band(direction, u_systems, edge);  // the ITCZ's, at the texel: both layers'
    vec4 fields = belts_over_surface(belts_at(origin, band, older_latitude, u_systems.seed, edge, texel_arc, organised), surface);
    float belts = belt_cloud(fields);
    vec3 older_origin = origin;
#if MOVING_LAYERS
    vec3 young_origin = normalize(young_warped);
    float young_latitude = origin_latitude(young_origin);
    float young_organised;
    vec4 young_fields = belts_over_surface(
        belts_at(young_origin, band, young_latitude, u_young_systems_seed, edge, texel_arc, young_organised), surface);
    organised = layer_blend(organised, young_organised, u_young_share);
    belts = layer_blend(belts, belt_cloud(young_fields), u_young_share);
    fields = mix(fields, young_fields, u_young_share);
    origin = normalize(mix(warped, young_warped, u_young_share));
#endif
    uint near = cyclones_near(origin, u_systems);  // for the commas and the cold sectors alike
    float cyclones = cyclone_systems(origin, u_systems, near, edge);
    float systems = max(cyclones, belts);
    // The cells as the belts, each layer its own, in the cold sectors of the cyclones as drawn.
    // The cold sectors' open cells dim their cloud whether the cover resolves them or not
    // (cover_contrast), so they are found at any size.
    vec2 cold_sector_air = cold_air(origin, u_systems, near, sea);  // over the sea
    vec4 curl = imageLoad(curl_field, texel);
#if STREETS_DRAWN
    // The streets take their share of the cold air from the open cells, and lie along the flow's
    // wind at the texel (the rolls align with the present low-level wind, wherever the air came from).
    float cold = cold_sector_air.x * (1.0f - cold_sector_air.y);
    float streets = street_modulation(direction, curl.xyz, u_systems.streets * cold_sector_air.x * cold_sector_air.y,
                                      u_systems.seed, texel_arc);
#else
    float cold = cold_sector_air.x;
    float streets = 0.0f;
#endif
    // Beside the cyclones' cold sectors, the rest of the storm tracks' cold air streaming towards
    // the equator over the sea: open cells there too (no streets: those need the cold sector's
    // fresh outbreak off the ice or the land).
    float latitude = portable_asin(clamp(direction.z, -1.0f, 1.0f));
    float storm_track = storm_track_cold_air(direction, latitude, curl.xyz, curl.w, sea);
    cold = max(cold, storm_track);
    vec3 cells = cells_at(older_origin, older_latitude, u_systems.seed, surface_terms.x, cold, texel_arc, edge);
#if MOVING_LAYERS
    cells = mix(cells,
                cells_at(young_origin, young_latitude, u_young_systems_seed, surface_terms.x, cold, texel_arc, edge),
                u_young_share);
#endif
    float cyclonic = curl.w;
    CloudTypes types = cloud_types(cyclones, fields);
    float deck = deck_organisation(cells.x);
    // In the trades the cloud no system organises is shallow cumulus or thin cirrus: dim between
    // the systems, and dimmer and sparser between the organised patterns' clumps (each layer's
    // patterns at its own origin, blended as the belts).
    float shallow = shallow_trades_weight(types, latitude, deck, u_systems.shallow_trades);
    // The cells and streets are the boundary layer's: none show through a front's or a convective
    // system's deep cloud.
    float density = with_moats(
        with_cells(with_systems(shaped_density(noise, cyclonic, u_cyclone_cloudiness, surface, u_surface_weight), systems),
                   (cells.y + streets) * (1.0f - cells_hidden(types))),
        trade_moat(shallow, organised, types.cumulus));
    imageStore(density_field, texel, vec4(density, 0.0f, 0.0f, 0.0f));
    // The open cells' cloud is dim (cover_contrast), and so is the streets' (rows of cumulus over
    // as much clear sea): the whole cold sector's, streets drawn or not.
    float open_cloud = max(cells.z, u_systems.cells * cold_sector_air.x);
    float contrast = cover_contrast(shallow, organised, open_cloud * (1.0f - cells_hidden(types)));
    imageStore(cover_contrast_field, texel, vec4(contrast, 0.0f, 0.0f, 0.0f));
    // The cloud's top by its types (the remap clears it where the texel stays clear).
    imageStore(cloud_top_field, texel, vec4(cloud_top_km(types, latitude, cyclonic, deck), 0.0f, 0.0f, 0.0f));
    low = min(low, sortable_bits(density));
    high = max(high, sortable_bits(density));
  }
  atomicMin(density_range[0], low);
  atomicMax(density_range[1], high);
}
