#pragma once
// The render qualities of `nephele render --quality` and the viewer's refinement: each a display
// error target and the view steps, light steps, frames and resolution divisor that meet it on the
// default scene at 1280 x 720 most cheaply, as `nephele report render` measures them (table and
// figures in docs/rendering.md, "Qualities"). Options and scene keys given by name override
// only their own setting (regional::apply_render_quality).
#include <string>
#include <string_view>

namespace nephele::params {

struct RenderQuality {
  std::string_view name;
  // RMS over pixels and RGB of the display values in [0, 1] against the converged reference:
  // what the setting below is chosen to stay within.
  double target_display_rms;
  int view_steps, light_steps, frames, resolution_divisor;
  std::string_view why;  // one line for help texts and sidecars
};

inline constexpr RenderQuality render_qualities[] = {
    {"draft", 0.02, 8, 2, 1, 8, "display error about 0.02: a first look at the framing and the weather"},
    {"default", 0.01, 16, 4, 1, 4, "display error about 0.01 in seconds on two CPU cores"},
    {"final", 0.003, 48, 12, 1, 1, "display error well within 0.003 at full resolution: stills"},
};

// The step parameters' numbers (params/table.hpp) are the final quality's.
static_assert(render_qualities[2].name == std::string_view("final"));

// The quality of that name; nullptr when there is none.
const RenderQuality* find_render_quality(std::string_view name);
// The quality `nephele render` and the viewer take when none is named.
const RenderQuality& default_render_quality();
// The one today's library defaults equal (regional::Scene{}): full resolution, final.
const RenderQuality& final_render_quality();
// "draft|default|final".
std::string render_quality_names();

}  // namespace nephele::params
