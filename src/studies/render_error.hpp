#pragma once
// Image error of the ray marcher against its run time, over the numbers of view and light steps,
// the number of frames averaged and the resolution (docs/rendering.md, "Error against run time").
#include <functional>
#include <vector>

#include "core/image.hpp"
#include "regional/scene.hpp"

namespace nephele::studies {

// One way of rendering the sweep's frame: step counts, frames averaged (each with its own jitter
// of the march, render::RenderSettings::frames) and a resolution divisor: the frame is rendered at
// width/divisor x height/divisor and upsampled bilinearly (in linear radiance) to the full size.
struct RenderVariant {
  int view_steps = 0, light_steps = 0;
  int frames = 1;
  int divisor = 1;
};

struct RenderErrorRow {
  int view_steps = 0, light_steps = 0;
  int frames = 1, divisor = 1;
  double time_ms = 0;      // wall-clock time of the clouds pass, all frames together
  double display_rms = 0;  // RMS over pixels and RGB of the display values in [0, 1] (the PNG's)
  double rms_error = 0;    // RMS over pixels and RGB of the radiance, relative to the reference's mean
  double max_error = 0;    // largest absolute radiance difference, relative to the reference's mean
  // Wall-clock time of the whole render (render::render_prepared): shadow maps (unless the sweep
  // shares them), the clouds pass, the upsampling's guide and the upsampling; not the scene's
  // preparation (weather, noise).
  double render_ms = 0;
};

// What a sweep renders, its reference and its frame size: the one place that defines the sweeps
// of `nephele bench render` and `nephele report` (docs/rendering.md).
struct RenderSweepOptions {
  // Every view x light pair at one frame and full resolution, then the extra variants.
  std::vector<int> view_steps, light_steps;
  std::vector<RenderVariant> extra;
  // The reference: the most steps that stay within llvmpipe's loop limit on the default scene
  // (192 x 4 grazing x 2 sub-steps x (24 + 3) = 41472 iterations of the 65535; docs/rendering.md).
  int reference_view = 192, reference_light = 24, reference_frames = 4;
  int width = 160, height = 90;

  // The shadow maps depend on none of the variants' settings (render::shadow_map_key): made
  // once for the whole sweep, so that render_ms is the march's and the upsampling's. The
  // qualities make them in every render: their render_ms is what a user waits for.
  bool share_shadow_maps = true;
  std::vector<RenderVariant> variants() const;
  // "192 view x 24 light steps over 4 frames": the reference, as help texts and reports name it.
  std::string reference_name() const;

  // View 8, 16, 32, 48, 96 x light 2, 4, 6, 12; the defaults over 2 and 4 frames and at 1/2 and
  // 1/4 resolution; 24 x 6 over 4 frames; 8 x 2 at 1/2 and 1/4 resolution; against 192 x 24
  // steps over 4 frames, 160 x 90 pixels.
  static RenderSweepOptions full();
  // View 8, 16, 48 x light 2, 12, the defaults over 2 frames and at 1/2 resolution, against
  // 96 x 12 steps over 2 frames, 32 x 18 pixels (seconds, for CI).
  static RenderSweepOptions quick();
  // The qualities of params::render_qualities, each as a variant, against 96 x 12 steps in one
  // frame at full resolution, at 1280 x 720: the size their targets are set for, where the
  // resolution's error is the one a user sees (about 3 minutes on two CPU cores). quick: the
  // same at 64 x 36.
  static RenderSweepOptions qualities(bool quick);
};

// The errors of `image` against `reference` (both linear radiance, the same size and channels,
// RGB first), display_rms through the display encoding at `exposure` (render::tone_map); fills
// the three error fields of `row`. Pixels k = y width + x with excluded[k] are left out (an
// empty `excluded` leaves none out; all left out gives errors of 0).
void measure_render_error(const core::ImageData& image, const core::ImageData& reference, double exposure,
                          const std::vector<bool>& excluded, RenderErrorRow& row);

// What a sweep found about its own reference.
struct ReferenceCheck {
  // Pixels left out: those llvmpipe's loop limit cut short, with their workgroups.
  unsigned limited = 0;
  // The reference rendered with half its view and light steps (the same frames), against it:
  // an estimate of the reference's own error, which the rows' errors must clearly exceed to mean
  // anything. Not measured: the row's steps are 0.
  RenderErrorRow half_steps;
};

// Renders `scene` at the options' frame size with each variant (grid first, view-major) and
// compares with the reference; `progress` gets each row when it is done. The pixels of the
// reference that llvmpipe's loop limit cut short (render::RenderResult::loop_limited, with the
// rest of their 8 x 8 workgroup, which llvmpipe may have cut with them) are no reference: they
// are left out of every row's errors. `reference` (optional) gets their number and, rendered
// once more at half the reference's steps, its own error estimate. Needs a current OpenGL 4.5
// context.
std::vector<RenderErrorRow> render_error_sweep(const regional::Scene& scene, const RenderSweepOptions& options,
                                               const std::function<void(const RenderErrorRow&)>& progress = {},
                                               ReferenceCheck* reference = nullptr);

}  // namespace nephele::studies
