// What renderers need of the global cover's cloud besides its cover (docs/climate.md, "Optical
// thickness and cloud tops"): the optical thickness tau, log-normal over the cloudy texels by
// their rank in density, and the cloud-top height by cloud type. The remap pass writes tau from
// the rank the calibration's histograms give; the density pass the top from the weather systems;
// renderers of covers without these channels derive both from the cover (the fallbacks below).
#ifndef NEPHELE_CLOUD_PROPERTIES_GLSL
#define NEPHELE_CLOUD_PROPERTIES_GLSL
#include "prelude.glsl"
#include "perlin.glsl"
#include "slab_scattering.glsl"

// The standard normal quantile, Phi^-1(p) for p in (0, 1), by the rational approximation of
// Abramowitz and Stegun (1964) 26.2.23 (Hastings): |error| < 4.5e-4 in z.
float normal_quantile(float p) {
  float q = p < 0.5f ? p : 1.0f - p;
  float t = sqrt(-2.0f * log(q));
  float z = t - (2.515517f + t * (0.802853f + t * 0.010328f)) / (1.0f + t * (1.432788f + t * (0.189269f + t * 0.001308f)));
  return p < 0.5f ? -z : z;
}

// The standard normal CDF, Phi(z) = (1 + erf(z / sqrt 2)) / 2, with erf from Abramowitz and
// Stegun 7.1.26 (|error| <= 1.5e-7; GLSL has no erf).
float normal_cdf(float z) {
  float x = abs(z) * 0.70710678f;
  float t = 1.0f / (1.0f + 0.3275911f * x);
  float poly = t * (0.254829592f + t * (-0.284496736f + t * (1.421413741f + t * (-1.453152027f + t * 1.061405429f))));
  float erf_x = 1.0f - poly * exp(-x * x);
  return z >= 0.0f ? 0.5f + 0.5f * erf_x : 0.5f - 0.5f * erf_x;
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
  float cirrus;           // cirrus streaks and the anvils
  float anvil;            // the anvils of the ITCZ's systems and towers (part of cirrus)
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
const float TOP_BOUNDARY_LAYER_KM = 2.0f;  // the noise's unorganised cloud where the air does not rise:
                                          // the marine boundary layer's cloud, 1-2.5 km (Wood 2012)
const float TOP_FRONTAL_KM = 8.0f;        // nimbostratus under the cirrostratus of the comma head, 6-9 km
const float CIRRUS_BELOW_TROPOPAUSE_KM = 2.0f;  // cirrus 9-12 km at mid-latitudes, 14 in the tropics
const float ANVIL_BELOW_TROPOPAUSE_KM = 1.0f;   // deep convection reaches the tropopause

// The cyclonic depths between which the cyclones' ascent deepens the boundary-layer cloud to the
// cirrus level, by a smoothstep: weak ascent stays under the boundary layer's inversion, strong
// ascent fills the troposphere, so that tops are mostly low or high with fewer in between, as in
// the storm tracks. Chosen so that the default covers' height classes come near ISCCP's shares
// (docs/climate.md, "Optical thickness and cloud tops").
const float ASCENT_ONSET = 0.05f;
const float ASCENT_FULL = 0.45f;

// The cloud-top height (km above sea level) at a texel of geocentric `latitude` (radians) from
// its types' weights, the flow's cyclonic depth (0 .. about 0.6: the ascent of the cyclones) and
// the stratocumulus decks' organisation in [0, 1] (weather_systems.glsl's deck_organisation: off the west
// coasts with --surface, in patches of the decks' belt without). The unorganised cloud is
// boundary-layer cloud (2 km) where the air does not rise, sinking towards the decks' 1.5 km with
// their organisation; the cyclones' ascent deepens it with their cyclonic depth up to the cirrus
// level under the tropopause (ASCENT_ONSET to ASCENT_FULL), as the cloud of a storm's ascent
// fills the troposphere: altostratus and nimbostratus in between (ISCCP's middle class),
// cirrostratus tops in the deepest. Each system then replaces it by its weight, the higher types last, so
// that a system's top shows where it lies over lower cloud.
float cloud_top_km(IN(CloudTypes) types, float latitude, float cyclonic, float deck) {
  float tropopause = tropopause_km(latitude);
  float cirrus = tropopause - CIRRUS_BELOW_TROPOPAUSE_KM;
  float top = mix(TOP_BOUNDARY_LAYER_KM, TOP_STRATOCUMULUS_KM, clamp(deck, 0.0f, 1.0f));
  top = mix(top, cirrus, smoothstep(ASCENT_ONSET, ASCENT_FULL, cyclonic));
  top = mix(top, TOP_CUMULUS_KM, clamp(types.cumulus, 0.0f, 1.0f));
  top = mix(top, TOP_FRONTAL_KM, clamp(types.frontal, 0.0f, 1.0f));
  top = mix(top, cirrus, clamp(types.cirrus, 0.0f, 1.0f));
  return mix(top, tropopause - ANVIL_BELOW_TROPOPAUSE_KM, clamp(types.deep_convection, 0.0f, 1.0f));
}

// The anvils' share of organisation: they are a sheet of cirrus spread from the cores (Houze 2004),
// neither broken cumulus nor thick cloud. Optically thin (tau of a few), they reflect less than
// half of what thick cloud does (two-stream R = x / (1 + x), x = 3/4 (1 - g) tau with g = 0.75:
// 0.36 at tau 3 against 0.88 at tau 40). A quarter of the systems' organisation gives them the
// cover contrast 1 - 0.75 (1 - SHALLOW_CONTRAST) = 0.355 (cover_density.glsl): the noise's cloud a
// spread (0.074) above the threshold gets cover 1 - 0.965 exp(-0.355 x 0.074 / 0.05) = 0.43 at the
// default softness, two spreads 0.66, against 0.20 and 0.35 in the shallow cumulus around them.
const float ANVIL_ORGANISED = 0.25f;

// The organisation of the trades' cumulus clumps from their type weight c (weather_systems.glsl's
// trade_cumulus: at a clump's core the pattern's strength, gravel 0.45, fish 0.8, flowers 1): c^2,
// so that gravel's broken cumulus stay near sugar's dimness (organisation 0.2: cover contrast
// 1 - 0.8 (1 - SHALLOW_CONTRAST) = 0.31) and the fish's and flowers' stratiform sheets are
// bright (0.64 and 1: contrast 0.69 and 1), as the patterns' reflectances rise from sugar and
// gravel to fish and flowers (Bony et al. 2020).
float cumulus_organisation(float cumulus) {
  float c = clamp(cumulus, 0.0f, 1.0f);
  return c * c;
}

// How far a texel's cloud is organised by a weather system, in [0, 1]: the largest of the comma
// clouds' and the ITCZ's clusters' weights, a deck's organisation, the anvils' share (ANVIL_ORGANISED
// of their weight) and the trades' cumulus clumps' (cumulus_organisation). Not among them: the
// cirrus streaks, thin cloud; and the flow's cyclonic depth, whose vortices in the tropics are no
// weather system (the tropics' deep convection is the ITCZ's clusters): cloud its ascent lifts
// there is thin cirrus.
float organised_cloud(IN(CloudTypes) types, float deck) {
  float organised = max(max(types.frontal, types.deep_convection), max(deck, ANVIL_ORGANISED * types.anvil));
  return clamp(max(organised, cumulus_organisation(types.cumulus)), 0.0f, 1.0f);
}

// The trades' belt: the tropics to the subtropical highs' poleward edge, full to 26 degrees and
// gone from 33 (the trade cumulus fields' poleward edge, weather_systems.glsl), where the air
// sinks or rises only in the systems (the Hadley circulation's trade-wind branch; Riehl 1954).
float trades_belt(float latitude) { return 1.0f - smoothstep(0.45f, 0.58f, abs(latitude)); }

// The weight of the trades' shallow cumulus regime at a texel, in [0, 1]: in the trades' belt,
// where no system organises the cloud, times the regime's strength (--shallow-trades). There the
// cloud of a 10-100 km texel is a field of small cumulus over much clear sea, which covers a
// fifth to a third of it (Nuijens et al. 2014; "sugar" and "gravel" of Stevens et al. 2020), not
// a bright sheet (cover_density.glsl's cover_contrast).
float shallow_trades_weight(IN(CloudTypes) types, float latitude, float deck, float strength) {
  return clamp(strength, 0.0f, 1.0f) * trades_belt(latitude) * (1.0f - organised_cloud(types, deck));
}

// The moat of the organised trade patterns at a texel, in [0, 1]: the shallow cumulus regime's
// weight `shallow` (shallow_trades_weight) where the patterns organise the cumulus (`organised`,
// weather_systems.glsl's organised_trades) away from their clumps (the cumulus type's weight
// under 0.15, a sixth of the clumps' strength at the most: their fringes), where the sea between
// the flowers, fish and gravel is clearer than under sugar (Stevens et al. 2020).
float trade_moat(float shallow, float organised, float cumulus) {
  return clamp(shallow, 0.0f, 1.0f) * clamp(organised, 0.0f, 1.0f) * (1.0f - smoothstep(0.0f, 0.15f, cumulus));
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
  types.anvil = 0.0f;
  return cover > 0.0f ? cloud_top_km(types, latitude, 0.0f, 0.0f) : 0.0f;
}

// Below a cover texel: the cover says what share of a texel is cloudy, not where. A renderer that
// draws the texel's share as a uniform haze shows the texel grid and soft edges; real cloud
// fields are cloudy or clear down to tens of metres with edges whose perimeter dimension is
// about 4/3 (Lovejoy 1982, "Area-perimeter relation for rain and cloud areas", Science 216).
// subtexel_cloud draws that: a fractional Brownian field n on the sphere, octaves of gradient
// noise from one cover texel's wavelength down, amplitude 2^-H per halving with Hurst exponent H = 2/3, since
// the level sets of such a field have dimension 2 - H = 4/3 (Mandelbrot, "The Fractal Geometry of
// Nature", 1982, ch. 28); a point is cloudy where n lies below its quantile at the cover,
// n < sigma Phi^-1(c), so that the share c of every texel stays cloudy in expectation.
// Band-limited: an octave fades out as the sample's footprint grows from a quarter to half its
// wavelength, and the unresolved octaves (the faded ones and the infinite tail beyond the last
// one drawn) are taken by their distribution: the cloudy share of the footprint is
// Phi((sigma Phi^-1(c) - n_resolved) / sigma_unresolved). So it is the cover's own value, exactly,
// wherever a sample spans half a texel or more (nothing drawn), a sharp fractal edge close up,
// and continuous in between: nothing switches with distance.
const float SUBTEXEL_GAIN = 0.62996052f;  // 2^-(2/3)
// One texel: the cover's own structure above it stays as filtered (two texels broke the systems'
// interiors, cover 0.5-0.9, into clouds of two texels everywhere; half a texel left the edges
// blurred between half a texel and one and a half).
const float SUBTEXEL_FIRST_WAVELENGTH = 1.0f;  // texels
const int SUBTEXEL_OCTAVES = 12;               // to 1/2048 texel: 38 m under 78 km texels
// The tops' relief takes the field's octaves of wavelengths up to this, with amplitudes
// (wavelength / it)^(2/3): in metres, whatever the cover's texels (the cover's own top channel
// holds the larger scales); convective cells and the tops' undulations are below some 10 km.
const float SUBTEXEL_RELIEF_WAVELENGTH = 8000.0f;

// |relief| stays below this: its octaves' weights sum to at most 1 / (1 - 2^-2/3) = 2.70, each
// octave's |n| to PERLIN_BOUND, over sigma = PERLIN_OCTAVE_SIGMA (1 - 2^-4/3)^-1/2 = 0.348: 8.05.
const float SUBTEXEL_RELIEF_BOUND = 8.1f;

struct SubtexelCloud {
  float cover;   // the cloudy share of the sample's footprint
  float field;   // the resolved field in units of the whole field's deviation (mean 0, deviation <= 1)
  float relief;  // the resolved octaves below SUBTEXEL_RELIEF_WAVELENGTH, in units of their whole
                 // series' deviation, negated: > 0 in the cores of the clouds they draw
  float undulation;  // the same resolved octaves as `relief`, standardised by the deviation of all of
                     // them (mean 0, deviation <= 1): subtexel_optical_thickness's
  float undulation_share;  // the share of those octaves' variance that `undulation` holds
};

// At the point p on the planet (m, from its centre; points on one radius get the same value), for
// a cover c, cover texels `texel` m wide and a sample `footprint` m wide.
SubtexelCloud subtexel_cloud(vec3 p, float cover, float texel, float footprint) {
  SubtexelCloud result;
  result.cover = cover;
  result.relief = 0.0f;
  result.field = 0.0f;
  result.undulation = 0.0f;
  result.undulation_share = 0.0f;
  float wavelength = SUBTEXEL_FIRST_WAVELENGTH * texel;
  float amplitude = 1.0f;
  float resolved = 0.0f, unresolved = 0.0f, relief = 0.0f, relief_drawn = 0.0f;
  int drawn = 0;
  for (int k = 0; k < SUBTEXEL_OCTAVES; ++k) {
    float kept = 1.0f - smoothstep(0.25f * wavelength, 0.5f * wavelength, footprint);
    if (kept <= 0.0f) break;  // the finer octaves fade out earlier still
    drawn = k + 1;
    float octave = kept * perlin_noise(p / wavelength, ivec3(0), uvec3(uint(k), 0x6d3bu, 0x2c1bu));
    resolved += amplitude * octave;
    if (wavelength <= SUBTEXEL_RELIEF_WAVELENGTH) {
      float w = pow(wavelength / SUBTEXEL_RELIEF_WAVELENGTH, 0.6666667f);
      relief += w * octave;
      relief_drawn += w * w * kept * kept;
    }
    unresolved += amplitude * amplitude * (1.0f - kept * kept);
    amplitude *= SUBTEXEL_GAIN;
    wavelength *= 0.5f;
  }
  if (drawn == 0) return result;
  // The squared weights of all the relief's octaves, drawn or not: the weights fall by g from the
  // first octave of SUBTEXEL_RELIEF_WAVELENGTH and less, a geometric series of ratio g^2.
  float first_wavelength = SUBTEXEL_FIRST_WAVELENGTH * texel;
  float first = max(ceil(log2(first_wavelength / SUBTEXEL_RELIEF_WAVELENGTH)), 0.0f);
  float relief_octaves = float(SUBTEXEL_OCTAVES) - first;
  float g2 = SUBTEXEL_GAIN * SUBTEXEL_GAIN;
  float relief_weights =
      relief_octaves > 0.0f
          ? pow(first_wavelength * exp2(-first) / SUBTEXEL_RELIEF_WAVELENGTH, 1.3333333f) * (1.0f - pow(g2, relief_octaves)) /
                (1.0f - g2)
          : 0.0f;
  // Octaves from k on: sum of a_k^2 = a_k^2 / (1 - g^2); the whole field's variance is 1 / (1 - g^2).
  float tail = 1.0f / (1.0f - SUBTEXEL_GAIN * SUBTEXEL_GAIN);
  unresolved += amplitude * amplitude * tail;
  float sigma = PERLIN_OCTAVE_SIGMA * sqrt(tail);
  result.relief = -relief / sigma;
  result.field = resolved / sigma;
  if (relief_weights > 0.0f) {
    result.undulation = -relief / (PERLIN_OCTAVE_SIGMA * sqrt(relief_weights));
    result.undulation_share = relief_drawn / relief_weights;
  }
  if (cover > 0.0f && cover < 1.0f)
    result.cover = normal_cdf((normal_quantile(cover) * sigma - resolved) / (PERLIN_OCTAVE_SIGMA * sqrt(unresolved)));
  return result;
}

// How much of the sub-texel cloud's carving a texel's cloud takes, in [0, 1], by its ISCCP class
// (Rossow and Schiffer 1999): subtexel_cloud breaks a texel's cloud into clouds and clear sky, as
// the boundary layer's cumulus and stratocumulus, the middle cloud and the cores and anvils of deep
// convection are broken and edged below a texel. High cloud thinner than deep convection, ISCCP's
// cirrus and cirrostratus (tops above 440 hPa, about 6.5 km in the standard atmosphere; tau below
// 23), is not: it is a veil that the wind aloft spreads over hundreds of km, through which the
// ground shows where it is thin, and its cover is the veil's opacity, drawn as it is. Carved, the
// satellite's thin cirrus over land showed as fields of bright popcorn of half a texel (issue 31).
// Blended over a km of top and over tau 16-32 (23 within 40 %), so that nothing switches.
const float VEIL_TOP_START_KM = 6.0f;
const float VEIL_TOP_FULL_KM = 7.0f;
const float VEIL_TAU_FULL = 16.0f;
const float VEIL_TAU_END = 32.0f;
float subtexel_carving(float top_km, float tau) {
  float veil = smoothstep(VEIL_TOP_START_KM, VEIL_TOP_FULL_KM, top_km) * (1.0f - smoothstep(VEIL_TAU_FULL, VEIL_TAU_END, tau));
  return 1.0f - veil;
}

// The optical thickness of the sub-texel cloud at a sample. The cover gives a texel's cloud one
// tau, but real cloud is far from uniform inside: its optical thickness varies about log-normally,
// with a deviation of ln tau that makes the plane-parallel albedo bias (Cahalan et al. 1994, "The
// albedo of fractal stratocumulus clouds", J. Atmos. Sci. 51: the reduction factor chi =
// exp(mean ln tau) / mean tau about 0.7 for marine stratocumulus, a deviation of sqrt(-2 ln chi) =
// 0.84), and seen from orbit only 1.4 % of 8.8 km cloudy regions are uniform within 5 % in
// reflectivity (Genkova and Davies 2003, "Spatial heterogeneity of reflected radiance from globally
// distributed clouds", GRL 30). Here ln tau varies with the tops' relief, the field's octaves of
// 8 km and less standardised (`undulation` u): the domes are thicker, the hollows between them
// thinner, at the scales of cells and tops. Those octaves decide less of where a texel's cloud
// ends than the larger ones (the undulation's correlation with the field is g^k0 for relief
// octaves from the k0-th: 0.40 under 20 km texels, 0.16 under 78 km), so the edges are only a
// little thinner than the cores.
// The texel's tau is the tau of a uniform cloud that reflects as much as its varied cloud, which
// is what a retrieval such as ISCCP's gives for a pixel; so whether a view resolves the variation
// or not, the cloud reflects the same on average. With the two-stream reflectance R = x / (1 + x),
// x = 3/4 (1 - g) tau, as a function f of ln tau, f'' / f' = (1 - x) / (1 + x) = 2 T - 1 with T
// the slab's diffuse transmittance; ln tau + spread u - c keeps E[f] to second order in the
// resolved variance v spread^2 when c = (2 T - 1) v spread^2 / 2: the arithmetic mean for thin
// cloud (R linear in tau), the geometric mean (Cahalan et al.'s effective thickness) at x = 1,
// and a little thicker for thick cloud, whose reflectance saturates.
// The spread fades in with the texel's tau, smoothstep(1, 3.6, tau): thin cloud (ISCCP's class below
// 3.6), through which the ground shows, stays uniform, so that it hides as much of the ground as
// the ground renderer's layers, which have no such variation (a varied thin slab transmits more on
// average: docs/orbit_view.md, "The sub-texel cloud"); the stratocumulus and thicker cloud of
// Cahalan et al.'s bias take all of it.
float subtexel_optical_thickness(float tau, IN(SubtexelCloud) detail, float spread) {
  spread *= smoothstep(1.0f, 3.6f, tau);
  float variance = spread * spread * detail.undulation_share;
  float correction = (2.0f * slab_diffuse_transmittance(tau) - 1.0f) * 0.5f * variance;
  return tau * exp(spread * detail.undulation - correction);
}

#endif
