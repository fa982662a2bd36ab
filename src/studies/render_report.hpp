#pragma once
// The render part of `nephele report`: from the rows of the render error sweep
// (render/render_error.hpp) to render_error.csv, the work-precision diagram
// render_error_vs_runtime.svg, the printed table and the summary section, and the choice of
// settings that the summary compares with the defaults. Pure functions; no OpenGL.
#include <string>
#include <vector>

#include "params/render_quality.hpp"
#include "studies/render_error.hpp"

namespace nephele::studies {

// Compared with the default step counts (regional::Scene{}.view_steps x light_steps, one frame,
// full resolution). Errors compared are the display RMS (RenderErrorRow::display_rms).
struct RenderStepChoice {
  double factor = 1.5;
  bool has_default = false;
  RenderErrorRow default_row{};
  // The fastest row whose display RMS is at most factor x the default's (the default itself when
  // none is faster); ties go to the smaller error.
  bool has_cheapest = false;
  RenderErrorRow cheapest{};
  // The row with the least display RMS whose time is at most the default's (the default itself
  // when none is more accurate); ties go to the shorter time.
  bool has_most_accurate = false;
  RenderErrorRow most_accurate{};
};

RenderStepChoice choose_render_steps(const std::vector<RenderErrorRow>& rows, int default_view, int default_light,
                                     double factor = 1.5);

// render_error.csv: view_steps, light_steps, frames, divisor, clouds_ms, display_rms, rel_rms,
// rel_max, then the sweep's reference_view_steps, reference_light_steps, reference_frames, width
// and height repeated on every row.
std::string render_error_csv(const std::vector<RenderErrorRow>& rows, const RenderSweepOptions& options);

// The fixed-width table that `bench render` and `report` print: a header line, then one line
// per row.
std::string render_error_table_header();
std::string render_error_table_line(const RenderErrorRow& row);

// The work-precision diagram: display RMS error against clouds-pass time, log-log, one polyline
// per light-step count through the one-frame full-resolution rows, each point labelled with its
// view steps; the other variants as grey squares labelled "V x L, F frames, 1/D"; the default
// ringed. Rows with zero error (the reference's own settings) cannot be drawn on a log scale and
// are left out.
// `subtitle` (e.g. the device) is a smaller line under the title.
std::string render_error_svg(const std::vector<RenderErrorRow>& rows, const std::string& title,
                             const std::string& subtitle, int default_view, int default_light);

// The "Render: image error against run time" section of summary.md; `reference`: what the sweep
// found about its reference (the pixels left out, said when not 0; its own error estimate, said
// when measured).
std::string render_summary_markdown(const std::vector<RenderErrorRow>& rows, const RenderSweepOptions& options,
                                    const RenderStepChoice& choice, int default_view, int default_light,
                                    const ReferenceCheck& reference = {});

// The qualities (params::render_qualities), rows of RenderSweepOptions::qualities in their order:
// render_quality.csv (quality, target_display_rms, view_steps, light_steps, frames, divisor,
// display_rms, rel_rms, render_ms, clouds_ms, then the reference's steps and the frame size) and
// the "Render: qualities" section of summary.md, which says whether each meets its target.
std::string render_quality_csv(const std::vector<RenderErrorRow>& rows, const RenderSweepOptions& options);
std::string render_quality_markdown(const std::vector<RenderErrorRow>& rows, const RenderSweepOptions& options);

// "48 view x 12 light steps", with ", 4 frames" and ", 1/2 resolution" where they apply.
std::string render_variant_name(const RenderErrorRow& row);

}  // namespace nephele::studies
