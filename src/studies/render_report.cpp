#include "studies/render_report.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "studies/svg_plot.hpp"

namespace nephele::studies {
namespace {

bool is_default(const RenderErrorRow& r, int view, int light) {
  return r.view_steps == view && r.light_steps == light && r.frames == 1 && r.divisor == 1;
}

bool on_grid(const RenderErrorRow& r) { return r.frames == 1 && r.divisor == 1; }

const char* const palette[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#9467bd", "#d62728", "#8c564b", "#e377c2", "#17becf"};

}  // namespace

std::string render_variant_name(const RenderErrorRow& r) {
  std::string name = std::to_string(r.view_steps) + " view x " + std::to_string(r.light_steps) + " light steps";
  if (r.frames > 1) name += ", " + std::to_string(r.frames) + " frames";
  if (r.divisor > 1) name += ", 1/" + std::to_string(r.divisor) + " resolution";
  return name;
}

RenderStepChoice choose_render_steps(const std::vector<RenderErrorRow>& rows, int default_view, int default_light,
                                     double factor) {
  RenderStepChoice c;
  c.factor = factor;
  for (const auto& r : rows)
    if (is_default(r, default_view, default_light)) {
      c.default_row = r;
      c.has_default = true;
    }
  if (!c.has_default) return c;
  const RenderErrorRow& d = c.default_row;
  for (const auto& r : rows) {
    if (r.display_rms <= factor * d.display_rms &&
        (!c.has_cheapest || r.time_ms < c.cheapest.time_ms ||
         (r.time_ms == c.cheapest.time_ms && r.display_rms < c.cheapest.display_rms))) {
      c.cheapest = r;
      c.has_cheapest = true;
    }
    if (r.time_ms <= d.time_ms &&
        (!c.has_most_accurate || r.display_rms < c.most_accurate.display_rms ||
         (r.display_rms == c.most_accurate.display_rms && r.time_ms < c.most_accurate.time_ms))) {
      c.most_accurate = r;
      c.has_most_accurate = true;
    }
  }
  return c;
}

std::string render_error_csv(const std::vector<RenderErrorRow>& rows, const RenderSweepOptions& options) {
  std::ostringstream s;
  s << "view_steps,light_steps,frames,divisor,clouds_ms,display_rms,rel_rms,rel_max,reference_view_steps,"
       "reference_light_steps,reference_frames,width,height\n";
  char line[320];
  for (const auto& r : rows) {
    std::snprintf(line, sizeof line, "%d,%d,%d,%d,%.4f,%.6e,%.6e,%.6e,%d,%d,%d,%d,%d\n", r.view_steps, r.light_steps,
                  r.frames, r.divisor, r.time_ms, r.display_rms, r.rms_error, r.max_error, options.reference_view,
                  options.reference_light, options.reference_frames, options.width, options.height);
    s << line;
  }
  return s.str();
}

std::string render_error_table_header() {
  char line[160];
  std::snprintf(line, sizeof line, "%6s %6s %6s %4s %10s %12s %12s %12s\n", "view", "light", "frames", "res",
                "clouds_ms", "display_rms", "rel_rms", "rel_max");
  return line;
}

std::string render_error_table_line(const RenderErrorRow& r) {
  char line[160];
  const std::string resolution = "1/" + std::to_string(r.divisor);
  std::snprintf(line, sizeof line, "%6d %6d %6d %4s %10.1f %12.5f %12.5f %12.5f\n", r.view_steps, r.light_steps,
                r.frames, resolution.c_str(), r.time_ms, r.display_rms, r.rms_error, r.max_error);
  return line;
}

std::string render_error_svg(const std::vector<RenderErrorRow>& rows, const std::string& title,
                             const std::string& subtitle, int default_view, int default_light) {
  std::vector<RenderErrorRow> drawn;
  for (const auto& r : rows)
    if (r.display_rms > 0) drawn.push_back(r);
  std::vector<int> lights;
  std::vector<double> times, errors;
  for (const auto& r : drawn) {
    if (on_grid(r) && std::find(lights.begin(), lights.end(), r.light_steps) == lights.end())
      lights.push_back(r.light_steps);
    times.push_back(r.time_ms);
    errors.push_back(r.display_rms);
  }
  std::sort(lights.begin(), lights.end());

  std::ostringstream s;
  studies::begin_document(s, 600, 490, title);
  s << "<text x='300' y='38' text-anchor='middle' font-size='11'>" << studies::escape(subtitle) << "</text>\n";
  const studies::LogLogPanel panel(30, 20, times, errors);
  panel.draw_axes(s, "time of the clouds pass, all frames, wall-clock (ms)",
                  "image error, rms of display values [0, 1]");
  // One polyline per light-step count, in order of view steps; each point labelled by them.
  for (size_t li = 0; li < lights.size(); ++li) {
    std::vector<RenderErrorRow> series;
    for (const auto& r : drawn)
      if (on_grid(r) && r.light_steps == lights[li]) series.push_back(r);
    std::sort(series.begin(), series.end(), [](const auto& a, const auto& b) { return a.view_steps < b.view_steps; });
    const std::string colour = palette[li % (sizeof palette / sizeof palette[0])];
    std::vector<std::pair<double, double>> points;
    for (const auto& r : series) points.emplace_back(panel.x(r.time_ms), panel.y(r.display_rms));
    studies::polyline(s, points, colour);
    for (size_t k = 0; k < series.size(); ++k) {
      const auto [x, y] = points[k];
      studies::marker(s, 0, x, y, colour);
      s << "<text x='" << x + 6 << "' y='" << y - 6 << "' font-size='10' fill='" << colour << "'>"
        << series[k].view_steps << "</text>\n";
      if (is_default(series[k], default_view, default_light)) studies::ring(s, x, y);
    }
  }
  // The other variants (frames, resolution): grey squares with their own labels.
  for (const auto& r : drawn) {
    if (on_grid(r)) continue;
    const double x = panel.x(r.time_ms), y = panel.y(r.display_rms);
    studies::marker(s, 1, x, y, "#555555");
    std::string label = std::to_string(r.view_steps) + "x" + std::to_string(r.light_steps);
    if (r.frames > 1) label += " " + std::to_string(r.frames) + "f";
    if (r.divisor > 1) label += " 1/" + std::to_string(r.divisor);
    s << "<text x='" << x + 6 << "' y='" << y + 12 << "' font-size='10' fill='#555555'>" << studies::escape(label)
      << "</text>\n";
  }
  // Legend: colours are light-step counts; labels the view steps; the ring the default.
  double x = 100;
  for (size_t li = 0; li < lights.size(); ++li) {
    studies::legend_line(s, x, 455, palette[li % (sizeof palette / sizeof palette[0])],
                         std::to_string(lights[li]) + " light steps");
    x += 110;
  }
  s << "<text x='100' y='479'>labels: view steps; squares: V x L, frames (f), resolution; ring: the default, "
    << default_view << " x " << default_light << (drawn.size() < rows.size() ? "; zero-error rows not drawn" : "")
    << "</text>\n";
  studies::end_document(s);
  return s.str();
}

std::string render_summary_markdown(const std::vector<RenderErrorRow>& rows, const RenderSweepOptions& options,
                                    const RenderStepChoice& choice, int default_view, int default_light,
                                    const ReferenceCheck& reference) {
  std::ostringstream s;
  char line[768];
  s << "## Render: image error against run time\n\n";
  std::snprintf(
      line, sizeof line,
      "The built-in default scene (Gurten, global cover as the weather) at %d x %d pixels, rendered with each "
      "pair of view and light steps, over several frames (each with its own jitter) and at lower "
      "resolutions (upsampled bilinearly), and compared with a reference of %d view x %d light steps over "
      "%d frames. The error is the RMS over pixels and RGB of the display values in [0, 1] (exposure, "
      "filmic curve and sRGB as in the PNG); the RMS and the largest difference of the linear radiance, "
      "relative to the reference's mean, are given beside it. Times are the wall-clock time of the clouds "
      "pass, all frames together (render_error.csv, render_error_vs_runtime.svg).\n\n",
      options.width, options.height, options.reference_view, options.reference_light, options.reference_frames);
  s << line;
  if (reference.limited > 0) {
    std::snprintf(line, sizeof line,
                  "%u of the reference's %d pixels (those that needed 65535 or more shader loop iterations, "
                  "where llvmpipe stops every loop, and the rest of their 8 x 8 workgroups) are no reference: "
                  "they are left out of every error below.\n\n",
                  reference.limited, options.width * options.height);
    s << line;
  }
  if (reference.half_steps.view_steps > 0) {
    std::snprintf(line, sizeof line,
                  "The reference's own error, estimated by rendering it with half its steps (%d view x %d light): "
                  "display rms %.5f, rel rms %.5f. Errors below that are not resolved.\n\n",
                  reference.half_steps.view_steps, reference.half_steps.light_steps, reference.half_steps.display_rms,
                  reference.half_steps.rms_error);
    s << line;
  }
  s << "| view steps | light steps | frames | resolution | clouds ms | display rms | rel rms | rel max | |\n"
       "|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : rows) {
    std::snprintf(line, sizeof line, "| %d | %d | %d | 1/%d | %.1f | %.4f | %.4f | %.4f | %s |\n", r.view_steps,
                  r.light_steps, r.frames, r.divisor, r.time_ms, r.display_rms, r.rms_error, r.max_error,
                  is_default(r, default_view, default_light) ? "default" : "");
    s << line;
  }
  s << "\n";
  if (!choice.has_default) {
    s << "The defaults (" << default_view << " view x " << default_light
      << " light steps) are not in this sweep: no comparison.\n";
    return s.str();
  }
  const RenderErrorRow& d = choice.default_row;
  std::snprintf(line, sizeof line,
                "- Defaults (the final quality, `--quality final`, and the library's): %s, display rms %.4f, rel rms "
                "%.4f, clouds %.1f ms.\n",
                render_variant_name(d).c_str(), d.display_rms, d.rms_error, d.time_ms);
  s << line;
  if (choice.has_cheapest) {
    const RenderErrorRow& c = choice.cheapest;
    std::snprintf(line, sizeof line,
                  "- Cheapest within %.3gx the default's error (display rms <= %.4f): %s%s, display rms %.4f, "
                  "%.1f ms (%.2fx the default's time).\n",
                  choice.factor, choice.factor * d.display_rms, render_variant_name(c).c_str(),
                  is_default(c, default_view, default_light) ? " (the default)" : "", c.display_rms, c.time_ms,
                  d.time_ms > 0 ? c.time_ms / d.time_ms : 1.0);
    s << line;
  }
  if (choice.has_most_accurate) {
    const RenderErrorRow& a = choice.most_accurate;
    std::snprintf(line, sizeof line,
                  "- Most accurate within the default's time (<= %.1f ms): %s%s, display rms %.4f "
                  "(%.2fx the default's error), %.1f ms.\n",
                  d.time_ms, render_variant_name(a).c_str(),
                  is_default(a, default_view, default_light) ? " (the default)" : "", a.display_rms,
                  d.display_rms > 0 ? a.display_rms / d.display_rms : 1.0, a.time_ms);
    s << line;
  }
  s << "\nTimes of one sweep each; on a shared machine they vary by tens of percent, so read close calls "
       "with care.\n";
  return s.str();
}

namespace {

// The quality of row k of a qualities sweep; throws when the rows are not that sweep's.
const params::RenderQuality& quality_of_row(const std::vector<RenderErrorRow>& rows, std::size_t k) {
  constexpr std::size_t count = sizeof params::render_qualities / sizeof params::render_qualities[0];
  if (rows.size() != count) throw std::invalid_argument("render quality rows: one row per quality expected");
  return params::render_qualities[k];
}

}  // namespace

std::string render_quality_csv(const std::vector<RenderErrorRow>& rows, const RenderSweepOptions& options) {
  std::ostringstream s;
  s << "quality,target_display_rms,view_steps,light_steps,frames,divisor,display_rms,rel_rms,render_ms,clouds_ms,"
       "reference_view_steps,reference_light_steps,reference_frames,width,height\n";
  char line[400];
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const RenderErrorRow& r = rows[k];
    const params::RenderQuality& q = quality_of_row(rows, k);
    std::snprintf(line, sizeof line, "%s,%.4g,%d,%d,%d,%d,%.6e,%.6e,%.1f,%.1f,%d,%d,%d,%d,%d\n",
                  std::string(q.name).c_str(), q.target_display_rms, r.view_steps, r.light_steps, r.frames, r.divisor,
                  r.display_rms, r.rms_error, r.render_ms, r.time_ms, options.reference_view, options.reference_light,
                  options.reference_frames, options.width, options.height);
    s << line;
  }
  return s.str();
}

std::string render_quality_markdown(const std::vector<RenderErrorRow>& rows, const RenderSweepOptions& options) {
  std::ostringstream s;
  char line[768];
  s << "## Render: qualities\n\n";
  std::snprintf(line, sizeof line,
                "`nephele render --quality` (params/render_quality.hpp) on the built-in default scene at %d x %d "
                "pixels, against %d view x %d light steps over %d frame(s) at full resolution. Display rms as above; "
                "render ms: the whole render (shadow maps, clouds, the upsampling and its guide), not the process "
                "around it (render_quality.csv).\n\n",
                options.width, options.height, options.reference_view, options.reference_light,
                options.reference_frames);
  s << line;
  s << "| quality | settings | target | display rms | meets it | render ms |\n|---|---|---|---|---|---|\n";
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const RenderErrorRow& r = rows[k];
    const params::RenderQuality& q = quality_of_row(rows, k);
    std::snprintf(line, sizeof line, "| %s | %s | %.3g | %.4f | %s | %.0f |\n", std::string(q.name).c_str(),
                  render_variant_name(r).c_str(), q.target_display_rms, r.display_rms,
                  r.display_rms <= q.target_display_rms ? "yes" : "no", r.render_ms);
    s << line;
  }
  s << "\n";
  return s.str();
}

}  // namespace nephele::studies
