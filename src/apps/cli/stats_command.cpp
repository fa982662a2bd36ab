// nephele stats COVER_DIR: the statistics of a cover (src/studies/cover_statistics.hpp).
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>

#include "apps/cli/commands.hpp"
#include "apps/cli/options.hpp"
#include "files/atomic_output.hpp"
#include "params/table.hpp"
#include "studies/cover_statistics.hpp"

namespace nephele::cli {

int run_stats(const std::vector<std::string>& arguments) {
  std::string out;
  Options options("stats COVER_DIR",
                  "Reads a cover written by nephele generate (cover.json with the faces and/or the equirect\n"
                  "EXR) and prints and writes stats.json and stats.png: coverage by 2- and 10-degree latitude\n"
                  "band against the profile's targets, the zonal power spectrum (|lat| <= 60) and its slope,\n"
                  "the perimeter dimension of cloud objects, the histogram of cover values and the warp's\n"
                  "fold figures (docs/climate.md).",
                  params::stats);
  options.bind(params::run::stats_out, &out);
  std::vector<std::string> rest = arguments;
  const std::string cover_dir = take_leading_operand(rest);
  if (!options.parse(rest)) {
    std::cout << options.help();
    return exit_ok;
  }
  if (cover_dir.empty()) throw UsageError("COVER_DIR", "", "a directory written by nephele generate", "is missing");
  const std::filesystem::path directory =
      out.empty() ? std::filesystem::path(cover_dir) / "stats" : std::filesystem::path(out);
  files::check_output_directory(directory, "--out");
  const studies::CoverStatistics stats = studies::cover_statistics(cover_dir);
  files::OutputSet outputs(directory, files::OutputSet::Scope::directory);
  studies::write_statistics(outputs, stats);

  std::cout << std::fixed << std::setprecision(3) << "coverage by 10-degree band (" << stats.coverage_source
            << "), south to north:\n";
  for (size_t b = 0; b < stats.coverage_10deg.size(); ++b) {
    std::cout << "  " << std::setw(4) << -90 + 10 * static_cast<int>(b) << " to " << std::setw(3)
              << -80 + 10 * static_cast<int>(b) << ": " << stats.coverage_10deg[b];
    if (!stats.target_10deg.empty())
      std::cout << "  target " << stats.target_10deg[b] << "  error " << std::showpos
                << stats.coverage_10deg[b] - stats.target_10deg[b] << std::noshowpos;
    std::cout << "\n";
  }
  if (!stats.spectrum.empty())
    std::cout << "zonal spectrum slope " << stats.spectrum_fit.slope << " (k " << stats.fit_k_low << " to "
              << stats.fit_k_high << ")\nperimeter dimension D " << stats.perimeter.dimension << " ("
              << stats.perimeter.objects << " objects of " << stats.perimeter.min_area << " to "
              << stats.perimeter.max_area << " px)\n";
  else
    std::cout << "no equirect map: no spectrum and no perimeter dimension\n";
  std::cout << "clear fraction " << stats.histogram[0] << "\nwrote " << (directory / "stats.json").string() << " and "
            << (directory / "stats.png").string() << "\n";
  return exit_ok;
}

}  // namespace nephele::cli
