// nephele report: error of each warp approximation against its run time (docs/numerics.md).
#include <filesystem>
#include <iostream>
#include <sstream>

#include "cli/commands.hpp"
#include "cli/cover_options.hpp"
#include "cli/device_limits.hpp"
#include "export/atomic_output.hpp"
#include "gl/egl_context.hpp"
#include "numerics/work_precision.hpp"

namespace nephele::cli {
namespace {

template <class T>
std::vector<T> parse_list(const std::string& option, const std::string& text, double min, double max, bool integers) {
  std::vector<T> values;
  std::stringstream stream(text);
  std::string item;
  const std::string allowed = "a comma-separated list of " + std::string(integers ? "integers" : "numbers") + " in " +
                              std::to_string(min) + ".." + std::to_string(max);
  while (std::getline(stream, item, ',')) {
    const double v = parse_number(option, item, min, max);
    if (integers && v != static_cast<double>(static_cast<long long>(v)))
      throw UsageError(option + ": '" + item + "' is not an integer (" + allowed + ")");
    values.push_back(static_cast<T>(v));
  }
  if (values.empty()) throw UsageError(option + ": give " + allowed);
  return values;
}

}  // namespace

int run_report(const std::vector<std::string>& arguments) {
  cover::CoverParameters parameters;
  std::string out = "report", sizes, steps, tolerances;
  bool quick = false;
  int samples = 0, repeat = 0;  // 0: the mode's default
  float budget_ms = 0.0f;
  Options options("report",
                  "Sweeps integrator x steps x curl mode x size, times the curl and warp passes and compares\n"
                  "the warped points with a reference solution at sample points. Writes error_vs_runtime.csv,\n"
                  "error_vs_runtime.svg (work-precision diagram), stability.csv and summary.md into --out.\n"
                  "The flow time T = iterations * step stays fixed; fixed-step schemes use h = T / steps.");
  options.add_string("--out", &out, "output directory (created if missing)");
  options.add_flag("--quick", &quick, "a short sweep (size 32, 10 and 50 steps, 96 sample points) for CI");
  options.add_string("--sizes", &sizes, "comma-separated cube face sizes (default 128,256,512; quick 32)");
  options.add_string("--steps", &steps, "comma-separated step counts of the fixed-step schemes (default 5,10,25,50,100,200)");
  options.add_string("--tolerances", &tolerances, "comma-separated tolerances of the adaptive scheme (default 1e-2..1e-6)");
  options.add_int("--samples", &samples, 0, 64, "sample grid m: 6 m^2 sample points (0: 20, quick 4)");
  options.add_int("--repeat", &repeat, 0, 20, "timed runs per configuration, the fastest counts (0: 3, quick 1)");
  options.add_float("--budget-ms", &budget_ms, 0.0, 1e7, "skip runs predicted to take longer (0: 20000, quick 2000)");
  add_cover_options(options, parameters, false);
  WarpOptions warp_options;
  warp_options.add(options, parameters, false);
  if (!options.parse(arguments)) {
    std::cout << options.help();
    return exit_ok;
  }
  warp_options.apply(parameters);
  validate_cover_parameters(parameters);
  numerics::SweepOptions sweep =
      quick ? numerics::SweepOptions::quick(parameters) : numerics::SweepOptions::full(parameters);
  if (!sizes.empty()) sweep.sizes = parse_list<int>("--sizes", sizes, 1, 16384, true);
  if (!steps.empty()) sweep.steps = parse_list<int>("--steps", steps, 1, 100000, true);
  if (!tolerances.empty()) sweep.tolerances = parse_list<float>("--tolerances", tolerances, 1e-7, 1.0, false);
  if (samples > 0) sweep.sample_grid = samples;
  if (repeat > 0) sweep.repeat = repeat;
  if (budget_ms > 0) sweep.budget_ms = budget_ms;
  const std::filesystem::path directory(out);
  if (std::filesystem::exists(directory) && !std::filesystem::is_directory(directory))
    throw UsageError("--out: '" + out + "' exists and is not a directory");

  gl::EglContext context;
  for (int size : sweep.sizes) check_cover_fits(context, size);
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error) throw UsageError("--out: cannot create directory '" + out + "': " + error.message());

  std::cout << "device: " << context.info().renderer << " (" << context.info().version << ")\n" << std::flush;
  numerics::SweepResult result =
      numerics::run_sweep(sweep, [](const std::string& line) { std::cout << line << "\n" << std::flush; });
  result.device = context.info().renderer + " (" + context.info().version + ")";

  output::OutputSet outputs(directory);
  output::write_text_file(outputs.temporary_for("error_vs_runtime.csv"), numerics::error_csv(result.rows));
  output::write_text_file(outputs.temporary_for("stability.csv"), numerics::stability_csv(result.rows));
  output::write_text_file(outputs.temporary_for("error_vs_runtime.svg"),
                          numerics::work_precision_svg(result.rows, "Warp error against run time, " + result.device,
                                                       result.cpu_device
                                                           ? "CPU time of the curl + warp passes, all threads (ms)"
                                                           : "time of the curl + warp passes (ms)"));
  const std::string summary = numerics::summary_markdown(result, sweep);
  output::write_text_file(outputs.temporary_for("summary.md"), summary);
  outputs.commit();
  for (const auto& c : result.comparisons)
    if (c.has_baseline)
      std::cout << "size " << c.size << ": at the default's error (" << c.baseline.warp_err_rms << " rad rms) "
                << (c.has_equal_error ? std::to_string(c.speedup) + "x faster" : std::string("no faster run"))
                << "; at its time (" << c.baseline.time_ms << " ms) "
                << (c.has_equal_time ? std::to_string(c.error_ratio) + "x less error" : std::string("no run"))
                << "\n";
  std::cout << "wrote " << (directory / "error_vs_runtime.csv").string() << ", error_vs_runtime.svg, stability.csv, "
            << "summary.md\n";
  return exit_ok;
}

}  // namespace nephele::cli
