#pragma once
// Everything that determines a global cloud cover. Defaults give an Earth-like cover.
#include <cstdint>

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
};

// Independent seeds per noise layer, derived from the user's seed.
enum class NoiseLayer : std::uint32_t { potential_north = 1, potential_south = 2, density = 3 };
std::uint32_t layer_seed(std::uint32_t seed, NoiseLayer layer);

glsl::FbmParams fbm_params(const NoiseOctaves& octaves, std::uint32_t seed, NoiseLayer layer);
glsl::CurlParams curl_params(const CoverParameters& p);
glsl::FbmParams density_params(const CoverParameters& p);

}  // namespace nephele::cover
