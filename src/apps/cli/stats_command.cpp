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
#include "studies/motion_statistics.hpp"

namespace nephele::cli {

int run_stats(const std::vector<std::string>& arguments) {
  std::string out;
  Options options("stats COVER_DIR",
                  "Reads a cover written by nephele generate (cover.json with the faces and/or the equirect\n"
                  "EXR) and prints and writes stats.json and stats.png: coverage by 2- and 10-degree latitude\n"
                  "band against the profile's targets, the zonal power spectrum (|lat| <= 60) and its slope,\n"
                  "the perimeter dimension of cloud objects, the histogram of cover values and the warp's\n"
                  "fold figures (docs/climate.md). On a sequence (generate --flow moving --sequence N) it measures\n"
                  "the motion instead: motion.json and motion.svg with the clouds' eastward speed by band against\n"
                  "the flow's wind, the correlation by lag and the cloud fraction across frames.",
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
  if (std::filesystem::exists(std::filesystem::path(cover_dir) / "sequence.json")) {
    // A sequence (generate --flow moving --sequence N): its motion (docs/climate.md, "Motion").
    const studies::MotionStatistics motion = studies::motion_statistics(cover_dir);
    files::OutputSet outputs(directory, files::OutputSet::Scope::directory);
    studies::write_motion(outputs, motion);
    std::cout << std::fixed << std::setprecision(2) << motion.frames << " frames " << motion.interval_hours
              << " h apart; eastward speed by 10-degree band (m/s), clouds against the flow's zonal-mean wind:\n";
    for (size_t b = 0; b < motion.band_centres_deg.size(); ++b)
      std::cout << "  " << std::setw(6) << motion.band_centres_deg[b] << ": clouds " << std::setw(7)
                << motion.cloud_speed_ms[b] << "  flow " << std::setw(7) << motion.flow_speed_ms[b] << "\n";
    std::cout << "correlation of the cover by lag:";
    for (size_t k = 0; k < motion.correlation_by_lag.size(); ++k)
      std::cout << " " << motion.interval_hours * double(k) << " h " << std::setprecision(3)
                << motion.correlation_by_lag[k] << std::setprecision(2)
                << (k + 1 < motion.correlation_by_lag.size() ? "," : "");
    std::cout << "\nmoving with the clouds:";
    for (size_t k = 0; k < motion.comoving_correlation_by_lag.size(); ++k)
      std::cout << " " << motion.interval_hours * double(k) << " h " << std::setprecision(3)
                << motion.comoving_correlation_by_lag[k] << std::setprecision(2)
                << (k + 1 < motion.comoving_correlation_by_lag.size() ? "," : "");
    std::cout << "\ndecorrelation (1/e) after " << motion.decorrelation_hours << " h at a fixed place, "
              << motion.comoving_decorrelation_hours << " h moving with the clouds; cloud fraction "
              << std::setprecision(4) << motion.cloud_fraction_mean << " (range " << motion.cloud_fraction_range
              << ")\nwrote " << (directory / "motion.json").string() << " and " << (directory / "motion.svg").string()
              << "\n";
    return exit_ok;
  }
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
              << stats.perimeter.max_area << " px)\n"
              << "cloud objects " << stats.objects.objects << ", size distribution N(>=a) ~ a^-"
              << stats.objects.size_exponent << " (" << std::setprecision(0) << stats.objects.fit_low_km2 << " to "
              << stats.objects.fit_high_km2 << " km2)" << std::setprecision(3) << ", largest system "
              << stats.objects.largest_share << " of the cloud, median elongation " << stats.objects.elongation_median
              << "\nmid-tones (cover 0.25-0.75) " << stats.objects.mid_tone_share << " of the cloud; edge cover "
              << stats.objects.edge_value << " against " << stats.objects.cloudy_mean << " inside (contrast "
              << (stats.objects.cloudy_mean > 0 ? stats.objects.edge_value / stats.objects.cloudy_mean : 0.0) << ")\n";
  else
    std::cout << "no equirect map: no spectrum and no perimeter dimension\n";
  if (stats.properties.present) {
    const studies::CloudPropertyStatistics& p = stats.properties;
    std::cout << "optical thickness: thin (tau < 3.6) " << p.thin << ", medium " << p.medium << ", thick (>= 23) "
              << p.thick << " of the cloud; ln tau " << p.log_tau_mean << " +- " << p.log_tau_sd
              << "\ncloud tops: low (< 3.2 km) " << p.low << ", middle " << p.middle << ", high (>= 6.5 km) " << p.high
              << ", mean " << p.top_mean_km << " km\n";
  }
  std::cout << "clear fraction " << stats.histogram[0] << "\nwrote " << (directory / "stats.json").string() << " and "
            << (directory / "stats.png").string() << "\n";
  return exit_ok;
}

}  // namespace nephele::cli
