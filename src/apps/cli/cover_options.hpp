#pragma once
// The options shared by every command that makes a global cover (generate, bench).
#include "apps/cli/options.hpp"
#include "cover/cover_parameters.hpp"
#include "io/cover_files.hpp"
#include "params/table.hpp"

namespace nephele::cli {

// Registers the cover's numeric parameters that the table gives the command `use`
// (params::generate, params::bench_cover, params::report).
void add_cover_options(Options& options, cover::CoverParameters& p, unsigned use);
// Checks that span several options; throws UsageError.
void validate_cover_parameters(const cover::CoverParameters& p);

// The flow (--flow steady|moving) and the cover's time (--time) into `p`: throws UsageError
// naming the option for a word or a time it does not take.
void apply_flow(const std::string& flow, cover::CoverParameters& p);

// The images a cover's files hold and how (--files, --precision, --exr-compression of generate
// and assemble), bound to `options`; file_options() checks them after the parse.
class CoverFileOption {
 public:
  void add(Options& options);
  io::CoverFileOptions file_options() const;  // throws UsageError naming the option

 private:
  std::string files_{params::run::cover_files.default_text}, precision_{params::run::precision.default_text},
      compression_{params::run::exr_compression.default_text};
};

// How the warp is solved, --integrator, --curl-mode, --tolerance, --max-substeps (unless
// include_integrator is false), and --noise-offset (docs/numerics.md); with include_integrator
// also the flow, --flow and --time (cover/moving_flow.hpp). Values that Options
// cannot hold (names, a double) are parsed after Options::parse, by apply().
class WarpOptions {
 public:
  void add(Options& options, cover::CoverParameters& p, bool include_integrator = true);
  void apply(cover::CoverParameters& p) const;  // throws UsageError naming the option
  // The numeric parameters that add() binds (so add_cover_options leaves them out).
  static bool binds(const params::Parameter& p);

 private:
  std::string integrator_{params::cover::integrator.default_text};
  std::string curl_mode_{params::cover::curl_mode.default_text};
  std::string flow_{params::cover::flow.default_text};
  const Options* options_ = nullptr;  // what was given, for the checks of --flow moving
};

// The latitude profile, --profile earth|flat|FILE (read after Options::parse by apply(), which
// also refuses --month with --profile flat: a flat profile has nothing to shift).
class ProfileOption {
 public:
  void add(Options& options);
  void apply(cover::CoverParameters& p) const;  // throws core::InputError (exit 2)

 private:
  std::string value_{params::cover::profile.default_text};
};

// The land/ocean mask, --surface none|etopo5|FILE (read after Options::parse by apply()).
class SurfaceOption {
 public:
  void add(Options& options);
  // Throws core::InputError (exit 2); the default etopo5 without its package warns on stderr.
  void apply(cover::CoverParameters& p) const;

 private:
  std::string value_{params::cover::surface.default_text};
};

}  // namespace nephele::cli
