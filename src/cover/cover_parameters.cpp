#include "cover/cover_parameters.hpp"

namespace nephele::cover {

std::uint32_t layer_seed(std::uint32_t seed, NoiseLayer layer) {
  // Layer numbers far above octave numbers keep layer keys apart from octave keys.
  return glsl::noise_key(seed, 0x10000u + static_cast<std::uint32_t>(layer)).x;
}

glsl::FbmParams fbm_params(const NoiseOctaves& o, std::uint32_t seed, NoiseLayer layer) {
  return glsl::FbmParams{o.frequency, o.octaves, o.lacunarity, o.gain, layer_seed(seed, layer),
                         glsl::ivec3(0)};
}

glsl::CurlParams curl_params(const CoverParameters& p) {
  return glsl::CurlParams{fbm_params(p.potential, p.seed, NoiseLayer::potential_north),
                          fbm_params(p.potential, p.seed, NoiseLayer::potential_south),
                          p.prevailing, p.mix_frequency, p.curl_strength};
}

glsl::FbmParams density_params(const CoverParameters& p) {
  return fbm_params(p.density, p.seed, NoiseLayer::density);
}

}  // namespace nephele::cover
