#pragma once
// Temporal reprojection for reduced-rate marching (docs/rendering.md, "Reprojection"): a frame
// marches one pixel of each stride x stride block (RenderSettings::march_stride, march_phase),
// and the others come from the previous frame, looked up along the same view direction (as
// Horizon Zero Dawn's clouds do with 1 of 16 pixels, Schneider 2015). The phase cycles, so
// that a camera at rest has every pixel marched after stride^2 frames.
#include <glm/glm.hpp>

#include "core/image.hpp"
#include "render/cloud_renderer.hpp"

namespace nephele::render {

// The previous frame: its linear radiance (RGBA) and its camera.
struct FrameHistory {
  core::ImageData radiance;
  Camera camera;
};

// The phase of frame `frame` of a stride x stride cycle: a fixed order that visits every pixel
// of a block once in stride^2 frames, each next one far from the last (for stride 2: (0, 0),
// (1, 1), (1, 0), (0, 1)).
glm::ivec2 march_phase(long frame, int stride);

// The unit view direction of pixel (x, y) in the camera's east-north-up frame, as the marcher's
// view_direction (perspective cameras only).
glm::dvec3 pixel_direction(const Camera& camera, double x, double y);

// Fills the pixels of `image` (RGBA, the camera's size) that the lattice (stride, phase) did not
// march: from `history` along each pixel's view direction, bilinear between its pixel centres,
// where that direction falls inside the previous frame (same size; up to half a pixel beyond its
// outer pixel centres, which are then extended); else from the nearest
// marched pixel. Directions are compared in each camera's own east-north-up frame: exact for
// turns and zooms, and for a move the frames differ by the distance over the Earth's radius
// (1e-5 rad for 50 m), while a cloud 5 km away shifts by 0.01 rad: a parallax the rest frames'
// refinement removes. Returns the number of pixels taken from the history.
long fill_unmarched(core::ImageData& image, const Camera& camera, int stride, glm::ivec2 phase,
                    const FrameHistory* history);

}  // namespace nephele::render
