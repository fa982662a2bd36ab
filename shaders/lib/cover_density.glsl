// Cloud density sampled through the warp, and its remapping to coverage.
#ifndef NEPHELE_COVER_DENSITY_GLSL
#define NEPHELE_COVER_DENSITY_GLSL
#include "prelude.glsl"
#include "worley_fbm.glsl"

// Inverted Worley fBm at the warped point W_K(v) (renormalised: it lies on the sphere).
float cover_density(vec3 warped, IN(FbmParams) params) {
  return inverted_worley_fbm(normalize(warped), params).w;
}

// The same with the noise shifted by `offset` (see curl_velocity_shifted).
float cover_density_shifted(vec3 warped, IN(FbmParams) params, vec3 offset) {
  return inverted_worley_fbm(normalize(warped) + offset, params).w;
}

// The two cloud layers of the moving flow (--flow moving), each its noise carried along the flow
// for its age, weighted by the younger's share w (docs/algorithm.md, "The moving flow"): the
// older fades out as the younger fades in. A linear blend: the calibration that follows ranks the
// densities, so any normalisation by the weights would change nothing.
float layer_blend(float older, float younger, float young_share) {
  return (1.0f - young_share) * older + young_share * younger;
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

// The cover's noise as the weather systems' edge offset in [-1, 1]: the warped fBm's values
// spread about 0.55 with a standard deviation near 0.1 (8 octaves of gain 0.75).
float system_edge(float noise) {
  return clamp((noise - 0.55f) / 0.15f, -1.0f, 1.0f);
}

// The density with the weather systems' field w in [0, 1] (weather_systems.glsl): d (1 + 0.6 w), a
// factor, as the cyclones' and the surface's, so that the systems keep the warped noise's texture
// and frayed edges inside them and only lift it above the threshold.
float with_systems(float density, float systems) {
  return density * (1.0f + 0.6f * systems);
}

// The cover of a cloudy texel just above the threshold: cloud boundaries are steps of optical
// thickness at a texel's scale, not ramps from nothing.
const float COVER_EDGE = 0.1f;

// Cover from density with the calibrated threshold: texels with density above the threshold, and
// only those, are cloudy (cover > 0). With softness s > 0, 1 - (1 - e) exp(-(d - t) / s), e the
// COVER_EDGE: cloud more than a few s above the threshold (the weather systems' bands) saturates
// towards 1 and ends in a sharp edge, cloud just above it (thin cirrus, the noise's fringes)
// stays grey. With s = 0 the linear ramp from the threshold (0) to the largest density (1) of
// earlier versions.
float cover_from_density(float density, float threshold, float density_max, float softness) {
  if (softness > 0.0f)
    return density > threshold ? 1.0f - (1.0f - COVER_EDGE) * exp(-(density - threshold) / softness) : 0.0f;
  float span = density_max - threshold;
  return span > 0.0f ? clamp((density - threshold) / span, 0.0f, 1.0f) : 0.0f;
}

#endif
