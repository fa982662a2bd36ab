#include "studies/noise_grid_precision.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/time.hpp"
#include "cover/global_cover.hpp"
#include "studies/svg_plot.hpp"

namespace nephele::studies {
namespace {

using Kind = NoiseGridRow::Kind;

struct Frame {
  std::vector<float> density, cover;
  double time_ms = 0;
};

cover::CoverParameters frame_parameters(const NoiseGridOptions& o, Kind kind, float nodes) {
  cover::CoverParameters p = o.base;
  p.flow = cover::Flow::moving;
  p.size = o.size;
  p.warp_grid = kind == Kind::every_texel ? 0 : o.warp_grid;
  p.noise_grid_nodes = nodes;
  if (kind == Kind::later) p.time = core::format_utc_minutes(core::parse_utc_time(p.time) + 600.0);
  return p;
}

// One frame, `runs` times: the median time of the warp and density passes, the fields of the first
// run (which are every run's).
Frame run_frame(const cover::CoverParameters& p, int runs) {
  Frame frame;
  std::vector<double> times;
  for (int k = 0; k < std::max(1, runs); ++k) {
    cover::GlobalCover cover(p);
    cover.run();
    double ms = 0;
    for (const cover::PassTiming& t : cover.timings())
      if (t.pass == "warp" || t.pass == "density") ms += t.milliseconds;
    times.push_back(ms);
    if (k == 0) {
      frame.density = cover.density_field().read();
      frame.cover = cover.cover_field().read();
    }
  }
  std::sort(times.begin(), times.end());
  frame.time_ms = times[times.size() / 2];
  return frame;
}

NoiseGridRow compare(const cover::CoverParameters& p, Kind kind, const Frame& frame, const Frame& reference) {
  NoiseGridRow row;
  row.kind = kind;
  row.nodes = p.noise_grid_nodes;
  row.octaves = cover::noise_grid_octaves(p);
  row.time_ms = frame.time_ms;
  const std::size_t n = reference.density.size();
  double density_sum = 0, cover_sum = 0, mean = 0, square = 0;
  std::size_t flipped = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double d = double(frame.density[k]) - reference.density[k];
    const double c = double(frame.cover[k]) - reference.cover[k];
    density_sum += d * d;
    cover_sum += c * c;
    row.density_max = std::max(row.density_max, std::abs(d));
    if ((frame.cover[k] > 0.0f) != (reference.cover[k] > 0.0f)) ++flipped;
    mean += reference.density[k];
    square += double(reference.density[k]) * reference.density[k];
  }
  row.density_rms = std::sqrt(density_sum / double(n));
  row.cover_rms = std::sqrt(cover_sum / double(n));
  row.flipped = double(flipped) / double(n);
  mean /= double(n);
  row.reference_spread = std::sqrt(std::max(0.0, square / double(n) - mean * mean));
  return row;
}

}  // namespace

NoiseGridOptions NoiseGridOptions::full(const cover::CoverParameters& base) {
  return {base, 1024, 512, {32, 16, 8, 4, 2, 1}, 1};
}

NoiseGridOptions NoiseGridOptions::quick(const cover::CoverParameters& base) { return {base, 64, 32, {4, 2, 1}, 1}; }

const char* noise_grid_kind_name(Kind kind) {
  switch (kind) {
    case Kind::reference: return "every octave at every texel";
    case Kind::noise_grid: return "noise grid";
    case Kind::every_texel: return "trajectories from every texel";
    case Kind::later: return "ten minutes later";
  }
  return "";
}

std::vector<NoiseGridRow> noise_grid_sweep(const NoiseGridOptions& o,
                                           const std::function<void(const NoiseGridRow&)>& on_row) {
  // The reference first, once more than the others: the process's first frame compiles the shaders.
  const cover::CoverParameters at_reference = frame_parameters(o, Kind::reference, 0.0f);
  const Frame reference = run_frame(at_reference, o.repeat + 1);
  std::vector<NoiseGridRow> rows{compare(at_reference, Kind::reference, reference, reference)};
  if (on_row) on_row(rows.back());
  for (Kind kind : {Kind::every_texel, Kind::later}) {
    const cover::CoverParameters p = frame_parameters(o, kind, 0.0f);
    rows.push_back(compare(p, kind, run_frame(p, o.repeat), reference));
    if (on_row) on_row(rows.back());
  }
  for (float nodes : o.nodes) {
    const cover::CoverParameters p = frame_parameters(o, Kind::noise_grid, nodes);
    rows.push_back(compare(p, Kind::noise_grid, run_frame(p, o.repeat), reference));
    if (on_row) on_row(rows.back());
  }
  return rows;
}

std::string noise_grid_line(const NoiseGridRow& r) {
  char line[320];
  std::snprintf(line, sizeof line,
                "%-29s %5.1f nodes per cell, %d octaves: %8.1f ms, density rms %.2e max %.2e, cover rms %.2e, "
                "cloudiness flipped %.2e",
                noise_grid_kind_name(r.kind), r.nodes, r.octaves, r.time_ms, r.density_rms, r.density_max, r.cover_rms,
                r.flipped);
  return line;
}

std::string noise_grid_csv(const std::vector<NoiseGridRow>& rows) {
  std::ostringstream s;
  s.precision(6);
  s << "kind,noise_grid_nodes,grid_octaves,time_ms,density_err_rms,density_err_max,cover_err_rms,flipped,"
       "density_spread\n";
  for (const auto& r : rows)
    s << noise_grid_kind_name(r.kind) << ',' << r.nodes << ',' << r.octaves << ',' << r.time_ms << ',' << r.density_rms
      << ',' << r.density_max << ',' << r.cover_rms << ',' << r.flipped << ',' << r.reference_spread << '\n';
  return s.str();
}

std::string noise_grid_svg(const std::vector<NoiseGridRow>& rows, const std::string& title) {
  const float default_nodes = float(params::cover::noise_grid_nodes.default_number);
  std::ostringstream s;
  begin_document(s, 1060, 500, title);
  const struct {
    double NoiseGridRow::*first;
    double NoiseGridRow::*second;
    const char* first_name;
    const char* second_name;
    const char* label;
  } panels[] = {{&NoiseGridRow::density_rms, &NoiseGridRow::density_max, "density rms", "density max",
                 "density against every octave at every texel"},
                {&NoiseGridRow::cover_rms, &NoiseGridRow::flipped, "cover rms", "share of texels flipped",
                 "cover against every octave at every texel"}};
  const char* colours[] = {"#1f77b4", "#d62728"};
  std::vector<const NoiseGridRow*> series;
  double reference_ms = 0;
  for (const auto& r : rows) {
    if (r.kind == Kind::noise_grid) series.push_back(&r);
    if (r.kind == Kind::reference) reference_ms = r.time_ms;
  }
  std::sort(series.begin(), series.end(), [](auto a, auto b) { return a->time_ms < b->time_ms; });
  for (int p = 0; p < 2; ++p) {
    std::vector<double> xs, ys;
    for (const auto& r : rows)
      if (r.kind != Kind::reference) {
        xs.push_back(r.time_ms);
        ys.push_back(r.*(panels[p].first));
        ys.push_back(r.*(panels[p].second));
      }
    if (reference_ms > 0) xs.push_back(reference_ms);
    if (xs.empty()) continue;
    const LogLogPanel panel(530.0 * p, 20, xs, ys, 1e-3, 1e-9);
    panel.draw_axes(s, "time of the warp and density passes (ms)", panels[p].label);
    for (int c = 0; c < 2; ++c) {
      double NoiseGridRow::*value = c == 0 ? panels[p].first : panels[p].second;
      std::vector<std::pair<double, double>> points;
      for (const auto* r : series) points.emplace_back(panel.x(r->time_ms), panel.y(r->*value));
      polyline(s, points, colours[c], c == 1);
      for (std::size_t k = 0; k < series.size(); ++k) {
        marker(s, c, points[k].first, points[k].second, colours[c]);
        if (series[k]->nodes == default_nodes) ring(s, points[k].first, points[k].second);
      }
      legend_line(s, 530.0 * p + 90 + 170 * c, 465, colours[c], c == 0 ? panels[p].first_name : panels[p].second_name,
                  c == 1);
      // The scales: grey, the trajectories from every texel; green, ten minutes later.
      for (const auto& r : rows)
        if (r.kind == Kind::every_texel || r.kind == Kind::later)
          marker(s, c, panel.x(r.time_ms), panel.y(r.*value), r.kind == Kind::every_texel ? "#888888" : "#2ca02c");
    }
    // Every octave at every texel: no error, its time a vertical line.
    if (reference_ms > 0) {
      const double x = panel.x(reference_ms);
      s << "<line x1='" << x << "' y1='" << 20 + LogLogPanel::top << "' x2='" << x << "' y2='"
        << 20 + LogLogPanel::height - LogLogPanel::bottom << "' stroke='#555' stroke-dasharray='2,2'/>\n";
    }
  }
  char note[240];
  std::snprintf(note, sizeof note,
                "dotted line: the reference's time; grey: the trajectories from every texel (the warp grid's own "
                "error); green: the reference ten minutes later; ring: the default, %g nodes per cell",
                double(default_nodes));
  s << "<text x='40' y='490'>" << escape(note) << "</text>\n";
  end_document(s);
  return s.str();
}

std::string noise_grid_markdown(const std::vector<NoiseGridRow>& rows, const NoiseGridOptions& o) {
  std::ostringstream s;
  char line[640];
  s << "## The noise grid: the density's first octaves from the warp grid\n\n";
  std::snprintf(line, sizeof line,
                "One frame at %s, %d texels per face, warp grid of %d nodes per face edge, against the same frame "
                "with every octave at every texel (the first row), over every texel. For scale: the trajectories "
                "traced from every texel instead of the warp grid, and the reference frame ten minutes later. Time: "
                "the warp and the density passes. The reference density's standard deviation: %.3f.\n\n",
                o.base.time.c_str(), o.size, o.warp_grid, rows.empty() ? 0.0 : rows.front().reference_spread);
  s << line;
  s << "| frame | nodes per cell | octaves on the grid | time (ms) | density rms | density max | cover rms | "
       "cloudiness flipped |\n";
  s << "|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : rows) {
    std::snprintf(line, sizeof line, "| %s | %g | %d | %.1f | %.2e | %.2e | %.2e | %.2e |\n",
                  noise_grid_kind_name(r.kind), double(r.nodes), r.octaves, r.time_ms, r.density_rms, r.density_max,
                  r.cover_rms, r.flipped);
    s << line;
  }
  s << "\n";
  return s.str();
}

}  // namespace nephele::studies
