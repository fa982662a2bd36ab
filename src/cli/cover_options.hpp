#pragma once
// The options shared by every command that makes a global cover (generate, bench).
#include "cli/options.hpp"
#include "cover/cover_parameters.hpp"

namespace nephele::cli {

// Registers the cover's parameters (the size too, unless include_size is false).
void add_cover_options(Options& options, cover::CoverParameters& p, bool include_size = true);
// Checks that span several options; throws UsageError.
void validate_cover_parameters(const cover::CoverParameters& p);

}  // namespace nephele::cli
