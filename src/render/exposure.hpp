#pragma once
// A camera's metering for the orbit view: the exposure that puts the frame's highlights at the
// filmic curve's shoulder (render::tone_map), as a photographer of the Earth from orbit exposes
// for the clouds so that they keep their texture instead of clipping to white.
#include "core/image.hpp"

namespace nephele::render {

// The share of the lit pixels (luminance above kLitLuminance) that lies below the metered
// highlight, and where the highlight goes: tone_map's x = 1 (display 0.80 linear, 0.91 in sRGB),
// below the curve's white.
inline constexpr double kHighlightPercentile = 0.99;
inline constexpr double kHighlightKey = 1.0;
// Black space and the unlit night side (W m^-2 sr^-1 nm^-1): not metered.
inline constexpr double kLitLuminance = 1e-4;

// kHighlightKey over the kHighlightPercentile-th luminance (Rec. 709 weights of R, G, B) of the
// lit pixels, at most kHighlightKey over `sunlit_white` (the luminance of a white surface under
// the frame's highest sun, render::sunlit_white_luminance; 0: no such bound), so that a frame
// of thin cloud and land is exposed as a camera set for sunlit cloud would show it, not
// brightened until its dim highlights reach the shoulder; clamped to [fallback / 4,
// fallback * 4] so that a frame of night or of a few clouds is not pushed far from the usual;
// `fallback` when no pixel is lit.
double highlight_exposure(const core::ImageData& radiance, double fallback, double sunlit_white = 0.0);

}  // namespace nephele::render
