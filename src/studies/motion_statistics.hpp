#pragma once
// The motion of a sequence of moving covers (generate --flow moving --sequence N): how far the
// clouds move between frames and whether that matches the flow's own winds, how fast the pattern
// renews, how steady the cloud fraction stays (docs/climate.md, "Motion"). nephele stats runs it
// on a directory with sequence.json.
#include <filesystem>
#include <string>
#include <vector>

#include "files/atomic_output.hpp"

namespace nephele::studies {

struct MotionStatistics {
  int frames = 0;
  double interval_hours = 0;
  int equirect_width = 0;
  // Per 10-degree band from 60 S to 60 N (centres -55 .. 55): the clouds' eastward speed from
  // the shift that best correlates each pair of consecutive frames along the band (m/s, mean over
  // pairs), and the flow's zonal-mean eastward wind at the band's centre (m/s).
  std::vector<double> band_centres_deg, cloud_speed_ms, flow_speed_ms;
  // Correlation of the cover between frames k apart (per texel, weighted by solid angle, 60 S to
  // 60 N, mean over start frames), k = 0 .. frames - 1, and the lag where it falls below 1/e.
  std::vector<double> correlation_by_lag;
  double decorrelation_hours = 0;  // 0 when it never falls below 1/e within the sequence
  // The same moving with the clouds: frame k + lag's rows shifted back by their band's measured
  // zonal displacement over lag intervals (a Lagrangian decorrelation in the zonal mean: how
  // fast the pattern itself renews, not how fast it passes a place).
  std::vector<double> comoving_correlation_by_lag;
  double comoving_decorrelation_hours = 0;
  double cloud_fraction_mean = 0, cloud_fraction_range = 0;  // over the frames (sequence.json)
};

// Reads sequence.json and each frame's cover.json and cover_equirect.exr; throws core::InputError
// naming the file for a missing or malformed one.
MotionStatistics motion_statistics(const std::filesystem::path& sequence_dir);

// motion.json and motion.svg (speeds by band, correlation by lag) into `outputs`, committed.
void write_motion(files::OutputSet& outputs, const MotionStatistics& motion);

}  // namespace nephele::studies
