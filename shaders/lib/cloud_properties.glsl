// What renderers need of the global cover's cloud besides its cover (docs/climate.md, "Optical
// thickness and cloud tops"): the optical thickness tau, log-normal over the cloudy texels by
// their rank in density, and the cloud-top height by cloud type. The remap pass writes tau from
// the rank the calibration's histograms give; the density pass the top from the weather systems;
// renderers of covers without these channels derive both from the cover (the fallbacks below).
#ifndef NEPHELE_CLOUD_PROPERTIES_GLSL
#define NEPHELE_CLOUD_PROPERTIES_GLSL
#include "prelude.glsl"

// The standard normal quantile, Phi^-1(p) for p in (0, 1), by the rational approximation of
// Abramowitz and Stegun (1964) 26.2.23 (Hastings): |error| < 4.5e-4 in z.
float normal_quantile(float p) {
  float q = p < 0.5f ? p : 1.0f - p;
  float t = sqrt(-2.0f * log(q));
  float z = t - (2.515517f + t * (0.802853f + t * 0.010328f)) / (1.0f + t * (1.432788f + t * (0.189269f + t * 0.001308f)));
  return p < 0.5f ? -z : z;
}

// The ranks are kept 1/1000 from 0 and 1: the quantile's tails (|z| <= 3.09) bound tau within
// median exp(+-3.09 spread), however few texels the histograms resolve there.
const float RANK_LIMIT = 0.001f;

// tau of a cloudy texel whose density exceeds the share `rank` in [0, 1] of its band's cloudy
// texels (0: at the threshold, 1: the densest): the log-normal's quantile, median exp(spread z).
// ISCCP's cloudy pixels are roughly log-normal in tau (Rossow and Schiffer 1999, "Advances in
// understanding clouds from ISCCP", BAMS 80). The table's median 4 and spread 1.2 are a choice
// near ISCCP's rough shares: 47 % of the cloud below tau 3.6 (ISCCP's thin classes), 46 % between
// 3.6 and 23 (medium), 7 % above 23 (thick).
float optical_thickness_from_rank(float rank, float median, float spread) {
  return median * exp(spread * normal_quantile(clamp(rank, RANK_LIMIT, 1.0f - RANK_LIMIT)));
}

// A texel's rank among its band's cloudy texels from the band's tail weights, the share of the
// band's solid angle denser than its density (tail_density) and than the threshold (tail_threshold,
// the cloudy share): 1 - tail_density / tail_threshold.
float cloudy_rank(float tail_density, float tail_threshold) {
  return tail_threshold > 0.0f ? clamp(1.0f - tail_density / tail_threshold, 0.0f, 1.0f) : 0.5f;
}

// The fallback for covers without a tau channel: the cover's value as the rank. The remap's cover,
// 1 - (1 - e) exp(-x / s) of the density's excess x, grows with the rank as tau does, so thin cloud
// (grey cover) is optically thin and saturated cloud thick, with the same median and spread.
float optical_thickness_from_cover(float cover, float median, float spread) {
  return cover > 0.0f ? optical_thickness_from_rank(cover, median, spread) : 0.0f;
}

// The weights of the cloud types at a texel, each in [0, 1] (weather_systems.glsl's fields, the
// belts' divided by their weights in the density so that a system's core is 1).
struct CloudTypes {
  float frontal;          // the cyclones' comma cloud: frontal bands and the warm-front shield
  float deep_convection;  // the ITCZ's clusters
  float cumulus;          // trade cumulus
  float cirrus;           // cirrus streaks
};

// The tropopause's height above sea level, km: about 16-17 km in the tropics and 8-9 km at the
// poles (Hoinka 1998, "Statistics of the global tropopause pressure", Mon. Wea. Rev. 126), as
// 9 + 7 cos^2(latitude).
float tropopause_km(float latitude) {
  float c = cos(latitude);
  return 9.0f + 7.0f * c * c;
}

// Cloud-top heights above sea level (km) by type, after ISCCP's classes (low tops below 680 hPa,
// about 3.2 km; middle 680-440 hPa, to 6.5 km; high above) and the types' typical tops:
const float TOP_STRATOCUMULUS_KM = 1.5f;  // subtropical decks under the trade inversion, 1-2 km (Wood 2012)
const float TOP_CUMULUS_KM = 2.0f;        // trade cumulus, 1.5-2.5 km (Nuijens et al. 2014)
const float TOP_LAYER_KM = 3.0f;          // the noise's unorganised cloud: low and middle layers
const float TOP_FRONTAL_KM = 8.0f;        // nimbostratus under the cirrostratus of the comma head, 6-9 km
const float CIRRUS_BELOW_TROPOPAUSE_KM = 2.0f;  // cirrus 9-12 km at mid-latitudes, 14 in the tropics
const float ANVIL_BELOW_TROPOPAUSE_KM = 1.0f;   // deep convection reaches the tropopause

// The cloud-top height (km above sea level) at a texel of geocentric `latitude` (radians) from
// its types' weights, the flow's cyclonic depth (0 .. about 0.6: lifted layers in cyclones) and
// the stratocumulus decks' surface bias b in [-1, 1] (> 0 off the west coasts; 0 without
// --surface). The unorganised cloud's top, 3 km, is held at the trade inversion's 2 km between
// about 8 and 35 degrees (the subtropics' subsiding air caps the cloud: Stevens 2005), sinks
// towards the decks' 1.5 km with b and rises up to 3 km more with the cyclonic depth; each system
// then replaces it by its weight, the higher types last, so that a system's top shows where it
// lies over lower cloud.
float cloud_top_km(IN(CloudTypes) types, float latitude, float cyclonic, float surface_bias) {
  float tropopause = tropopause_km(latitude);
  float a = abs(latitude);
  float inversion = smoothstep(0.1f, 0.18f, a) * (1.0f - smoothstep(0.55f, 0.65f, a));
  float layer = mix(TOP_LAYER_KM, TOP_CUMULUS_KM, inversion);
  float top = mix(layer, TOP_STRATOCUMULUS_KM, clamp(surface_bias, 0.0f, 1.0f)) +
              3.0f * clamp(cyclonic / 0.6f, 0.0f, 1.0f);
  top = mix(top, TOP_CUMULUS_KM, clamp(types.cumulus, 0.0f, 1.0f));
  top = mix(top, TOP_FRONTAL_KM, clamp(types.frontal, 0.0f, 1.0f));
  top = mix(top, tropopause - CIRRUS_BELOW_TROPOPAUSE_KM, clamp(types.cirrus, 0.0f, 1.0f));
  return mix(top, tropopause - ANVIL_BELOW_TROPOPAUSE_KM, clamp(types.deep_convection, 0.0f, 1.0f));
}

// The geometric thickness (km) of a cloud with its top at top_km and optical thickness tau: from a
// third of the depth above 0.5 km (the lowest cloud bases) for thin cloud to all of it for
// thick (tau 60 and more), since a cloud's optical thickness grows with its depth (as H^(5/3) for
// an adiabatic cloud: Brenguier et al. 2000): stratocumulus 300 m, trade cumulus 450 m, the comma
// clouds' shield about 3 km, cumulonimbus from 0.5 km to their anvils; at least 300 m, and at
// most down to 200 m below the top.
float cloud_thickness_km(float top_km, float tau) {
  float depth = (top_km - 0.5f) * (0.3f + 0.7f * smoothstep(3.6f, 60.0f, tau));
  return clamp(depth, 0.3f, max(top_km - 0.2f, 0.3f));
}

// The optical depth of a uniform slab with the mean transmittance of a texel whose share `cover`
// holds cloud of optical thickness tau: -ln(1 - c (1 - exp(-tau))), at most tau (where c = 1 and
// exp(-tau) underflows, tau itself).
float covered_optical_depth(float cover, float tau) {
  float c = clamp(cover, 0.0f, 1.0f);
  float transmitted = (1.0f - c) + c * exp(-tau);
  return transmitted > 0.0f ? min(-log(transmitted), tau) : tau;
}

// The fallback for covers without a cloud-top channel: the unorganised cloud's top, raised
// towards the frontal top where the cover saturates (thick cloud is mostly the systems').
float cloud_top_from_cover(float cover, float latitude) {
  CloudTypes types;
  types.frontal = clamp((cover - 0.8f) / 0.2f, 0.0f, 1.0f);
  types.deep_convection = 0.0f;
  types.cumulus = 0.0f;
  types.cirrus = 0.0f;
  return cover > 0.0f ? cloud_top_km(types, latitude, 0.0f, 0.0f) : 0.0f;
}

#endif
