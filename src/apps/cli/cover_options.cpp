#include "apps/cli/cover_options.hpp"

#include "cover/moving_flow.hpp"
#include "io/profile_files.hpp"
#include "io/surface_files.hpp"
#include "params/table.hpp"
#include "params/values.hpp"

#include <cmath>
#include <iostream>
#include <sstream>

namespace nephele::cli {

// Highest noise frequency (cells per unit radius) for which float positions keep ~1e-3 cell
// precision on the unit sphere.
static constexpr double max_octave_frequency = 4096.0;

void add_cover_options(Options& o, cover::CoverParameters& p, unsigned use) {
  cover::visit_numeric_parameters(p, [&](const params::Parameter& parameter, auto& field) {
    // The warp's own options (tolerance, ...) are bound by WarpOptions.
    if (parameter.used_by(use) && !WarpOptions::binds(parameter)) o.bind(parameter, &field);
  });
}

void validate_cover_parameters(const cover::CoverParameters& p) {
  auto check = [](const char* prefix, const cover::NoiseOctaves& n) {
    if (n.octaves <= 0) return;
    const double highest = n.frequency * std::pow(static_cast<double>(n.lacunarity), n.octaves - 1);
    if (highest > max_octave_frequency) {
      std::ostringstream message;
      message << "--" << prefix << "-frequency, --" << prefix << "-lacunarity and --" << prefix
              << "-octaves: the highest octave has " << highest << " cells per unit radius; allowed at most "
              << max_octave_frequency << " (frequency * lacunarity^(octaves - 1))";
      throw UsageError(message.str());
    }
  };
  check("curl", p.potential);
  check("density", p.density);
}

void apply_flow(const std::string& flow, cover::CoverParameters& p) {
  const auto kind = cover::parse_flow(flow);
  if (!kind) throw UsageError(params::cover::flow.option(), flow, params::cover::flow.range_text());
  p.flow = *kind;
  try {
    cover::hours_since_epoch(p.time);
  } catch (const std::invalid_argument&) {
    throw UsageError(params::cover::time.option(), p.time, std::string(params::cover::time.allowed));
  }
}

bool WarpOptions::binds(const params::Parameter& p) {
  namespace c = params::cover;
  return &p == &c::tolerance || &p == &c::max_substeps || &p == &c::noise_offset;
}

void WarpOptions::add(Options& o, cover::CoverParameters& p, bool include_integrator) {
  namespace c = params::cover;
  if (include_integrator) {
    o.bind(c::integrator, &integrator_);
    o.bind(c::curl_mode, &curl_mode_);
    o.bind(c::tolerance, &p.tolerance);
    o.bind(c::max_substeps, &p.max_substeps);
    if (c::flow.used_by(o.use())) {
      o.bind(c::flow, &flow_);
      o.bind(c::time, &p.time);
    }
    options_ = &o;
  }
  o.bind(c::noise_offset, &p.noise_offset);
}

void WarpOptions::apply(cover::CoverParameters& p) const {
  const auto integrator = cover::parse_integrator(integrator_);
  if (!integrator)
    throw UsageError(params::cover::integrator.option(), integrator_, params::cover::integrator.range_text());
  const auto mode = cover::parse_curl_mode(curl_mode_);
  if (!mode) throw UsageError(params::cover::curl_mode.option(), curl_mode_, params::cover::curl_mode.range_text());
  p.integrator = *integrator;
  p.curl_mode = *mode;
  apply_flow(flow_, p);
  if (p.flow == cover::Flow::moving && options_ != nullptr) {
    // The moving flow integrates with RK4 on the spline grids of its time nodes or on the
    // procedural flow: an option that asks for another way is refused, not ignored.
    if (p.integrator != cover::Integrator::rk4)
      throw UsageError(params::cover::integrator.option(), integrator_, "rk4 with --flow moving");
    if (p.curl_mode == cover::CurlMode::sampled)
      throw UsageError(params::cover::curl_mode.option(), curl_mode_, "spline, procedural with --flow moving");
    for (const params::Parameter* given : {&params::cover::tolerance, &params::cover::max_substeps})
      if (options_->given(*given)) throw UsageError(given->option() + ": only with --integrator adaptive");
  }
  if (p.flow == cover::Flow::steady && options_ != nullptr) {
    for (const params::Parameter* given : {&params::cover::time, &params::cover::vortex_lifetime, &params::cover::loop})
      if (options_->given(*given))
        throw UsageError(given->option() + ": only with --flow moving (a steady cover has no time)");
  }
}

void ProfileOption::add(Options& o) { o.bind(params::cover::profile, &value_); }

void ProfileOption::apply(cover::CoverParameters& p) const {
  p.profile = io::profile_from_option(value_);
  if (p.profile.kind == cover::LatitudeProfile::Kind::flat && p.month != 0)
    throw UsageError(params::cover::month.option(), std::to_string(p.month), "0 with --profile flat",
                     "has no profile to shift");
}

void SurfaceOption::add(Options& o) { o.bind(params::cover::surface, &value_); }

void SurfaceOption::apply(cover::CoverParameters& p) const {
  std::string warning;
  p.surface = io::surface_from_option(value_, &warning);
  if (!warning.empty()) std::cerr << "warning: " << warning << "\n";
}

void CoverFileOption::add(Options& options) {
  options.bind(params::run::cover_files, &files_);
  options.bind(params::run::precision, &precision_);
  options.bind(params::run::exr_compression, &compression_);
}

io::CoverFileOptions CoverFileOption::file_options() const {
  io::CoverFileOptions file_options;
  io::parse_cover_files(files_, file_options);
  params::check_word(params::run::precision, precision_, params::run::precision.option());
  params::check_word(params::run::exr_compression, compression_, params::run::exr_compression.option());
  file_options.half = precision_ == "half";
  file_options.compression = compression_;
  return file_options;
}

}  // namespace nephele::cli
