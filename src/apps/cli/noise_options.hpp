#pragma once
// The options of nephele noise, parsed and checked (exposed for the tests and the benchmark).
#include <string>
#include <vector>

#include "gpu/egl_context.hpp"
#include "noise/noise_spec.hpp"

namespace nephele::cli {

struct NoiseRequest {
  noise::TextureSpec spec;
  std::string preset;  // empty unless --preset
  std::string out;
  int png_bits = 8;
  bool verbose = false;
  bool quiet = false;       // no progress report
  bool size_given = false;  // --size rather than --width, --height, --depth
  bool stretch = false;     // map each channel's range onto [0, 1]
  std::string help;         // the --help text when *help_shown
};

// Parses and validates everything that needs no OpenGL context; throws UsageError naming the
// option and its allowed values.
NoiseRequest parse_noise_request(const std::vector<std::string>& arguments, bool* help_shown = nullptr);

// nephele bench noise.
int bench_noise(const std::vector<std::string>& arguments);

}  // namespace nephele::cli
