#pragma once
// Everything that determines a global cloud cover. Defaults give an Earth-like cover.
#include <cstdint>
#include <memory>

#include "cover/flow_kind.hpp"
#include "cover/integrators.hpp"
#include "cover/latitude_profile.hpp"
#include "cover/surface_bias.hpp"
#include "params/table.hpp"
#include "shader_math/shader_math.hpp"

namespace nephele::cover {

struct NoiseOctaves {
  float frequency;  // cells per unit length (the sphere has radius 1)
  int octaves;
  float lacunarity;
  float gain;
};

// Defaults come from the parameter table (src/params/table.hpp).
struct CoverParameters {
  int size = params::cover::size.default_int();  // texels per cube face edge
  std::uint32_t seed = params::cover::seed.default_uint32();
  int iterations = params::cover::iterations.default_int();  // K, warp steps
  float step = params::cover::step.default_float();          // h, warp step size; flow time T = K h
  float coverage = params::cover::coverage.default_float();  // target solid-angle fraction of cloudy sky
  // Target fraction by latitude, rescaled to `coverage` (docs/climate.md); flat: one threshold.
  LatitudeProfile profile = earth_profile();
  int month = params::cover::month.default_int();  // seasonal shift; 0 annual mean
  NoiseOctaves potential{params::cover::curl_frequency.default_float(), params::cover::curl_octaves.default_int(),
                         params::cover::curl_lacunarity.default_float(),
                         params::cover::curl_gain.default_float()};      // Worley fBm of the stream function
  float prevailing = params::cover::prevailing.default_float();          // strength of the zonal wind bands
  float mix_frequency = params::cover::mix_frequency.default_float();    // m(lat) = sin(a lat); sfsim uses 3
  float curl_strength = params::cover::curl_strength.default_float();    // scale of the stream function
  float curl_smoothing = params::cover::curl_smoothing.default_float();  // lambda of the smooth potential
  int zonal_cells = params::cover::zonal_cells.default_int();            // zonal wind cells per hemisphere
  float storm_tracks = params::cover::storm_tracks.default_float();      // vortex focus on the storm tracks
  float cyclone_cloudiness =
      params::cover::cyclone_cloudiness.default_float();  // weight of the cyclonic depth in the density
  // The weather systems (weather_systems.hpp) and the remap's softness (docs/climate.md).
  int cyclones = params::cover::cyclones.default_int();                  // per hemisphere
  float itcz = params::cover::itcz.default_float();                      // strength of the ITCZ's clusters
  float spcz = params::cover::spcz.default_float();                      // strength of the SPCZ's (with a mask)
  float trade_cumulus = params::cover::trade_cumulus.default_float();    // strength of the cumulus fields
  float cirrus = params::cover::cirrus.default_float();                  // strength of the cirrus streaks
  float shallow_trades = params::cover::shallow_trades.default_float();  // the trades' unorganised cloud thin
  float stratocumulus_cells = params::cover::stratocumulus_cells.default_float();  // the decks' and cold air's cells
  float cloud_streets = params::cover::cloud_streets.default_float();              // the cold air's streets
  float cover_softness = params::cover::cover_softness.default_float();            // density scale of the remap
  float tau_median = params::cover::tau_median.default_float();                    // the cloud's optical thickness,
  float tau_spread = params::cover::tau_spread.default_float();                    // log-normal (cloud_properties.glsl)
  NoiseOctaves density{params::cover::density_frequency.default_float(), params::cover::density_octaves.default_int(),
                       params::cover::density_lacunarity.default_float(),
                       params::cover::density_gain.default_float()};  // Worley fBm of the cloud density
  // Land/ocean mask (--surface; null: none) and its weight k in density (1 + k b).
  std::shared_ptr<const SurfaceMask> surface;
  float surface_weight = params::cover::surface_weight.default_float();
  // How the warp is solved (docs/numerics.md): RK4 on a C2 cubic B-spline of the curl of the
  // smooth potential, smooth enough for order 4 (sfsim: Euler, sampled, 50 steps).
  cover::Integrator integrator = *cover::parse_integrator(std::string(params::cover::integrator.default_text));
  cover::CurlMode curl_mode = *cover::parse_curl_mode(std::string(params::cover::curl_mode.default_text));
  float tolerance = params::cover::tolerance.default_float();    // adaptive: largest error estimate of a step, radians
  int max_substeps = params::cover::max_substeps.default_int();  // adaptive: attempted steps per texel at most
  int curl_size = params::cover::curl_size.default_int();        // spline: curl grid nodes per face edge
  int warp_grid = params::cover::warp_grid.default_int();        // moving: trajectories' grid (0: every texel)
  // The warp grid's nodes per Worley cell from which the density's octaves come from its spline.
  float noise_grid_nodes = params::cover::noise_grid_nodes.default_float();
  // Shifts every noise layer by (d, d, d) sphere radii. Non-zero offsets make the lattices
  // periodic and are reduced modulo the period in double (noise_offset below), so that float
  // keeps its precision however far away the offset is.
  double noise_offset = params::cover::noise_offset.default_number;
  // The moving flow (cover/moving_flow.hpp): steady, or vortices and clouds that evolve in time.
  Flow flow = *parse_flow(std::string(params::cover::flow.default_text));
  std::string time{params::cover::time.default_text};                      // ISO 8601 UTC: the moment of the cover
  float vortex_lifetime = params::cover::vortex_lifetime.default_float();  // hours
  float loop_hours = params::cover::loop.default_float();                  // 0: no loop
};

// The numeric fields of a cover with their declarations in the parameter table, in the order
// of cover.json: the one place that ties the table to the fields. The command line binds
// options through it and the sidecar writes its keys through it. (The integrator and the curl
// mode are names, handled beside it.) `P` is CoverParameters, const or not.
template <class P, class Visit>
void visit_numeric_parameters(P& p, Visit&& visit) {
  namespace c = params::cover;
  visit(c::size, p.size);
  visit(c::seed, p.seed);
  visit(c::iterations, p.iterations);
  visit(c::step, p.step);
  visit(c::tolerance, p.tolerance);
  visit(c::max_substeps, p.max_substeps);
  visit(c::curl_size, p.curl_size);
  visit(c::warp_grid, p.warp_grid);
  visit(c::noise_grid_nodes, p.noise_grid_nodes);
  visit(c::coverage, p.coverage);
  visit(c::month, p.month);
  visit(c::noise_offset, p.noise_offset);
  visit(c::curl_frequency, p.potential.frequency);
  visit(c::curl_octaves, p.potential.octaves);
  visit(c::curl_lacunarity, p.potential.lacunarity);
  visit(c::curl_gain, p.potential.gain);
  visit(c::prevailing, p.prevailing);
  visit(c::mix_frequency, p.mix_frequency);
  visit(c::curl_strength, p.curl_strength);
  visit(c::curl_smoothing, p.curl_smoothing);
  visit(c::zonal_cells, p.zonal_cells);
  visit(c::storm_tracks, p.storm_tracks);
  visit(c::cyclone_cloudiness, p.cyclone_cloudiness);
  visit(c::cyclones, p.cyclones);
  visit(c::itcz, p.itcz);
  visit(c::spcz, p.spcz);
  visit(c::trade_cumulus, p.trade_cumulus);
  visit(c::cirrus, p.cirrus);
  visit(c::shallow_trades, p.shallow_trades);
  visit(c::stratocumulus_cells, p.stratocumulus_cells);
  visit(c::cloud_streets, p.cloud_streets);
  visit(c::cover_softness, p.cover_softness);
  visit(c::tau_median, p.tau_median);
  visit(c::tau_spread, p.tau_spread);
  visit(c::density_frequency, p.density.frequency);
  visit(c::density_octaves, p.density.octaves);
  visit(c::density_lacunarity, p.density.lacunarity);
  visit(c::density_gain, p.density.gain);
  visit(c::surface_weight, p.surface_weight);
  visit(c::vortex_lifetime, p.vortex_lifetime);
  visit(c::loop, p.loop_hours);
}

// Independent seeds per noise layer, derived from the user's seed.
enum class NoiseLayer : std::uint32_t { potential_north = 1, potential_south = 2, density = 3, weather_systems = 4 };
std::uint32_t layer_seed(std::uint32_t seed, NoiseLayer layer);

glsl::FbmParams fbm_params(const NoiseOctaves& octaves, std::uint32_t seed, NoiseLayer layer);
glsl::CurlParams curl_params(const CoverParameters& p);
glsl::FbmParams density_params(const CoverParameters& p);

// Cells per lattice period at octave 0 for a noise offset: floor(2 f) + 2, so that the period
// in sphere radii, (floor(2 f) + 2) / f, exceeds the sphere's diameter 2 and no two points of
// the sphere see the same noise. 0 (not periodic) when the offset is 0.
int offset_period_cells(const NoiseOctaves& octaves, double offset);
// The offset reduced modulo that period, in double, per axis: the uniform the passes add.
glsl::vec3 reduced_noise_offset(const NoiseOctaves& octaves, double offset);
glsl::vec3 potential_offset(const CoverParameters& p);
glsl::vec3 density_offset(const CoverParameters& p);

}  // namespace nephele::cover
