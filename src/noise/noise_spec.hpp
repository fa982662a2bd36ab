#pragma once
// What a tileable noise texture holds: its size, up to four channels with their fBm, the
// presets, and the checks that make the result tile exactly.
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "shader_math/shader_math.hpp"

namespace nephele::noise {

enum class NoiseType { worley, inverted_worley, perlin, perlin_worley };

// One channel: a noise type with its fBm. Cells count along the texture's width (x); the
// other axes get cells * height / width and cells * depth / width, so cells stay cubes.
struct ChannelSpec {
  NoiseType type = NoiseType::worley;
  int cells = 4;            // cells per period along x at octave 0
  int octaves = 1;          // 1..max_octaves
  float lacunarity = 2.0f;  // frequency ratio between octaves (must keep whole cell counts)
  float gain = 0.5f;        // amplitude ratio between octaves (persistence)
  // The inverted Worley fBm of perlin-worley (same lacunarity and gain).
  int worley_cells = 4;
  int worley_octaves = 3;
};

struct TextureSpec {
  int width = 32, height = 32, depth = 32;
  std::uint32_t seed = 1;
  std::vector<ChannelSpec> channels = std::vector<ChannelSpec>(1);  // 1..4: r, g, b, a
};

constexpr int max_octaves = 8;

// A texture specification that cannot tile or cannot be made; the message names the option
// and the allowed values.
class SpecError : public core::InputError {
 public:
  using core::InputError::InputError;
};

const char* type_name(NoiseType type);
NoiseType parse_type(const std::string& name);  // throws SpecError naming --type
const char* channel_letter(int channel);        // "r", "g", "b", "a"

// Sizes, cell counts and octaves; not device limits (those need a context).
void validate(const TextureSpec& spec);

// The shader parameters of a channel: frequency in cells per texel, period in cells per axis,
// per-channel seeds derived from spec.seed.
glsl::NoiseChannel channel_params(const TextureSpec& spec, int channel);

// "shape": 128^3 RGBA (R Perlin-Worley, G B A inverted Worley fBm at 4, 8, 16 cells);
// "erosion": 32^3 RGB inverted Worley fBm at 2, 4, 8 cells (docs/noise.md).
TextureSpec preset(const std::string& name, std::uint32_t seed);

// The default settings of channel k (0 = r .. 3 = a) from the settings of channel r: one more
// detail level per channel, cells (and perlin-worley's Worley cells) doubled k times, stopping
// at one cell per texel so that every width works with the defaults (docs/noise.md).
ChannelSpec default_channel(const ChannelSpec& base, int k, int width);
std::vector<std::string> preset_names();

}  // namespace nephele::noise
