#pragma once
// Everything that determines a global cloud cover. Defaults give an Earth-like cover.
#include <cstdint>

#include "cover/integrators.hpp"
#include "shader_math/shader_math.hpp"

namespace nephele::cover {

struct NoiseOctaves {
  float frequency;   // cells per unit length (the sphere has radius 1)
  int octaves;
  float lacunarity;
  float gain;
};

struct CoverParameters {
  int size = 512;                 // texels per cube face edge
  std::uint32_t seed = 1;
  int iterations = 50;            // K, warp steps
  float step = 0.006f;            // h, warp step size; flow time T = K h
  float coverage = 0.67f;         // target solid-angle fraction of cloudy sky
  NoiseOctaves potential{2.0f, 3, 2.0f, 0.3f};  // Worley fBm of the stream function
  float prevailing = 0.5f;        // strength of the zonal wind bands
  float mix_frequency = 2.5f;     // m(lat) = sin(a lat); sfsim uses 3
  float curl_strength = 0.5f;     // scale of the stream function, hence of the velocities
  NoiseOctaves density{3.0f, 6, 2.0f, 0.5f};    // Worley fBm of the cloud density
  // How the warp is solved (docs/numerics.md); the defaults are sfsim's scheme.
  cover::Integrator integrator = cover::Integrator::euler;
  cover::CurlMode curl_mode = cover::CurlMode::sampled;
  float tolerance = 1e-4f;        // adaptive: largest error estimate of a step, radians
  int max_substeps = 4096;        // adaptive: attempted steps per texel before it gives up
  // Shifts every noise layer by (d, d, d) sphere radii. Non-zero offsets make the lattices
  // periodic and are reduced modulo the period in double (noise_offset below), so that float
  // keeps its precision however far away the offset is.
  double noise_offset = 0.0;
};

// Independent seeds per noise layer, derived from the user's seed.
enum class NoiseLayer : std::uint32_t { potential_north = 1, potential_south = 2, density = 3 };
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
