#pragma once
// The work-precision sweep behind `nephele report`: every integrator x steps x curl mode x
// size runs on the GPU, is timed, and its warp is compared with the reference flow at sample
// points (docs/numerics.md, "The report").
#include <functional>
#include <string>
#include <vector>

#include "cover/cover_parameters.hpp"
#include "cover/integrators.hpp"
#include "studies/reference_flow.hpp"
#include "cover/stability.hpp"

namespace nephele::studies {

using cover::all_integrators;
using cover::curl_mode_name;
using cover::CurlMode;
using cover::FlowRates;
using cover::FoldingReport;
using cover::Integrator;
using cover::integrator_name;
using cover::StiffnessReport;
using cover::SubstepReport;

struct SweepOptions {
  cover::CoverParameters base;  // the flow and cover; T = base.iterations * base.step
  std::vector<int> sizes;
  std::vector<Integrator> integrators;  // fixed-step ones run `steps`, adaptive `tolerances`
  std::vector<CurlMode> curl_modes;
  std::vector<int> steps;
  std::vector<float> tolerances;
  int sample_grid = 16;        // 6 sample_grid^2 sample points
  int repeat = 3;              // timed runs per configuration; the fastest counts
  double budget_ms = 30000.0;  // skip runs predicted to take longer than this
  ReferenceOptions reference;

  // Runs the sweep plans (some may be skipped by the budget), for progress reports.
  int planned_runs() const;

  static SweepOptions full(const cover::CoverParameters& base);
  static SweepOptions quick(const cover::CoverParameters& base);
};

struct SweepRow {
  Integrator integrator = Integrator::euler;
  CurlMode curl_mode = CurlMode::sampled;
  int size = 0;
  int steps = 0;           // K; adaptive: mean attempted steps per texel, rounded
  double step = 0.0;       // h; adaptive: the first step
  double tolerance = 0.0;  // adaptive only
  // Curl pass (sampled only) + warp pass, fastest of the repeats; on a CPU device (llvmpipe)
  // CPU time of all threads, else wall-clock time. wall_ms is always wall-clock.
  double time_ms = 0.0;
  double curl_ms = 0.0, warp_ms = 0.0, wall_ms = 0.0;
  double warp_err_rms = 0.0, warp_err_max = 0.0, warp_err_median = 0.0, warp_err_p99 = 0.0;
  double cover_err_rms = 0.0, cover_err_max = 0.0;
  StiffnessReport stiffness;
  FoldingReport folding;
  SubstepReport substeps;
  bool off_sphere = false;  // a warped point off the unit sphere by more than 1e-5, or not finite
};

struct SkippedRun {
  std::string description;
  double predicted_ms;
};

// A comparison with Euler, 50 steps (sfsim's scheme) at one size, with the sampled curl or,
// with the same velocity as the default, the procedural one.
struct Comparison {
  int size = 0;
  CurlMode baseline_mode = CurlMode::sampled;
  bool has_baseline = false;
  SweepRow baseline;
  bool has_equal_error = false;  // the fastest run with warp_err_rms <= the baseline's
  SweepRow equal_error;
  double speedup = 0.0;         // baseline time / its time
  bool has_equal_time = false;  // the most accurate run with time_ms <= the baseline's
  SweepRow equal_time;
  double error_ratio = 0.0;  // baseline warp_err_rms / its warp_err_rms
};

// The observed order of a fixed-step scheme: minus the least-squares slope of log(warp_err_rms)
// against log(steps) over its runs at one size and curl mode whose error lies above `floor`
// (below it float rounding, not the step, sets the error).
struct ObservedOrder {
  Integrator integrator = Integrator::euler;
  CurlMode curl_mode = CurlMode::sampled;
  int size = 0;
  double order = 0.0;
  int runs = 0;  // runs in the fit (at least 2)
};
// The warp's float rounding: about 1e-7 rad per unit of flow (the RK4 errors level off there).
constexpr double order_error_floor = 1e-6;
std::vector<ObservedOrder> observed_orders(const std::vector<SweepRow>& rows, double floor = order_error_floor);

struct SweepResult {
  std::vector<SweepRow> rows;
  std::vector<ObservedOrder> orders;
  std::vector<SkippedRun> skipped;
  std::vector<Comparison> comparisons;
  int samples = 0;
  int unconverged_samples = 0;            // reference points dropped from the statistics (cut ones included)
  int cut_samples = 0;                    // of those, the points the budget cut short
  double reference_error_estimate = 0.0;  // largest error estimate of a converged reference point, radians
  double reference_seconds = 0.0;
  double mean_reference_steps = 0.0;
  double flow_time = 0.0;
  std::string device;
  bool cpu_device = false;  // llvmpipe: times are CPU times
};

// Runs the sweep; needs a current OpenGL context. `progress` gets one line per run.
// `progress` gets a line per run and per event; `advance`, if given, the runs done (ran or
// skipped) after each, out of options.planned_runs().
SweepResult run_sweep(const SweepOptions& options, const std::function<void(const std::string&)>& progress,
                      const std::function<void(int)>& advance = {});

std::vector<Comparison> compare_with_default(const std::vector<SweepRow>& rows,
                                             CurlMode baseline_mode = CurlMode::sampled);

// error_vs_runtime.csv: integrator, curl_mode, size, steps, time_ms, warp_err_rms, warp_err_max,
// cover_err_rms, cover_err_max.
std::string error_csv(const std::vector<SweepRow>& rows);
// stability.csv: the same runs with step, tolerance, stiffness, folding and sub-steps.
std::string stability_csv(const std::vector<SweepRow>& rows);
// The work-precision diagram: warp and cover rms error against time, log-log, as SVG.
std::string work_precision_svg(const std::vector<SweepRow>& rows, const std::string& title,
                               const std::string& time_label = "time of curl + warp passes (ms)");
// summary.md: the comparisons with the default, the reference, stiffness and folding.
std::string summary_markdown(const SweepResult& result, const SweepOptions& options);

}  // namespace nephele::studies
