// Cloud density sampled through the warp, and its remapping to coverage.
#ifndef NEPHELE_COVER_DENSITY_GLSL
#define NEPHELE_COVER_DENSITY_GLSL
#include "prelude.glsl"
#include "worley_fbm.glsl"

// The cover's noise from its octaves' sums: `grid_sum`, octaves [0, grid_octaves) of
// inverted_worley_octaves at the warped point (the noise grid's spline, or 0 with grid_octaves 0),
// and the others evaluated at the warped point W_K(v) (renormalised: it lies on the sphere)
// shifted by `offset` (see curl_velocity_shifted); over the octaves' weights, the fBm.
float cover_density_from_grid(vec3 warped, float grid_sum, int grid_octaves, IN(FbmParams) params, vec3 offset) {
  float norm = fbm_norm(params);
  float rest = inverted_worley_octaves(normalize(warped) + offset, params, grid_octaves, params.octaves);
  return norm > 0.0f ? (grid_sum + rest) / norm : 0.0f;
}

// Inverted Worley fBm at the warped point with the noise shifted by `offset`: every octave there.
float cover_density_shifted(vec3 warped, IN(FbmParams) params, vec3 offset) {
  return cover_density_from_grid(warped, 0.0f, 0, params, offset);
}

// The same unshifted.
float cover_density(vec3 warped, IN(FbmParams) params) { return cover_density_shifted(warped, params, vec3(0.0f)); }

// The mean and the standard deviation of the cover's noise, inverted Worley fBm of the table's
// density octaves (8 of gain 0.75) on the sphere: 0.470 and 0.074 over 200000 random directions.
const float NOISE_MEAN = 0.47f;
const float NOISE_SPREAD = 0.074f;

// A blend of the two cloud layers' fields of the moving flow (--flow moving), each carried along
// the flow for its age, weighted by the younger's share w (docs/algorithm.md, "The moving flow"):
// the older fades out as the younger fades in. Linear: for fields in [0, 1] such as the weather
// systems' belts.
float layer_blend(float older, float younger, float young_share) {
  return (1.0f - young_share) * older + young_share * younger;
}

// The same for the two layers' noise, keeping its spread: independent noises blended linearly
// spread less (by sqrt((1 - w)^2 + w^2), 0.71 at w = 1/2), which the remap's softness, a density
// scale, would show as a cover greyer half way between layers than at their peaks. The blend
// about the noise's mean, divided by that factor, keeps the spread at every share.
float noise_blend(float older, float younger, float young_share) {
  float norm = sqrt((1.0f - young_share) * (1.0f - young_share) + young_share * young_share);
  return NOISE_MEAN + layer_blend(older - NOISE_MEAN, younger - NOISE_MEAN, young_share) / norm;
}

// The density shaped by the circulation and the surface: d (1 + k c) (1 + k_s b). c is the
// flow's cyclonic depth at the texel (curl_flow_shifted's w, 0 .. about 0.6) and k >= 0 the
// cyclone_cloudiness; b in [-1, 1] the land/ocean bias there (surface_bias.hpp: deserts < 0,
// stratocumulus decks > 0) and k_s in [0, 1] its weight, so both factors stay >= 0. Factors
// rather than sums keep the warped noise's structure (a sum lays smooth blobs over it) and
// thicken or thin it; the calibration then places the threshold (docs/climate.md).
float shaped_density(float density, float cyclonic, float cloudiness, float surface, float surface_weight) {
  return density * (1.0f + cloudiness * cyclonic) * (1.0f + surface_weight * surface);
}

// The cover's noise as the weather systems' edge offset in [-1, 1]: two standard deviations
// either side of its mean.
float system_edge(float noise) {
  return clamp((noise - NOISE_MEAN) / (2.0f * NOISE_SPREAD), -1.0f, 1.0f);
}

// The density with the weather systems' field w in [0, 1] (weather_systems.glsl): d (1 + 0.5 w), a
// factor, as the cyclones' and the surface's, so that the systems keep the warped noise's texture
// and frayed edges inside them and only lift it above the threshold.
float with_systems(float density, float systems) {
  return density * (1.0f + 0.5f * systems);
}

// The density with the convective cells' modulation m (weather_systems.glsl's cell_modulation,
// zero on average over a region of cells): a factor, as the systems', so that the cells keep the
// noise's texture and move cloud from the closed cells' rims into their interiors and from the
// open cells' centres onto their walls.
float with_cells(float density, float modulation) { return density * (1.0f + modulation); }

// The density between the organised trade patterns' clumps (cloud_properties.glsl's trade_moat, m
// in [0, 1]): d (1 - MOAT_CLEARING m), a factor as the cells', which keeps the noise's texture
// but leaves the moats' sea mostly clear: a density thinned by 0.12 (1.6 of the noise's spreads
// at its mean) is cloudy at a tropical band's threshold (about a quarter of a spread below the
// mean) in about a quarter of the moats' texels rather than three fifths, and the calibration
// gives the band's cloud to the clumps and to sugar.
const float MOAT_CLEARING = 0.12f;
float with_moats(float density, float moat) { return density * (1.0f - MOAT_CLEARING * clamp(moat, 0.0f, 1.0f)); }

// The share of a cloudy texel's excess of density over the threshold that its cover shows: 1 where
// a system organises the cloud, SHALLOW_CONTRAST in the trades' shallow cumulus, from their weight w
// (cloud_properties.glsl's shallow_trades_weight): 1 - w (1 - SHALLOW_CONTRAST). The density pass
// writes it beside the density, and the remap shrinks the excess by it (contrasted_cover): which
// texels are cloudy, and so every band's coverage, the shapes and the optical thickness's ranks, are
// the density's, and only the brightness of the cloud changes. 0.14: the noise's cloud a spread
// (0.074) above the threshold then gets cover 1 - (1 - 0.014) exp(-0.14 x 0.074 / 0.05) = 0.20 at
// the default softness, two spreads 0.35, as the trades' low cloud amount of 20-30 % (Brueck et al.
// 2015); the edge's step shrinks with the contrast (contrasted_cover), so that this dim cloud fades
// into the clear sea.
// Where the trades' cumulus organise into gravel, fish or flowers (weather_systems.glsl's
// trade_regimes), their cloud gathers into the patterns' clumps and the sea between them is
// clearer than under sugar's even dusting (Stevens et al. 2020 describe flowers and fish as set
// apart by clear sky): the shallow cloud there keeps MOAT_CONTRAST of sugar's contrast, so
// that a spread above the threshold it has cover 1 - 0.996 exp(-0.042 x 0.074 / 0.05) = 0.06 and
// the clumps stand out. `organised` in [0, 1]: the organised patterns' share at the texel.
// Open cells (`open_weight` in [0, 1]: the open pattern's weight where nothing deep hides it,
// weather_systems.glsl's cell_weights) dim the cloud by a factor of their own, 1 - o (1 -
// OPEN_CELL_CLOUD_CONTRAST): their walls are rings of cumulus a few km wide around clear cells
// 20-80 km across (Agee et al. 1973; Wood and Hartmann 2006, "Spatial variability of liquid water
// path in marine low cloud", J. Climate 19: cloud fraction about 0.5-0.6 in open cells against
// 0.9 in closed ones), so that a 10-20 km texel on a wall is partly clear and its cumulus
// optically medium (tau 5-15: two-stream reflectance x / (1 + x), x = 0.19 tau, 0.5-0.75 against
// 0.9 for a frontal band's tau 50). Its cover is about half the thick cloud's, not the saturated 1
// that the walls' density step gives: with 0.25 a wall's excess of 0.15 (two noise spreads) has
// cover 1 - 0.975 exp(-0.25 x 0.15 / 0.05) = 0.54, one of 0.3 has 0.78, where without it they
// have 0.96 and 1.00. Resolved or not, the open cells' cloud is that dim: the factor holds at any
// size.
const float SHALLOW_CONTRAST = 0.14f;
const float MOAT_CONTRAST = 0.3f;
const float OPEN_CELL_CLOUD_CONTRAST = 0.25f;
float cover_contrast(float shallow_weight, float organised, float open_weight) {
  float shallow = SHALLOW_CONTRAST * (1.0f - (1.0f - MOAT_CONTRAST) * clamp(organised, 0.0f, 1.0f));
  float trades = 1.0f - clamp(shallow_weight, 0.0f, 1.0f) * (1.0f - shallow);
  return trades * (1.0f - clamp(open_weight, 0.0f, 1.0f) * (1.0f - OPEN_CELL_CLOUD_CONTRAST));
}

// The cover of a cloudy texel just above the threshold: cloud boundaries are steps of optical
// thickness at a texel's scale, not ramps from nothing.
const float COVER_EDGE = 0.1f;

// The cover of a cloudy texel whose density exceeds the threshold by `excess` > 0: with softness
// s > 0, 1 - (1 - e) exp(-excess / s), e the cover just above the threshold (`edge`: COVER_EDGE,
// or less for dim cloud, contrasted_cover): cloud more than a few s above the threshold (the
// weather systems' bands) saturates towards 1 and ends in a sharp edge, cloud just above it (thin
// cirrus, the noise's fringes) stays grey. With s = 0 the linear ramp of earlier versions over
// `span`, the threshold's distance to the largest density (0 or less: no cover).
float cover_from_excess(float excess, float span, float softness, float edge) {
  if (softness > 0.0f) return 1.0f - (1.0f - edge) * exp(-excess / softness);
  return span > 0.0f ? clamp(excess / span, 0.0f, 1.0f) : 0.0f;
}

// Cover from density with the calibrated threshold: texels with density above the threshold, and
// only those, are cloudy (cover > 0; cover_from_excess).
float cover_from_density(float density, float threshold, float density_max, float softness) {
  return density > threshold ? cover_from_excess(density - threshold, density_max - threshold, softness, COVER_EDGE)
                             : 0.0f;
}

// The same with the excess shrunk by the density pass's cover contrast c (cover_contrast), and the
// edge's step e with it: 1 - (1 - c e) exp(-c x / s). A cloudy texel stays cloudy, its cover
// dimmer where the contrast is below 1, and equal to cover_from_density's to the bit where it is 1.
// The step is a thick cloud's boundary; dim cloud, the trades' shallow cumulus or the open cells'
// walls, is a texel partly under small clouds, whose cover fades into the clear sea beside it
// rather than ending in a dark rim (with e alone their clear patches showed as holes with hard,
// ragged edges in a grey field).
float contrasted_cover(float density, float threshold, float density_max, float softness, float contrast) {
  return density > threshold ? cover_from_excess(contrast * (density - threshold), density_max - threshold, softness,
                                                 COVER_EDGE * contrast)
                             : 0.0f;
}

#endif
