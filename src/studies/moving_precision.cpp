#include "studies/moving_precision.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "cover/global_cover.hpp"
#include "cover/moving_flow.hpp"
#include "shader_math/shader_math.hpp"
#include "studies/svg_plot.hpp"

namespace nephele::studies {
namespace {

using glsl::vec3;

// The sample texels: a g x g grid of texel centres on each face, g = ceil(sqrt(samples / 6)),
// as indices into a face-major RGBA read-back.
std::vector<std::size_t> sample_texels(int size, int samples) {
  const int g = std::clamp(int(std::ceil(std::sqrt(samples / 6.0))), 1, size);
  std::vector<std::size_t> out;
  for (int face = 0; face < 6; ++face)
    for (int j = 0; j < g; ++j)
      for (int i = 0; i < g; ++i) {
        const int x = std::min(size - 1, int((i + 0.5) * size / g)), y = std::min(size - 1, int((j + 0.5) * size / g));
        out.push_back((std::size_t(face) * size + y) * size + x);
      }
  return out;
}

struct Layers {
  std::vector<vec3> young, old;
};

// Both layers' points at the samples by the CPU twin with `factor` times the run's steps: the
// procedural flow, one trajectory as the GPU's (young, then on to the older layer's age).
Layers reference_layers(const cover::CoverParameters& p, const cover::FrameClock& clock,
                        const std::vector<vec3>& starts, int factor) {
  const glsl::MovingCurl field{cover::curl_params(p), cover::potential_offset(p), clock.motion};
  Layers out;
  for (const vec3& x : starts) {
    const vec3 young = glsl::back_trajectory(x, clock.time, clock.young_age, clock.young_steps * factor, field);
    out.young.push_back(young);
    out.old.push_back(glsl::back_trajectory(young, clock.time - clock.young_age, clock.old_age - clock.young_age,
                                            clock.older_steps * factor, field));
  }
  return out;
}

vec3 point(const std::vector<float>& field, std::size_t texel) {
  return vec3(field[4 * texel], field[4 * texel + 1], field[4 * texel + 2]);
}

double angle(vec3 a, vec3 b) {
  const double ax = a.x, ay = a.y, az = a.z, bx = b.x, by = b.y, bz = b.z;
  const double cx = ay * bz - az * by, cy = az * bx - ax * bz, cz = ax * by - ay * bx;
  return std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), ax * bx + ay * by + az * bz);
}

bool on_sphere(vec3 a) {
  const double length = std::sqrt(double(a.x) * a.x + double(a.y) * a.y + double(a.z) * a.z);
  return std::isfinite(length) && std::abs(length - 1.0) <= 1e-5;
}

struct Config {
  const char* sweep;
  cover::CurlMode mode;
  int curl_size;
  int iterations;
  float step;
  int warp_grid = 0;  // the trajectories from a grid of this many nodes per face edge (0: every texel)
};

MovingPrecisionRow run_config(const MovingPrecisionOptions& o, const Config& c,
                              std::map<std::pair<int, float>, Layers>& references) {
  cover::CoverParameters p = o.base;
  p.flow = cover::Flow::moving;
  p.integrator = cover::Integrator::rk4;
  p.size = o.size;
  p.iterations = c.iterations;
  p.step = c.step;
  p.curl_mode = c.mode;
  if (c.mode == cover::CurlMode::spline) p.curl_size = c.curl_size;
  p.warp_grid = c.warp_grid;
  MovingPrecisionRow row;
  row.sweep = c.sweep;
  row.curl_mode = cover::curl_mode_name(c.mode);
  row.curl_size = c.mode == cover::CurlMode::spline ? c.curl_size : 0;
  row.iterations = c.iterations;
  row.step = c.step;
  row.warp_grid = cover::warp_grid_cells(p);
  const cover::FrameClock clock = cover::frame_clock(p, cover::hours_since_epoch(p.time));
  row.window_hours = clock.old_age * cover::flow_hours_per_unit;
  std::vector<double> times;
  std::vector<float> identity, young, old;
  for (int k = 0; k < std::max(1, o.repeat); ++k) {
    cover::GlobalCover cover(p);  // new each time: the spline grids are made in every run
    cover.run_identity();
    if (c.mode == cover::CurlMode::spline) cover.run_moving_splines();
    cover.run_moving_warp();
    double ms = 0;
    for (const cover::PassTiming& t : cover.timings())
      if (t.pass == "spline" || t.pass == "warp") ms += t.milliseconds;
    times.push_back(ms);
    if (k == 0) {
      identity = cover.identity_field().read();
      young = cover.young_warp_field().read();
      old = cover.warp_field().read();
    }
  }
  std::sort(times.begin(), times.end());
  row.time_ms = times[times.size() / 2];
  const std::vector<std::size_t> texels = sample_texels(o.size, o.samples);
  const auto key = std::make_pair(c.iterations, c.step);
  if (!references.count(key)) {
    std::vector<vec3> starts;
    for (std::size_t t : texels) starts.push_back(point(identity, t));
    references[key] = reference_layers(p, clock, starts, o.reference_factor);
  }
  const Layers& reference = references[key];
  double young_sum = 0, old_sum = 0;
  for (std::size_t k = 0; k < texels.size(); ++k) {
    const vec3 y = point(young, texels[k]), w = point(old, texels[k]);
    row.finite = row.finite && on_sphere(y) && on_sphere(w);
    const double ey = angle(y, reference.young[k]), eo = angle(w, reference.old[k]);
    young_sum += ey * ey;
    old_sum += eo * eo;
    row.young_max = std::max(row.young_max, ey);
    row.old_max = std::max(row.old_max, eo);
  }
  // Every texel, not only the samples, must stay finite and on the sphere.
  for (std::size_t t = 0; t < young.size() / 4; ++t)
    row.finite = row.finite && on_sphere(point(young, t)) && on_sphere(point(old, t));
  row.young_rms = std::sqrt(young_sum / double(texels.size()));
  row.old_rms = std::sqrt(old_sum / double(texels.size()));
  return row;
}

std::string series_name(const MovingPrecisionRow& r) {
  const std::string curl = r.curl_mode == "spline" ? "spline " + std::to_string(r.curl_size) : r.curl_mode;
  return r.warp_grid > 0 ? curl + ", warp grid" : curl;
}

const char* series_colour(std::size_t k) {
  static const char* colours[] = {"#d62728", "#1f77b4", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"};
  return colours[k % 6];
}

// The frame of both sweeps: 12 hours after the flow's time 0, where the defaults' layers are
// aged 0.9 T and 1.4 T (near the longest window, 3T/2, that a frame integrates).
cover::CoverParameters with_frame_time(cover::CoverParameters p) {
  p.time = "2000-01-01T12:00Z";
  return p;
}

}  // namespace

MovingPrecisionOptions MovingPrecisionOptions::full(const cover::CoverParameters& base) {
  return {with_frame_time(base), 128, 384, 32, {1, 2, 4, 8, 16}, {1, 2, 4, 8, 16}, {64, 128, 256}, {16, 32, 64}, 3};
}

MovingPrecisionOptions MovingPrecisionOptions::quick(const cover::CoverParameters& base) {
  return {with_frame_time(base), 16, 24, 8, {1, 2, 4}, {1, 2, 4}, {32}, {8}, 1};
}

std::vector<MovingPrecisionRow> moving_precision_sweep(const MovingPrecisionOptions& o,
                                                       const std::function<void(const MovingPrecisionRow&)>& on_row) {
  const double flow_time = double(o.base.iterations) * o.base.step;
  std::vector<Config> configs;
  // The step: T fixed, h = T / K, procedural and each spline grid.
  for (int k : o.steps) {
    const float h = static_cast<float>(flow_time / k);
    configs.push_back({"step", cover::CurlMode::procedural, 0, k, h});
    for (int n : o.curl_sizes) configs.push_back({"step", cover::CurlMode::spline, n, k, h});
  }
  // The window: h fixed, T = K h; procedural and the finest grid.
  for (int k : o.windows) {
    configs.push_back({"window", cover::CurlMode::procedural, 0, k, o.base.step});
    if (!o.curl_sizes.empty())
      configs.push_back({"window", cover::CurlMode::spline, o.curl_sizes.back(), k, o.base.step});
  }
  // The warp grid: the defaults' K and h and the finest curl grid, the trajectories from coarser
  // and coarser grids of nodes.
  for (int g : o.warp_grids)
    if (!o.curl_sizes.empty())
      configs.push_back({"grid", cover::CurlMode::spline, o.curl_sizes.back(), o.base.iterations, o.base.step, g});
  std::map<std::pair<int, float>, Layers> references;
  std::vector<MovingPrecisionRow> rows;
  for (const Config& c : configs) {
    rows.push_back(run_config(o, c, references));
    if (on_row) on_row(rows.back());
  }
  return rows;
}

std::string moving_precision_line(const MovingPrecisionRow& r) {
  char line[256];
  std::snprintf(line, sizeof line,
                "%-6s %-10s %4d K %2d h %.4f W %6.1f h grid %4d: %8.1f ms, young rms %.2e max %.2e, old rms %.2e max "
                "%.2e%s",
                r.sweep.c_str(), r.curl_mode.c_str(), r.curl_size, r.iterations, r.step, r.window_hours, r.warp_grid,
                r.time_ms, r.young_rms, r.young_max, r.old_rms, r.old_max, r.finite ? "" : " NOT FINITE");
  return line;
}

std::string moving_precision_csv(const std::vector<MovingPrecisionRow>& rows) {
  std::ostringstream s;
  s.precision(6);
  s << "sweep,curl_mode,curl_size,iterations,step,window_hours,time_ms,young_err_rms,young_err_max,old_err_rms,"
       "old_err_max,finite,warp_grid\n";
  for (const auto& r : rows)
    s << r.sweep << ',' << r.curl_mode << ',' << r.curl_size << ',' << r.iterations << ',' << r.step << ','
      << r.window_hours << ',' << r.time_ms << ',' << r.young_rms << ',' << r.young_max << ',' << r.old_rms << ','
      << r.old_max << ',' << (r.finite ? 1 : 0) << ',' << r.warp_grid << '\n';
  return s.str();
}

std::string moving_precision_svg(const std::vector<MovingPrecisionRow>& rows, const std::string& title) {
  std::vector<std::string> names;
  for (const auto& r : rows)
    if (std::find(names.begin(), names.end(), series_name(r)) == names.end()) names.push_back(series_name(r));
  std::ostringstream s;
  begin_document(s, 1060, 480, title);
  const struct {
    const char* sweep;
    double MovingPrecisionRow::*x;
    const char* label;
  } panels[] = {{"step", &MovingPrecisionRow::time_ms, "time of the spline grids and the warp (ms)"},
                {"window", &MovingPrecisionRow::window_hours, "window: the older layer's age (hours)"}};
  for (int p = 0; p < 2; ++p) {
    std::vector<double> xs, ys;
    for (const auto& r : rows)
      if (r.sweep == panels[p].sweep || (p == 0 && r.sweep == "grid")) {
        xs.push_back(r.*(panels[p].x));
        ys.push_back(r.old_max);
      }
    if (xs.empty()) continue;
    const LogLogPanel panel(530.0 * p, 20, xs, ys, 1e-3, 1e-9);
    panel.draw_axes(s, panels[p].label, "older layer: largest error against the reference (rad)");
    for (std::size_t n = 0; n < names.size(); ++n) {
      std::vector<const MovingPrecisionRow*> series;
      for (const auto& r : rows)
        if ((r.sweep == panels[p].sweep || (p == 0 && r.sweep == "grid")) && series_name(r) == names[n])
          series.push_back(&r);
      if (series.empty()) continue;
      std::sort(series.begin(), series.end(), [&](auto a, auto b) { return a->*(panels[p].x) < b->*(panels[p].x); });
      std::vector<std::pair<double, double>> points;
      for (const auto* r : series) points.emplace_back(panel.x(r->*(panels[p].x)), panel.y(r->old_max));
      polyline(s, points, series_colour(n));
      for (std::size_t k = 0; k < series.size(); ++k) {
        marker(s, 0, points[k].first, points[k].second, series_colour(n));
        // The defaults: K = 2 steps of 0.15.
        if (series[k]->iterations == 2 && std::abs(series[k]->step - 0.15) < 1e-6 && series[k]->sweep != "grid")
          ring(s, points[k].first, points[k].second);
      }
    }
  }
  double x = 80;
  for (std::size_t n = 0; n < names.size(); ++n) {
    legend_line(s, x, 465, series_colour(n), names[n]);
    x += 130;
  }
  s << "<text x='" << x << "' y='470'>ring: the defaults (2 steps of 0.15)</text>\n";
  end_document(s);
  return s.str();
}

std::string moving_precision_markdown(const std::vector<MovingPrecisionRow>& rows, const MovingPrecisionOptions& o) {
  std::ostringstream s;
  char line[512];
  s << "## The moving flow: error against run time and window\n\n";
  std::snprintf(line, sizeof line,
                "One frame at %s, %d texels per face; %zu sample texels against the procedural flow on the CPU with "
                "%d times the steps. Time: the spline grids (curl mode spline) and the warp pass. Errors: great-circle "
                "distance in radians (a texel at 1024 per face is 1.5e-3 rad).\n\n",
                o.base.time.c_str(), o.size, sample_texels(o.size, o.samples).size(), o.reference_factor);
  s << line;
  s << "| sweep | curl | warp grid | K | h | window (h) | time (ms) | younger rms | younger max | older rms | older "
       "max "
       "| finite |\n";
  s << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : rows) {
    std::snprintf(line, sizeof line, "| %s | %s | %s | %d | %.4g | %.1f | %.1f | %.2e | %.2e | %.2e | %.2e | %s |\n",
                  r.sweep.c_str(), series_name(r).c_str(),
                  r.warp_grid > 0 ? std::to_string(r.warp_grid).c_str() : "every texel", r.iterations, r.step,
                  r.window_hours, r.time_ms, r.young_rms, r.young_max, r.old_rms, r.old_max, r.finite ? "yes" : "NO");
    s << line;
  }
  s << "\n";
  return s.str();
}

}  // namespace nephele::studies
