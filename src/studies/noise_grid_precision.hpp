#pragma once
// Error against run time of the noise grid (--noise-grid-nodes; docs/numerics.md, 8c): a cover
// traced from a warp grid takes the density's first octaves from the grid's cubic spline instead
// of evaluating them at every texel. Each run makes one whole frame of the moving flow with the
// grid carrying the octaves that a threshold of nodes per Worley cell selects, timed (the warp
// pass, which evaluates the grid's octaves, and the density pass), and compares its density and
// cover with the same frame evaluated at every texel (threshold 0), texel by texel; NoiseGridRow
// names the two rows that give the errors a scale.
#include <functional>
#include <string>
#include <vector>

#include "cover/cover_parameters.hpp"

namespace nephele::studies {

struct NoiseGridOptions {
  cover::CoverParameters base;                   // flow moving; its time is the frame's
  int size = 1024;                               // texels per face edge
  int warp_grid = 512;                           // the warp grid's nodes per face edge (below size)
  std::vector<float> nodes{32, 16, 8, 4, 2, 1};  // thresholds, nodes per cell (the reference, 0, is run first)
  int repeat = 1;                                // timed runs per configuration (the median is kept)

  static NoiseGridOptions full(const cover::CoverParameters& base);
  static NoiseGridOptions quick(const cover::CoverParameters& base);
};

struct NoiseGridRow {
  // The reference (the warp grid, every octave at every texel), the noise grid at a threshold, and
  // two scales for its errors: the trajectories from every texel instead of the warp grid (the warp
  // grid's own error, which the defaults accept) and the reference's frame ten minutes later (the
  // weather's change in that time, about a texel's motion at 1024 per face).
  enum class Kind { reference, noise_grid, every_texel, later };
  Kind kind = Kind::reference;
  float nodes = 0;         // --noise-grid-nodes (0: every octave at every texel)
  int octaves = 0;         // the density's octaves the grid carries
  double time_ms = 0;      // the warp and the density passes (wall clock between glFinish)
  double density_rms = 0;  // the density against the reference's, over every texel
  double density_max = 0;
  double cover_rms = 0;         // the cover (Y) against the reference's
  double flipped = 0;           // share of texels cloudy in one and clear in the other
  double reference_spread = 0;  // the reference density's standard deviation (the scale of the errors)
};

// Runs the reference and each threshold (needs a current GL context); `on_row` sees each row.
std::vector<NoiseGridRow> noise_grid_sweep(const NoiseGridOptions& options,
                                           const std::function<void(const NoiseGridRow&)>& on_row = {});

std::string noise_grid_csv(const std::vector<NoiseGridRow>& rows);
// Two log-log panels against run time: the density's rms and largest errors, and the cover's rms
// error with the share of texels whose cloudiness flips; the default threshold ringed.
std::string noise_grid_svg(const std::vector<NoiseGridRow>& rows, const std::string& title);
std::string noise_grid_markdown(const std::vector<NoiseGridRow>& rows, const NoiseGridOptions& options);
std::string noise_grid_line(const NoiseGridRow& row);
const char* noise_grid_kind_name(NoiseGridRow::Kind kind);

}  // namespace nephele::studies
