#pragma once
// The refinement scheduler of nephele view: a change of the view renders at once at a quarter of
// the window's size in each direction (the preview), then at half size, then at full size in
// eight bands of rows, one render per frame, so that input is answered between renders and no
// frame costs a whole full-size render. While the camera alone moves, the preview marches one
// pixel of each preview_march_stride^2 block and reprojects the rest from the last preview
// (docs/viewer.md, "Reprojection").
#include <cstddef>
#include <string>
#include <vector>

#include "apps/viewer/view_source.hpp"
#include "apps/viewer/view_state.hpp"
#include "core/image.hpp"
#include "render/reprojection.hpp"

namespace nephele::viewer {

// One step of the refinement: the image at 1/divisor of the window's size each way, or band
// `band` of `bands` (of equal rows, the last one shorter) of it.
struct RefinementLevel {
  int divisor;
  int band, bands;
};
// The steps, coarse to fine: 1/4, 1/2, then the full size in eight bands.
const std::vector<RefinementLevel>& refinement_levels();

class Refinement {
 public:
  // True when `key` (everything a render reads) or the framebuffer's size is not the one being
  // refined: then restart.
  bool stale(const std::string& key, int width, int height) const {
    return key != shown_key_ || width != target_width_ || height != target_height_;
  }
  // Starts again from the preview. `scene_key` (all of the key but the camera) unchanged, at the
  // same size, means that the camera alone moved (asked only on a restart: the viewer builds
  // the keys each frame).
  void restart(const std::string& key, const std::string& scene_key, int width, int height);
  // Renders the level that is due, if any, with `source`; true when it did (shown() changed).
  bool step(ViewSource& source, const ViewState& state);
  // True when the full size of `key` has been rendered.
  bool done(const std::string& key) const { return next_level_ >= refinement_levels().size() && key == shown_key_; }
  // The level rendered next (refinement_levels().size() when done).
  std::size_t next_level() const { return next_level_; }
  // The last render (a band's rows only, for a band): its radiance, passes and times.
  const render::RenderResult& last_render() const { return last_render_; }
  // The linear radiance to show: the last whole render, or the full-size image its bands have
  // filled so far (the rows not yet marched from the half-size render, nearest pixel).
  const core::ImageData& shown() const { return shown_; }
  long renders() const { return renders_; }

 private:
  std::string shown_key_;        // the key of the state being refined
  std::string shown_scene_key_;  // its scene_key
  bool camera_moving_ = false;
  long moving_frames_ = 0;
  render::FrameHistory preview_history_;      // the last preview and its camera
  std::size_t next_level_ = 0;                // refinement level rendered next
  int target_width_ = 0, target_height_ = 0;  // framebuffer size being refined
  render::RenderResult last_render_;
  core::ImageData shown_;
  long renders_ = 0;
};

}  // namespace nephele::viewer
