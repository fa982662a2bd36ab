#include "cover/cover_parameters.hpp"

#include <cmath>

#include "cover/latitude_profile.hpp"

namespace nephele::cover {

std::uint32_t layer_seed(std::uint32_t seed, NoiseLayer layer) {
  // Layer numbers far above octave numbers keep layer keys apart from octave keys.
  return glsl::noise_key(seed, 0x10000u + static_cast<std::uint32_t>(layer)).x;
}

glsl::FbmParams fbm_params(const NoiseOctaves& o, std::uint32_t seed, NoiseLayer layer) {
  return glsl::FbmParams{o.frequency, o.octaves, o.lacunarity, o.gain, layer_seed(seed, layer), glsl::ivec3(0)};
}

glsl::CurlParams curl_params(const CoverParameters& p) {
  glsl::CurlParams c{fbm_params(p.potential, p.seed, NoiseLayer::potential_north),
                     fbm_params(p.potential, p.seed, NoiseLayer::potential_south),
                     p.prevailing,
                     p.mix_frequency,
                     p.curl_strength,
                     p.curl_smoothing,
                     p.storm_tracks,
                     p.zonal_cells,
                     static_cast<float>(storm_track_shift(p.month))};
  c.potential_north.period = c.potential_south.period = glsl::ivec3(offset_period_cells(p.potential, p.noise_offset));
  return c;
}

glsl::FbmParams density_params(const CoverParameters& p) {
  glsl::FbmParams f = fbm_params(p.density, p.seed, NoiseLayer::density);
  f.period = glsl::ivec3(offset_period_cells(p.density, p.noise_offset));
  return f;
}

int offset_period_cells(const NoiseOctaves& o, double offset) {
  return offset == 0.0 ? 0 : static_cast<int>(std::floor(2.0 * o.frequency)) + 2;
}

glsl::vec3 reduced_noise_offset(const NoiseOctaves& o, double offset) {
  const int cells = offset_period_cells(o, offset);
  if (cells == 0) return glsl::vec3(0.0f);
  // Every octave k has period cells lambda^k at frequency f lambda^k: the same period in radii
  // (exactly so for integer lacunarity), so one reduction serves all octaves.
  const double period = cells / static_cast<double>(o.frequency);
  return glsl::vec3(static_cast<float>(offset - period * std::floor(offset / period)));
}

glsl::vec3 potential_offset(const CoverParameters& p) { return reduced_noise_offset(p.potential, p.noise_offset); }
glsl::vec3 density_offset(const CoverParameters& p) { return reduced_noise_offset(p.density, p.noise_offset); }

}  // namespace nephele::cover
