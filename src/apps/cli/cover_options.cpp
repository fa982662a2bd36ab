#include "apps/cli/cover_options.hpp"

#include <cmath>
#include <sstream>

namespace nephele::cli {

// Highest noise frequency (cells per unit radius) for which float positions keep ~1e-3 cell
// precision on the unit sphere.
static constexpr double max_octave_frequency = 4096.0;

void add_cover_options(Options& o, cover::CoverParameters& p, bool include_size) {
  if (include_size) o.add_int("--size", &p.size, 1, 16384, "texels per cube face edge");
  o.add_uint32("--seed", &p.seed, "seed of all noise layers");
  o.add_int("--iterations", &p.iterations, 0, 100000, "warp steps K");
  o.add_float("--step", &p.step, 0.0, 10.0, "warp step size h (flow time T = K h)");
  o.add_float("--coverage", &p.coverage, 0.0, 1.0, "cloudy fraction of the sphere, by solid angle");
  o.add_float("--curl-frequency", &p.potential.frequency, 0.01, 4096.0,
              "Worley cells per unit radius of the flow's potential");
  o.add_int("--curl-octaves", &p.potential.octaves, 0, 16, "octaves of the potential");
  o.add_float("--curl-lacunarity", &p.potential.lacunarity, 1.0, 8.0, "frequency ratio between octaves");
  o.add_float("--curl-gain", &p.potential.gain, 0.0, 1.0, "amplitude ratio between octaves");
  o.add_float("--prevailing", &p.prevailing, -100.0, 100.0,
              "strength of the zonal wind bands (> 0: easterly trade winds)");
  o.add_float("--mix-frequency", &p.mix_frequency, 0.0, 10.0,
              "a in the hemisphere mix m = sin(a lat); 2.5 original, 3 sfsim");
  o.add_float("--curl-strength", &p.curl_strength, 0.0, 100.0,
              "scale of the flow's potential (velocity = strength * n x grad phi)");
  o.add_float("--density-frequency", &p.density.frequency, 0.01, 4096.0,
              "Worley cells per unit radius of the cloud density");
  o.add_int("--density-octaves", &p.density.octaves, 0, 16, "octaves of the cloud density");
  o.add_float("--density-lacunarity", &p.density.lacunarity, 1.0, 8.0, "frequency ratio between octaves");
  o.add_float("--density-gain", &p.density.gain, 0.0, 1.0, "amplitude ratio between octaves");
}

void validate_cover_parameters(const cover::CoverParameters& p) {
  auto check = [](const char* prefix, const cover::NoiseOctaves& n) {
    if (n.octaves <= 0) return;
    const double highest = n.frequency * std::pow(static_cast<double>(n.lacunarity), n.octaves - 1);
    if (highest > max_octave_frequency) {
      std::ostringstream message;
      message << "--" << prefix << "-frequency, --" << prefix << "-lacunarity and --" << prefix
              << "-octaves: the highest octave has " << highest
              << " cells per unit radius; allowed at most " << max_octave_frequency
              << " (frequency * lacunarity^(octaves - 1))";
      throw UsageError(message.str());
    }
  };
  check("curl", p.potential);
  check("density", p.density);
}

void WarpOptions::add(Options& o, cover::CoverParameters& p, bool include_integrator) {
  if (include_integrator) {
    o.add_string("--integrator", &integrator_, "warp stepping rule: euler, heun, rk4, geodesic or adaptive");
    o.add_string("--curl-mode", &curl_mode_,
                 "velocity of the warp: sampled (bilinear from the curl cube map) or procedural (exact point)");
    o.add_float("--tolerance", &p.tolerance, 1e-7, 1.0,
                "adaptive: largest error estimate per step, radians (the flow time is iterations * step)");
    o.add_int("--max-substeps", &p.max_substeps, 1, 1000000, "adaptive: attempted steps per texel at most");
  }
  o.add_string("--noise-offset", &noise_offset_,
               "shift of every noise layer by (d, d, d) sphere radii, -1e9 to 1e9; precision is kept by a periodic lattice");
}

void WarpOptions::apply(cover::CoverParameters& p) const {
  const auto integrator = cover::parse_integrator(integrator_);
  if (!integrator)
    throw UsageError("--integrator: '" + integrator_ + "' is not allowed (allowed: euler, heun, rk4, geodesic, adaptive)");
  const auto mode = cover::parse_curl_mode(curl_mode_);
  if (!mode) throw UsageError("--curl-mode: '" + curl_mode_ + "' is not allowed (allowed: sampled, procedural)");
  p.integrator = *integrator;
  p.curl_mode = *mode;
  p.noise_offset = parse_number("--noise-offset", noise_offset_, -1e9, 1e9);
}

}  // namespace nephele::cli
