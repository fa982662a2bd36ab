// What covers the ground of the views near the ground (docs/terrain.md, Land cover): lakes,
// rivers and towns from the land cover texture (regional::LandCoverGrid), and, drawn by
// procedure, the Plateau's fields and forest, rock, and snow above the season's snow line.
// Every pattern finer than the pixel's footprint on the ground fades to its mean colour, so
// that distant ground shows no moire. The texture `land` (LandCoverTexture) holds a layer per
// level (0 near, 1 far), sampled at uv in [0, 1]^2 like the height field:
//   red    signed distance (m) to the nearest shore or river bank, negative in the water
//   green  built-up fraction
#ifndef NEPHELE_LAND_COVER_GLSL
#define NEPHELE_LAND_COVER_GLSL
#include "prelude.glsl"
#include "render_types.glsl"
#include "hash.glsl"
#include "perlin.glsl"

// Broadband albedos (Oke, Boundary Layer Climates, 2nd ed., 1987, table 1.1: grass 0.16-0.26,
// crops 0.18-0.25, coniferous forest 0.05-0.15, towns 0.10-0.27, old snow 0.40-0.70, water at
// high sun 0.03-0.10), as RGB that keep the vegetation's green darker than its near infrared.
const vec3 LAND_MEADOW = vec3(0.09f, 0.15f, 0.06f);
const vec3 LAND_PASTURE = vec3(0.07f, 0.12f, 0.05f);
const vec3 LAND_CROP = vec3(0.20f, 0.18f, 0.10f);        // ripe cereals
const vec3 LAND_CROP_GREEN = vec3(0.08f, 0.14f, 0.05f);  // cereals before they ripen
const vec3 LAND_SOIL = vec3(0.14f, 0.11f, 0.08f);
const vec3 LAND_FOREST = vec3(0.035f, 0.06f, 0.03f);
const vec3 LAND_ROCK = vec3(0.20f, 0.19f, 0.17f);
const vec3 LAND_SNOW = vec3(0.80f, 0.82f, 0.85f);
const vec3 LAND_ROOF_TILE = vec3(0.25f, 0.12f, 0.08f);
const vec3 LAND_ROOF_GREY = vec3(0.17f, 0.17f, 0.18f);
const vec3 LAND_STREET = vec3(0.09f, 0.09f, 0.09f);
// Light scattered back from under a lake's surface (the diffuse part; the surface's own
// reflection is Fresnel's, sun_glint.glsl).
const vec3 WATER_ALBEDO = vec3(0.02f, 0.035f, 0.04f);

const float FIELD_SIZE = 180.0f;     // m, a parcel's length on the Plateau (its width 0.6 of that)
const float BLOCK_SIZE = 40.0f;      // m, a town's block of buildings with its street
const float FOREST_SCALE = 1500.0f;  // m, the largest patches of forest
const float TREE_LINE = 1900.0f;     // m above sea level, the northern Alps' upper forest limit
const float LAKE_WIND = 3.0f;        // m/s, the wind that roughens the lakes (sun_glint.glsl)

// The land cover at a horizontal coordinate: (water distance, built-up fraction, the band within
// which the distance is exact: 8 texels of the level read), from the near level where the point
// lies inside it, else the far one; far from any water and unbuilt outside both and without
// land cover.
vec3 land_sample(vec2 xy, IN(TerrainParams) t, IN(LandCoverTexture) land) {
  if (t.land == 0) return vec3(1.0e4f, 0.0f, 1.0e4f);
  float reach = max(abs(xy.x), abs(xy.y));
  // A texel short of the near level's edge, where its bilinear taps are still its own.
  float near_inside = t.land_near * (1.0f - 2.0f / t.land_texels);
  float texel_per_extent = 2.0f / t.land_texels;
  if (reach < near_inside)
    return vec3(vec2(texture(land, vec3(0.5f + 0.5f * xy / t.land_near, 0.0f))), 8.0f * texel_per_extent * t.land_near);
  if (reach < t.land_far)
    return vec3(vec2(texture(land, vec3(0.5f + 0.5f * xy / t.land_far, 1.0f))), 8.0f * texel_per_extent * t.land_far);
  return vec3(1.0e4f, 0.0f, 1.0e4f);
}

// The share of a pixel's footprint (m across) that lies in the water, from a land_sample: the
// signed distance's zero contour drawn with an edge as wide as the footprint, but never wider
// than half the level's exact band, beyond which the distance is clamped.
float water_coverage(vec3 cover, float footprint) {
  float edge = clamp(footprint, 1.0f, 0.5f * cover.z);
  return clamp(0.5f - cover.x / edge, 0.0f, 1.0f);
}

// How much of the detail of a pattern of period `size` a footprint (m) keeps: 1 when the
// footprint is a fifth of it or less, 0 from half of it (its mean colour then).
float pattern_detail(float footprint, float size) {
  return clamp((0.5f * size - footprint) / (0.3f * size), 0.0f, 1.0f);
}

// Gradient noise in the plane, about -1 to 1, of features `scale` m apart (a layer of the key).
float land_noise(vec2 xy, float scale, uint layer) {
  return perlin_noise(vec3(xy.x / scale, xy.y / scale, 0.5f), ivec3(0), noise_key(0x4c414e44u, layer));
}

// The arable parcels' colour at a crop stage (TerrainParams::crop_stage): bare soil, green, ripe.
vec3 crop_albedo(float stage) {
  return stage < 1.0f ? mix(LAND_SOIL, LAND_CROP_GREEN, clamp(stage, 0.0f, 1.0f))
                      : mix(LAND_CROP_GREEN, LAND_CROP, clamp(stage - 1.0f, 0.0f, 1.0f));
}

// Maize and root crops at a crop stage: bare soil in winter, green from late spring to the
// autumn harvest.
vec3 row_crop_albedo(float stage) { return mix(LAND_SOIL, LAND_CROP_GREEN, clamp(stage, 0.0f, 1.0f)); }

// Open farmland's mean albedo at a crop stage: the shares of the Swiss Plateau's farmland (about
// 70 % grassland), 0.45 meadow, 0.25 pasture, 0.18 cereals and 0.12 row crops.
vec3 field_mean_albedo(float stage) {
  return 0.45f * LAND_MEADOW + 0.25f * LAND_PASTURE + 0.18f * crop_albedo(stage) + 0.12f * row_crop_albedo(stage);
}

// The fields of the Plateau: parcels of FIELD_SIZE (0.6 as wide), each meadow, pasture, cereals
// (at the season's stage) or row crops by chance, in field_mean_albedo's shares.
vec3 field_albedo(vec2 xy, float footprint, float stage) {
  vec3 crop_colour = crop_albedo(stage);
  vec3 row_crops = row_crop_albedo(stage);
  vec3 mean = field_mean_albedo(stage);
  float detail = pattern_detail(footprint, 0.6f * FIELD_SIZE);
  if (detail <= 0.0f) return mean;
  // Parcels run at 23 degrees to the grid, in rows offset by chance.
  vec2 p = vec2(0.921f * xy.x - 0.391f * xy.y, 0.391f * xy.x + 0.921f * xy.y);
  float row = floor(p.y / (0.6f * FIELD_SIZE));
  vec3 offset = hash_to_unit3(pcg3d(uvec3(uint(int(row) + 65536), 11u, 3u)));
  float column = floor(p.x / FIELD_SIZE + offset.x);
  vec3 r = hash_to_unit3(pcg3d(uvec3(uint(int(column) + 65536), uint(int(row) + 65536), 5u)));
  vec3 crop = r.x < 0.45f ? LAND_MEADOW : r.x < 0.70f ? LAND_PASTURE : r.x < 0.88f ? crop_colour : row_crops;
  return mix(mean, crop * (0.85f + 0.3f * r.y), detail);
}

// A town: blocks of BLOCK_SIZE with streets along two sides, each block tiled roofs, grey roofs
// or gardens by chance.
vec3 urban_albedo(vec2 xy, float footprint) {
  vec3 blocks = 0.45f * LAND_ROOF_TILE + 0.30f * LAND_ROOF_GREY + 0.25f * LAND_MEADOW;
  vec3 mean = 0.36f * LAND_STREET + 0.64f * blocks;
  float detail = pattern_detail(footprint, 0.2f * BLOCK_SIZE);
  if (detail <= 0.0f) return mean;
  vec2 c = xy / BLOCK_SIZE;
  vec2 cell = floor(c);
  vec2 f = c - cell;
  vec3 r = hash_to_unit3(pcg3d(uvec3(uint(int(cell.x) + 65536), uint(int(cell.y) + 65536), 9u)));
  vec3 block = r.x < 0.45f ? LAND_ROOF_TILE : r.x < 0.75f ? LAND_ROOF_GREY : LAND_MEADOW;
  vec3 here = f.x < 0.2f || f.y < 0.2f ? LAND_STREET : block * (0.85f + 0.3f * r.y);
  return mix(mean, here, detail);
}

// Forest's share of the ground: patches where the noise exceeds a threshold, which slopes and
// the montane belt (900 to 1700 m) lower (the Plateau keeps its flat land for farming; its
// forest is about a quarter of the land) and the tree line ends. The edge widens with the
// footprint, so distant forest fades to its share.
float forest_cover(vec2 xy, float altitude, float slope, float footprint) {
  float tree_line = clamp((TREE_LINE - altitude) / 200.0f, 0.0f, 1.0f);
  if (tree_line <= 0.0f) return 0.0f;
  // The finer octaves fade to their mean (0) like the patterns, and cost nothing then.
  float n = 0.55f * land_noise(xy, FOREST_SCALE, 1u);
  float fine = pattern_detail(footprint, FOREST_SCALE / 3.7f);
  if (fine > 0.0f) n += fine * 0.3f * land_noise(xy, FOREST_SCALE / 3.7f, 2u);
  float finest = pattern_detail(footprint, FOREST_SCALE / 13.1f);
  if (finest > 0.0f) n += finest * 0.15f * land_noise(xy, FOREST_SCALE / 13.1f, 3u);
  float montane = clamp((altitude - 800.0f) / 300.0f, 0.0f, 1.0f) * clamp((1900.0f - altitude) / 400.0f, 0.0f, 1.0f);
  float threshold = 0.17f - 1.5f * slope - 0.12f * montane;
  float edge = 0.02f + 0.5f * footprint / FOREST_SCALE;
  float forest = smoothstep(threshold - edge, threshold + edge, n);
  return forest * tree_line;
}

// Snow's share: above the snow line (raised and lowered by up to 150 m by the noise), on
// slopes under about 45 degrees.
float snow_cover(vec2 xy, float altitude, float slope, float snow_line) {
  // The noise moves the line by at most 150 PERLIN_BOUND m: no snow further below it.
  if (altitude <= snow_line - 150.0f * PERLIN_BOUND) return 0.0f;
  float line = snow_line + 150.0f * land_noise(xy, 2000.0f, 4u);
  return clamp((altitude - line) / 300.0f, 0.0f, 1.0f) * (1.0f - clamp((slope - 0.25f) / 0.15f, 0.0f, 1.0f));
}

// The ground's own texture: brightness varying by up to about 20 % over 60 m, 12 m and 2.5 m
// (tussocks, bushes, furrows), each octave fading like the patterns as the footprint grows.
float ground_texture(vec2 xy, float footprint) {
  float t = 0.0f;
  float coarse = pattern_detail(footprint, 60.0f);
  if (coarse <= 0.0f) return 1.0f;  // the finer octaves are gone too
  t += 0.10f * coarse * land_noise(xy, 60.0f, 5u);
  float middle = pattern_detail(footprint, 12.0f);
  if (middle > 0.0f) t += 0.07f * middle * land_noise(xy, 12.0f, 6u);
  float fine = pattern_detail(footprint, 2.5f);
  if (fine > 0.0f) t += 0.05f * fine * land_noise(xy, 2.5f, 7u);
  return 1.0f + t;
}

// The ground's Lambertian albedo and the share of it that is water at a point of the ground
// (horizontal coordinate xy, altitude above the sphere, unit normal and vertical), seen with a
// footprint (m) per pixel.
struct GroundSurface {
  vec3 albedo;  // of the land part
  float water;  // share of the footprint in a lake or river
};

GroundSurface ground_surface(vec2 xy, float altitude, vec3 normal, vec3 up, float footprint, IN(TerrainParams) t,
                             IN(LandCoverTexture) land) {
  float slope = 1.0f - dot(normal, up);  // 0 flat, 0.29 at 45 degrees
  vec3 ground =
      mix(field_albedo(xy, footprint, t.crop_stage), LAND_FOREST, forest_cover(xy, altitude, slope, footprint));
  vec3 cover = land_sample(xy, t, land);
  ground = mix(ground, urban_albedo(xy, footprint), cover.y);
  // Rock above the meadows of the Alps and on their steep slopes (below about 1000 m steep
  // slopes are wooded: the Plateau's ravines), snow above the snow line.
  float steep = clamp((slope - 0.10f) / 0.10f, 0.0f, 1.0f) * clamp((altitude - 800.0f) / 400.0f, 0.0f, 1.0f);
  float rocky = max(clamp((altitude - 2000.0f) / 500.0f, 0.0f, 1.0f), steep);
  ground = mix(ground, LAND_ROCK, rocky);
  ground = mix(ground, LAND_SNOW, snow_cover(xy, altitude, slope, t.snow_line));
  ground *= ground_texture(xy, footprint);
  GroundSurface surface;
  surface.albedo = ground;
  surface.water = t.land != 0 ? water_coverage(cover, footprint) : 0.0f;
  return surface;
}

#endif
