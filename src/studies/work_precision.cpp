#include "studies/work_precision.hpp"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <stdexcept>

#include "cover/global_cover.hpp"
#include "studies/svg_plot.hpp"

namespace nephele::studies {
namespace {

using glm::dvec3;

// CPU time of this process, all threads (llvmpipe's included), in ms.
double process_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

double median_of(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

double quantile_of(std::vector<double> values, double q) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const size_t k = std::min(values.size() - 1, static_cast<size_t>(q * static_cast<double>(values.size())));
  return values[k];
}

double rms_of(const std::vector<double>& values) {
  double sum = 0.0;
  for (double v : values) sum += v * v;
  return values.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(values.size()));
}

double max_of(const std::vector<double>& values) {
  double m = 0.0;
  for (double v : values) m = std::max(m, v);
  return m;
}

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

std::string describe(Integrator integrator, CurlMode mode, int size, int steps, double tolerance) {
  std::ostringstream s;
  s << integrator_name(integrator) << " " << curl_mode_name(mode) << " size " << size;
  if (integrator == Integrator::adaptive)
    s << " tolerance " << tolerance;
  else
    s << " steps " << steps;
  return s.str();
}

struct Config {
  int steps;
  float step;
  float tolerance;
};

}  // namespace

SweepOptions SweepOptions::full(const cover::CoverParameters& base) {
  SweepOptions o;
  o.base = base;
  o.sizes = {128, 256, 512};
  o.integrators = all_integrators();
  o.curl_modes = {CurlMode::sampled, CurlMode::procedural, CurlMode::spline};
  o.steps = {1, 2, 4, 8, 16, 32, 50, 100, 200};
  o.tolerances = {1e-2f, 1e-3f, 1e-4f, 1e-5f, 1e-6f};
  o.sample_grid = 20;
  o.repeat = 3;
  o.budget_ms = 20000.0;
  return o;
}

SweepOptions SweepOptions::quick(const cover::CoverParameters& base) {
  SweepOptions o;
  o.base = base;
  o.sizes = {32};
  o.integrators = all_integrators();
  o.curl_modes = {CurlMode::sampled, CurlMode::procedural, CurlMode::spline};
  o.steps = {1, 2, 4, 8, 50};  // 1 and 2 keep RK4 above the float floor for its order
  o.tolerances = {1e-3f};
  o.sample_grid = 4;
  o.repeat = 1;
  o.budget_ms = 2000.0;
  return o;
}

int SweepOptions::planned_runs() const {
  int per_mode = 0;
  for (Integrator integrator : integrators)
    per_mode += static_cast<int>(integrator == Integrator::adaptive ? tolerances.size() : steps.size());
  return static_cast<int>(sizes.size() * curl_modes.size()) * per_mode;
}

SweepResult run_sweep(const SweepOptions& o, const std::function<void(const std::string&)>& progress,
                      const std::function<void(int)>& advance) {
  int runs_done = 0;
  auto advanced = [&] {
    if (advance) advance(++runs_done);
  };
  SweepResult result;
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  result.cpu_device = renderer && std::string(renderer).find("llvmpipe") != std::string::npos;
  const double flow_time = static_cast<double>(o.base.iterations) * o.base.step;
  result.flow_time = flow_time;
  const glsl::CurlParams curl = cover::curl_params(o.base);
  const glsl::FbmParams density = cover::density_params(o.base);
  const glm::vec3 flow_offset = cover::potential_offset(o.base), density_offset = cover::density_offset(o.base);

  // Sample points and their reference end points, shared by every size and run.
  const int m = std::max(1, o.sample_grid);
  const std::vector<glm::vec3> starts = sample_directions(6 * m * m, 0x5A3F1u);
  const auto reference_start = std::chrono::steady_clock::now();
  ReferenceOptions reference_options = o.reference;
  // The reference honours the budget too: points left when it runs out are dropped.
  if (o.budget_ms > 0.0)
    reference_options.deadline =
        reference_start + std::chrono::microseconds(static_cast<long long>(o.budget_ms * 1000.0));
  const std::vector<ReferencePoint> reference =
      reference_warps(starts, curl, flow_offset, flow_time, reference_options);
  result.reference_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - reference_start).count();
  result.samples = static_cast<int>(starts.size());
  double steps_sum = 0.0;
  for (const auto& r : reference) {
    steps_sum += static_cast<double>(r.steps);
    if (!r.converged) ++result.unconverged_samples;
    if (r.cut) ++result.cut_samples;
    if (r.converged) result.reference_error_estimate = std::max(result.reference_error_estimate, r.error_estimate);
  }
  result.mean_reference_steps = steps_sum / static_cast<double>(reference.size());
  progress("reference: " + std::to_string(starts.size()) + " points in " + format("%.1f", result.reference_seconds) +
           " s, " + format("%.0f", result.mean_reference_steps) + " steps per point on average; own error estimate " +
           format("%.1e", result.reference_error_estimate) + " rad");
  if (result.cut_samples > 0)
    progress("reference cut short by --budget-ms " + format("%.0f", o.budget_ms) + ": " +
             std::to_string(result.cut_samples) + " of " + std::to_string(starts.size()) +
             " points unfinished and left out of the statistics (raise --budget-ms for all)");
  if (result.cut_samples == static_cast<int>(starts.size()))
    throw std::runtime_error("the reference solution finished no sample point within --budget-ms " +
                             format("%.0f", o.budget_ms) + " ms: raise --budget-ms or lower --samples");

  std::vector<float> start_texels(4 * starts.size(), 0.0f);
  for (size_t k = 0; k < starts.size(); ++k)
    for (int c = 0; c < 3; ++c) start_texels[4 * k + c] = starts[k][c];
  const gpu::Texture start_field = gpu::Texture::cube(m, GL_RGBA32F);
  start_field.write(start_texels);
  const gpu::Texture sample_field = gpu::Texture::cube(m, GL_RGBA32F);

  for (int size : o.sizes) {
    FlowRates rates;
    bool have_rates = false;
    // Cost per velocity evaluation and texel pass, learnt from the runs so far (ms); used
    // only to skip runs that would exceed the budget.
    std::map<CurlMode, double> evaluation_ms;
    for (CurlMode mode : o.curl_modes)
      for (Integrator integrator : o.integrators) {
        std::vector<Config> configs;
        if (integrator == Integrator::adaptive) {
          for (float tolerance : o.tolerances) configs.push_back({o.base.iterations, o.base.step, tolerance});
        } else {
          for (int steps : o.steps) configs.push_back({steps, static_cast<float>(flow_time / steps), o.base.tolerance});
        }
        for (const Config& config : configs) {
          cover::CoverParameters p = o.base;
          p.flow = cover::Flow::steady;  // the sweep is of the steady warp (its reference flow)
          p.size = size;
          p.integrator = integrator;
          p.curl_mode = mode;
          p.iterations = config.steps;
          p.step = config.step;
          p.tolerance = config.tolerance;
          const std::string name = describe(integrator, mode, size, config.steps, config.tolerance);
          cover::GlobalCover cover(p);
          cover.run_identity();
          cover.run_curl();
          if (!have_rates) {
            rates = cover::flow_rates(cover.curl_field().read(), size);
            have_rates = true;
          }
          cover.warp_points(start_field, sample_field);
          const std::vector<float> sample_warp = sample_field.read();

          // Predicted cost: evaluations per texel times the cost of one.
          double evaluations = static_cast<double>(config.steps) * evaluations_per_step(integrator);
          if (integrator == Integrator::adaptive)
            evaluations = 1.0 + evaluations_per_step(integrator) * cover::substep_report(sample_warp).mean_attempts;
          const double curl_ms = cover.timings().back().milliseconds;
          const double per_evaluation =
              evaluation_ms.count(mode) ? evaluation_ms[mode] : (mode == CurlMode::procedural ? 2.5 : 0.1) * curl_ms;
          const double predicted = evaluations * per_evaluation;
          if (predicted > o.budget_ms) {
            result.skipped.push_back({name, predicted});
            progress("skipped " + name + ": predicted " + format("%.0f", predicted) + " ms");
            advanced();
            continue;
          }

          // Timed repeats of both passes (the first curl pass and the sample warp above were the
          // warm-up: llvmpipe compiles a shader at its first dispatch). Repeats stop early once
          // they took a third of the budget: long runs vary little.
          // Curl mode spline times its grid (pass "spline") in place of the curl pass: that is
          // what its warp needs, the curl cube map only what the diagnosis reads.
          const bool spline = mode == CurlMode::spline;
          std::vector<double> curl_wall, warp_wall, curl_cpu, warp_cpu;
          double spent_ms = 0.0;
          for (int r = 0; r < std::max(1, o.repeat) && (r == 0 || spent_ms < o.budget_ms / 3); ++r) {
            const double c0 = process_cpu_ms();
            if (spline)
              cover.run_spline();
            else
              cover.run_curl();
            const double c1 = process_cpu_ms();
            cover.run_warp();
            const double c2 = process_cpu_ms();
            curl_cpu.push_back(c1 - c0);
            warp_cpu.push_back(c2 - c1);
            curl_wall.push_back(cover.timings()[cover.timings().size() - 2].milliseconds);
            warp_wall.push_back(cover.timings().back().milliseconds);
            spent_ms += warp_wall.back();
          }
          cover.run_density();
          const cover::CoverageCalibration calibration = cover.run_coverage();

          SweepRow row;
          row.integrator = integrator;
          row.curl_mode = mode;
          row.size = size;
          row.step = config.step;
          row.tolerance = integrator == Integrator::adaptive ? config.tolerance : 0.0;
          // The fastest of the repeats: other processes on the machine only ever add time. On a
          // CPU device (llvmpipe) the passes' own CPU time counts, which they barely inflate.
          const bool cpu_device = result.cpu_device;
          auto fastest = [](const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); };
          row.curl_ms = fastest(cpu_device ? curl_cpu : curl_wall);
          row.warp_ms = fastest(cpu_device ? warp_cpu : warp_wall);
          // The sampled variant needs the curl cube map and the spline its grid (curl_ms: the
          // grid's pass); the procedural one only the warp pass.
          const bool needs_curl = mode != CurlMode::procedural;
          row.wall_ms = fastest(warp_wall) + (needs_curl ? fastest(curl_wall) : 0.0);
          row.time_ms = row.warp_ms + (needs_curl ? row.curl_ms : 0.0);
          evaluation_ms[mode] = std::min(evaluation_ms.count(mode) ? evaluation_ms[mode] : 1e300,
                                         row.warp_ms / std::max(1.0, evaluations));

          std::vector<double> warp_errors, cover_errors;
          for (size_t k = 0; k < starts.size(); ++k) {
            const glm::vec3 w(sample_warp[4 * k], sample_warp[4 * k + 1], sample_warp[4 * k + 2]);
            const float length = glm::length(w);
            if (!std::isfinite(length) || std::abs(length - 1.0f) > 1e-5f) row.off_sphere = true;
            if (!reference[k].converged) continue;
            warp_errors.push_back(great_circle_distance(dvec3(w), reference[k].end));
            const float approximate =
                glsl::cover_from_density(glsl::cover_density_shifted(w, density, density_offset), calibration.threshold,
                                         calibration.density_max, p.cover_softness);
            const float exact = glsl::cover_from_density(
                glsl::cover_density_shifted(glm::vec3(reference[k].end), density, density_offset),
                calibration.threshold, calibration.density_max, p.cover_softness);
            cover_errors.push_back(std::abs(static_cast<double>(approximate) - exact));
          }
          row.warp_err_rms = rms_of(warp_errors);
          row.warp_err_max = max_of(warp_errors);
          row.warp_err_median = median_of(warp_errors);
          row.warp_err_p99 = quantile_of(warp_errors, 0.99);
          row.cover_err_rms = rms_of(cover_errors);
          row.cover_err_max = max_of(cover_errors);

          const std::vector<float> warp = cover.warp_field().read();
          row.stiffness = cover::stiffness_report(rates, config.step, integrator);
          row.folding = cover::folding_report(warp, size);
          row.substeps = cover::substep_report(warp);
          row.steps = integrator == Integrator::adaptive ? static_cast<int>(std::lround(row.substeps.mean_attempts))
                                                         : config.steps;
          result.rows.push_back(row);
          progress(name + ": " + format("%.1f", row.time_ms) + " ms, warp error rms " +
                   format("%.2e", row.warp_err_rms) + " max " + format("%.2e", row.warp_err_max) +
                   ", cover error rms " + format("%.2e", row.cover_err_rms));
          advanced();
        }
      }
  }
  result.comparisons = compare_with_default(result.rows);
  for (const auto& c : compare_with_default(result.rows, CurlMode::procedural))
    if (c.has_baseline) result.comparisons.push_back(c);
  result.orders = observed_orders(result.rows);
  return result;
}

std::vector<ObservedOrder> observed_orders(const std::vector<SweepRow>& rows, double floor) {
  std::vector<ObservedOrder> orders;
  for (const auto& first : rows) {
    if (first.integrator == Integrator::adaptive) continue;
    bool seen = false;
    for (const auto& o : orders)
      seen = seen || (o.integrator == first.integrator && o.curl_mode == first.curl_mode && o.size == first.size);
    if (seen) continue;
    double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (const auto& r : rows)
      if (r.integrator == first.integrator && r.curl_mode == first.curl_mode && r.size == first.size &&
          r.warp_err_rms > floor && r.steps > 0) {
        const double x = std::log(static_cast<double>(r.steps)), y = std::log(r.warp_err_rms);
        n += 1;
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
      }
    const double spread = n * sxx - sx * sx;
    if (n < 2 || !(spread > 0)) continue;
    orders.push_back(
        {first.integrator, first.curl_mode, first.size, -(n * sxy - sx * sy) / spread, static_cast<int>(n)});
  }
  return orders;
}

std::vector<Comparison> compare_with_default(const std::vector<SweepRow>& rows, CurlMode baseline_mode) {
  std::vector<int> sizes;
  for (const auto& r : rows)
    if (std::find(sizes.begin(), sizes.end(), r.size) == sizes.end()) sizes.push_back(r.size);
  std::vector<Comparison> comparisons;
  for (int size : sizes) {
    Comparison c;
    c.size = size;
    c.baseline_mode = baseline_mode;
    for (const auto& r : rows)
      if (r.size == size && r.integrator == Integrator::euler && r.curl_mode == baseline_mode && r.steps == 50) {
        c.baseline = r;
        c.has_baseline = true;
      }
    if (c.has_baseline) {
      for (const auto& r : rows) {
        if (r.size != size || (r.integrator == Integrator::euler && r.curl_mode == baseline_mode && r.steps == 50))
          continue;
        if (r.warp_err_rms <= c.baseline.warp_err_rms && (!c.has_equal_error || r.time_ms < c.equal_error.time_ms)) {
          c.equal_error = r;
          c.has_equal_error = true;
        }
        if (r.time_ms <= c.baseline.time_ms && (!c.has_equal_time || r.warp_err_rms < c.equal_time.warp_err_rms)) {
          c.equal_time = r;
          c.has_equal_time = true;
        }
      }
      if (c.has_equal_error) c.speedup = c.baseline.time_ms / c.equal_error.time_ms;
      if (c.has_equal_time && c.equal_time.warp_err_rms > 0)
        c.error_ratio = c.baseline.warp_err_rms / c.equal_time.warp_err_rms;
    }
    comparisons.push_back(c);
  }
  return comparisons;
}

std::string error_csv(const std::vector<SweepRow>& rows) {
  std::ostringstream s;
  s << "integrator,curl_mode,size,steps,time_ms,warp_err_rms,warp_err_max,cover_err_rms,cover_err_max\n";
  char line[512];
  for (const auto& r : rows) {
    std::snprintf(line, sizeof line, "%s,%s,%d,%d,%.4f,%.6e,%.6e,%.6e,%.6e\n", integrator_name(r.integrator),
                  curl_mode_name(r.curl_mode), r.size, r.steps, r.time_ms, r.warp_err_rms, r.warp_err_max,
                  r.cover_err_rms, r.cover_err_max);
    s << line;
  }
  return s.str();
}

std::string stability_csv(const std::vector<SweepRow>& rows) {
  std::ostringstream s;
  s << "integrator,curl_mode,size,steps,step,tolerance,time_ms,curl_ms,warp_ms,wall_ms,warp_err_median,warp_err_p99,"
       "max_rate,stiffness,stable_limit,beyond_fraction,folded_fraction,jacobian_min,jacobian_max,area_error_rms,"
       "mean_substeps,max_substeps,capped_texels,off_sphere\n";
  char line[1024];
  for (const auto& r : rows) {
    std::snprintf(line, sizeof line,
                  "%s,%s,%d,%d,%.6g,%.3g,%.4f,%.4f,%.4f,%.4f,%.6e,%.6e,%.6g,%.6g,%.4g,%.6e,%.6e,%.6g,%.6g,%.6g,%.3f,%."
                  "0f,%ld,%d\n",
                  integrator_name(r.integrator), curl_mode_name(r.curl_mode), r.size, r.steps, r.step, r.tolerance,
                  r.time_ms, r.curl_ms, r.warp_ms, r.wall_ms, r.warp_err_median, r.warp_err_p99, r.stiffness.max_rate,
                  r.stiffness.stiffness, r.stiffness.limit, r.stiffness.beyond_fraction, r.folding.folded_fraction,
                  r.folding.jacobian_min, r.folding.jacobian_max, r.folding.area_error_rms, r.substeps.mean_attempts,
                  r.substeps.max_attempts, r.substeps.capped_texels, r.off_sphere ? 1 : 0);
    s << line;
  }
  return s.str();
}

namespace {

const char* colour(Integrator integrator) {
  switch (integrator) {
    case Integrator::euler: return "#1f77b4";
    case Integrator::heun: return "#ff7f0e";
    case Integrator::rk4: return "#2ca02c";
    case Integrator::geodesic: return "#9467bd";
    case Integrator::adaptive: return "#d62728";
  }
  return "#000000";
}

// The diagram's line style per curl mode: sampled solid, procedural dashed, spline dotted.
const char* curl_mode_dashes(CurlMode mode) {
  switch (mode) {
    case CurlMode::procedural: return "6,3";
    case CurlMode::spline: return "2,2";
    default: return "";
  }
}

// One log-log panel of the diagram at (x0, y0).
void svg_panel(std::ostringstream& s, const std::vector<SweepRow>& rows, double x0, double y0, const std::string& label,
               double SweepRow::*error, const std::vector<int>& sizes, const std::string& time_label) {
  std::vector<double> times, errors;
  for (const auto& r : rows) {
    times.push_back(r.time_ms);
    errors.push_back(r.*error);
  }
  const studies::LogLogPanel panel(x0, y0, times, errors);
  panel.draw_axes(s, time_label, label);
  // One polyline per integrator, curl mode and size, in order of time.
  for (Integrator integrator : all_integrators())
    for (CurlMode mode : cover::all_curl_modes())
      for (size_t si = 0; si < sizes.size(); ++si) {
        std::vector<const SweepRow*> series;
        for (const auto& r : rows)
          if (r.integrator == integrator && r.curl_mode == mode && r.size == sizes[si]) series.push_back(&r);
        if (series.empty()) continue;
        std::sort(series.begin(), series.end(), [](auto a, auto b) { return a->time_ms < b->time_ms; });
        std::vector<std::pair<double, double>> points;
        for (const SweepRow* r : series) points.emplace_back(panel.x(r->time_ms), panel.y(r->*error));
        studies::polyline(s, points, colour(integrator), curl_mode_dashes(mode));
        for (size_t k = 0; k < series.size(); ++k) {
          studies::marker(s, static_cast<int>(si), points[k].first, points[k].second, colour(integrator));
          const SweepRow* r = series[k];
          if (r->integrator == Integrator::euler && r->curl_mode == CurlMode::sampled && r->steps == 50)
            studies::ring(s, points[k].first, points[k].second);
        }
      }
}

}  // namespace

std::string work_precision_svg(const std::vector<SweepRow>& rows, const std::string& title,
                               const std::string& time_label) {
  std::vector<int> sizes;
  for (const auto& r : rows)
    if (std::find(sizes.begin(), sizes.end(), r.size) == sizes.end()) sizes.push_back(r.size);
  std::sort(sizes.begin(), sizes.end());
  std::ostringstream s;
  studies::begin_document(s, 1060, 490, title);
  svg_panel(s, rows, 0, 20, "warp error, rms great-circle distance (rad)", &SweepRow::warp_err_rms, sizes, time_label);
  svg_panel(s, rows, 530, 20, "cover error, rms", &SweepRow::cover_err_rms, sizes, time_label);
  // Legend: colours are integrators, dashes the curl mode, markers the size.
  double x = 80;
  for (Integrator integrator : all_integrators()) {
    studies::legend_line(s, x, 455, colour(integrator), integrator_name(integrator));
    x += 95;
  }
  studies::legend_line(s, x, 455, "#444", "sampled");
  x += 85;
  studies::legend_line(s, x, 455, "#444", "procedural", curl_mode_dashes(CurlMode::procedural));
  x += 95;
  studies::legend_line(s, x, 455, "#444", "spline", curl_mode_dashes(CurlMode::spline));
  x = 80;  // second row: sizes and the default
  const char* markers[] = {"circle", "square", "triangle"};
  for (size_t si = 0; si < sizes.size(); ++si) {
    s << "<text x='" << x << "' y='479'>" << markers[si % 3] << ": size " << sizes[si] << "</text>\n";
    x += 130;
  }
  s << "<text x='" << x << "' y='479'>ring: euler, 50 steps, sampled curl (the default)</text>\n";
  studies::end_document(s);
  return s.str();
}

std::string summary_markdown(const SweepResult& result, const SweepOptions& options) {
  std::ostringstream s;
  char line[1024];
  s << "# Error against run time of the global cover's warp\n\n";
  s << "Device: " << result.device << "\n\n";
  std::snprintf(line, sizeof line,
                "Flow time T = %.4g; %d sample points; reference: RK4 in double with step doubling, tolerance %.0e "
                "per step, steps at most %.0e, %.0f steps per point on average, %.1f s; %d points did not converge "
                "and are left out.\n\n",
                result.flow_time, result.samples, options.reference.tolerance, options.reference.max_step,
                result.mean_reference_steps, result.reference_seconds, result.unconverged_samples);
  s << line;
  std::snprintf(line, sizeof line,
                "The reference's own error estimate (sum of its accepted local error estimates, largest over the "
                "points) is %.1e rad: warp errors near it are not resolved.%s\n\n",
                result.reference_error_estimate,
                result.cut_samples > 0 ? (" The budget (--budget-ms " + format("%.0f", options.budget_ms) +
                                          ") cut the reference short: " + std::to_string(result.cut_samples) +
                                          " of the points above were not finished.")
                                             .c_str()
                                       : "");
  s << line;
  s << "Times are the fastest of up to " << options.repeat
    << " runs of the curl pass (sampled curl) or the spline's grid (spline curl) plus the warp pass, "
    << (result.cpu_device ? "in CPU time of all threads (the device is the CPU: llvmpipe; other processes barely "
                            "inflate it; stability.csv has the wall-clock times too)"
                          : "in wall-clock time")
    << "; errors are great-circle distances (radians) of the warped sample points from the reference, and "
       "differences of the cover there.\n\n";
  s << "## Observed orders\n\n";
  s << "Minus the least-squares slope of log(warp rms error) against log(steps), over the runs whose error "
       "exceeds "
    << format("%.0e", order_error_floor)
    << " rad (below it float rounding sets the error). The sampled curl is bilinear, only continuous: its "
       "error levels off at the sampling error of the size.\n\n| integrator | curl | size | order | runs |\n"
       "|---|---|---|---|---|\n";
  for (const auto& o : result.orders) {
    std::snprintf(line, sizeof line, "| %s | %s | %d | %.2f | %d |\n", integrator_name(o.integrator),
                  curl_mode_name(o.curl_mode), o.size, o.order, o.runs);
    s << line;
  }
  s << "\n## Against euler with 50 steps (sfsim's scheme), sampled and procedural curl\n\n";
  s << "| size | default time ms | default warp rms | equal error: fastest run | time ms | speed-up | equal time: "
       "most accurate run | warp rms | error ratio |\n|---|---|---|---|---|---|---|---|---|\n";
  auto name = [](const SweepRow& r) {
    std::ostringstream n;
    n << integrator_name(r.integrator) << " " << curl_mode_name(r.curl_mode) << " ";
    if (r.integrator == Integrator::adaptive)
      n << "tol " << r.tolerance << " (" << r.steps << " steps)";
    else
      n << r.steps << " steps";
    return n.str();
  };
  for (const auto& c : result.comparisons) {
    if (!c.has_baseline) {
      s << "| " << c.size << " | no default run in the sweep | | | | | | | |\n";
      continue;
    }
    std::snprintf(line, sizeof line, "| %d %s | %.1f | %.3e | %s | %s | %s | %s | %s | %s |\n", c.size,
                  curl_mode_name(c.baseline_mode), c.baseline.time_ms, c.baseline.warp_err_rms,
                  c.has_equal_error ? name(c.equal_error).c_str() : "none",
                  c.has_equal_error ? format("%.1f", c.equal_error.time_ms).c_str() : "-",
                  c.has_equal_error ? format("%.2fx", c.speedup).c_str() : "-",
                  c.has_equal_time ? name(c.equal_time).c_str() : "none",
                  c.has_equal_time ? format("%.3e", c.equal_time.warp_err_rms).c_str() : "-",
                  c.has_equal_time ? format("%.2fx", c.error_ratio).c_str() : "-");
    s << line;
  }
  double best_speedup = 0, best_ratio = 0;
  for (const auto& c : result.comparisons) {
    best_speedup = std::max(best_speedup, c.speedup);
    best_ratio = std::max(best_ratio, c.error_ratio);
  }
  std::snprintf(line, sizeof line,
                "\nBest speed-up at equal error: %.2fx; best error reduction at equal time: %.2fx. The goal (10x "
                "either way) is %s.\n\n",
                best_speedup, best_ratio, best_speedup >= 10 || best_ratio >= 10 ? "met" : "not met");
  s << line;

  s << "## Stiffness, folding and sub-steps\n\n";
  s << "| run | h | max rate | stiffness h rho | stable limit | beyond limit (sphere fraction) | folded fraction | "
       "rms(J - 1) | mean sub-steps | capped texels | off sphere |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : result.rows) {
    std::snprintf(line, sizeof line,
                  "| %s size %d | %.4g | %.1f | %.3g | %.3g | %.2e | %.2e | %.3g | %.1f | %ld | %s |\n",
                  name(r).c_str(), r.size, r.step, r.stiffness.max_rate, r.stiffness.stiffness, r.stiffness.limit,
                  r.stiffness.beyond_fraction, r.folding.folded_fraction, r.folding.area_error_rms,
                  r.substeps.mean_attempts, r.substeps.capped_texels, r.off_sphere ? "yes" : "no");
    s << line;
  }
  if (!result.skipped.empty()) {
    s << "\n## Skipped runs (predicted time over the budget of " << format("%.0f", options.budget_ms) << " ms)\n\n";
    for (const auto& k : result.skipped)
      s << "- " << k.description << ": " << format("%.0f", k.predicted_ms) << " ms\n";
  }
  return s.str();
}

}  // namespace nephele::studies
