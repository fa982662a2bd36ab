#pragma once
// Upsampling of a render at reduced resolution (`resolution_divisor`): bilinear, and edge-aware
// with the ground distance as its guide (what render_prepared shows and the render error sweep
// compares at lower resolutions).
#include <vector>

#include <glm/vec2.hpp>

#include "core/image.hpp"

namespace nephele::render {

// The image a renderer would show at `width` x `height` from one rendered smaller: bilinear
// between pixel centres (output pixel x covers the source coordinate (x + 1/2) w / W - 1/2),
// edges clamped. Channels as in `image`.
core::ImageData upsample_bilinear(const core::ImageData& image, int width, int height);

// Edge-aware upsampling of a render at reduced resolution: joint-bilateral (Kopf et al. 2007),
// guided by where each pixel's view ray meets the ground at both sizes (`guide` at the image's
// size, `upsampled_guide` at the output's; one channel: a distance in metres, negative for the
// sky; RenderResult::ground_distance). An output pixel takes the bilinear weights of its 2 x 2
// source pixels times their likeness to it: sky with sky, ground with ground at a similar
// distance (guided_likeness). Where none of the four is alike, it takes the most alike pixel of
// the 4 x 4 about it, the nearer on ties (nearest-depth upsampling); where none of those is
// alike either, the bilinear value. So the horizon and the silhouettes of hills stay as sharp
// as the full-size guide while smooth regions are bilinear (docs/rendering.md). A NaN in
// `upsampled_guide` says that the pixel has no guide (guide_pixels left it out): bilinear.
core::ImageData upsample_guided(const core::ImageData& image, const core::ImageData& guide,
                                const core::ImageData& upsampled_guide);

// How alike two pixels' guides are, in [0, 1]: 1 for two sky pixels, 0 for sky and ground, and
// for two ground distances a and b exp(-(ln(a / b))^2 / (2 sigma^2)) with sigma = 0.3: a
// distance 35 % apart weighs 0.6, one twice as far 0.07 (a silhouette against the land behind).
double guided_likeness(float a, float b);

// The pixels of a width x height image that upsample_guided needs a guide for: those whose 2 x 2
// source pixels in `guide` (the reduced image's) are not all alike (a pair with guided_likeness
// below 1/2: the horizon, a silhouette). Elsewhere the four agree and the result is bilinear
// whatever the pixel's own guide, so its ground need not be found (render/view_depth.comp).
std::vector<glm::ivec2> guide_pixels(const core::ImageData& guide, int width, int height);

// The image bilinear at the pixel coordinate (x, y) (pixel centres at integers), clamped to
// its edge pixels: every channel into out[0 .. channels). upsample_bilinear samples with it,
// and so does the reprojection (render/reprojection.hpp).
void sample_bilinear(const core::ImageData& image, double x, double y, float* out);

}  // namespace nephele::render
