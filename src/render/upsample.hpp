#pragma once
// Bilinear upsampling of a rendered image: what `resolution_divisor` shows and what the render
// error sweep compares at lower resolutions.
#include "core/image.hpp"

namespace nephele::render {

// The image a renderer would show at `width` x `height` from one rendered smaller: bilinear
// between pixel centres (output pixel x covers the source coordinate (x + 1/2) w / W - 1/2),
// edges clamped. Channels as in `image`.
core::ImageData upsample_bilinear(const core::ImageData& image, int width, int height);

// The image bilinear at the pixel coordinate (x, y) (pixel centres at integers), clamped to
// its edge pixels: every channel into out[0 .. channels). upsample_bilinear samples with it,
// and so does the reprojection (render/reprojection.hpp).
void sample_bilinear(const core::ImageData& image, double x, double y, float* out);

}  // namespace nephele::render
