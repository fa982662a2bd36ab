#include "noise/noise_spec.hpp"

#include <cmath>
#include <cstdint>
#include <numeric>
#include <sstream>

namespace nephele::noise {
namespace {

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// Layer numbers far above octave numbers keep layer keys apart from octave keys (as the cover).
std::uint32_t channel_seed(std::uint32_t seed, int channel, bool worley_part) {
  return glsl::noise_key(seed, 0x20000u + 2u * static_cast<std::uint32_t>(channel) + (worley_part ? 1u : 0u)).x;
}

// Cells along an axis of `size` texels for `cells` along the width: cells * size / width, in 64
// bits since both factors reach 2^16 and more (--cells to 2^20) and their int product overflowed.
// The quotient is at most `size` whenever cells <= width, which validate checks.
int cells_along(int cells, int size, int width) {
  return static_cast<int>(static_cast<std::int64_t>(cells) * size / width);
}

glsl::FbmParams fbm_params(const TextureSpec& spec, int cells, int octaves, const ChannelSpec& c, std::uint32_t seed) {
  return glsl::FbmParams{
      static_cast<float>(cells) / static_cast<float>(spec.width),
      octaves,
      c.lacunarity,
      c.gain,
      seed,
      glsl::ivec3(cells, cells_along(cells, spec.height, spec.width), cells_along(cells, spec.depth, spec.width))};
}

// Checks one fBm of a channel: whole cells on every axis at every octave, none narrower than
// a texel, and octave frequencies that stay equal to period / size (so that it tiles).
void validate_fbm(const TextureSpec& spec, const std::string& where, const std::string& cells_option, int cells,
                  int octaves, const ChannelSpec& c) {
  if (cells < 1 || cells > spec.width)
    throw SpecError(cells_option + ": " + where + " has " + std::to_string(cells) +
                    " cells along the width; allowed range 1 to " + std::to_string(spec.width) +
                    " (cells must be at least one texel wide)");
  const int g = std::gcd(spec.width, std::gcd(spec.height, spec.depth));
  const int step = spec.width / g;  // cells * height / width is whole for every axis iff step | cells
  if (cells % step != 0)
    throw SpecError(cells_option + ": " + where + " has " + std::to_string(cells) + " cells along the width " +
                    std::to_string(spec.width) + ", which gives " + number(double(cells) * spec.height / spec.width) +
                    " x " + number(double(cells) * spec.depth / spec.width) +
                    " cells along height and depth; the texture only tiles with whole cells on every axis: use a "
                    "multiple of " +
                    std::to_string(step));
  if (octaves < 1 || octaves > max_octaves)
    throw SpecError("--octaves: " + where + " has " + std::to_string(octaves) + " octaves; allowed range 1 to " +
                    std::to_string(max_octaves));
  // Step the octaves exactly as the shaders do (next_octave in tileable_noise.glsl).
  float frequency = static_cast<float>(cells) / static_cast<float>(spec.width);
  glsl::ivec3 period(cells, cells_along(cells, spec.height, spec.width), cells_along(cells, spec.depth, spec.width));
  double exact[3] = {double(period.x), double(period.y), double(period.z)};
  const char* axes[3] = {"width", "height", "depth"};
  for (int k = 1; k < octaves; ++k) {
    frequency *= c.lacunarity;
    period = glsl::ivec3(glsl::vec3(period) * c.lacunarity + 0.5f);
    for (int a = 0; a < 3; ++a) {
      exact[a] *= c.lacunarity;
      if (std::abs(exact[a] - period[a]) > 1e-4 * exact[a])
        throw SpecError("--lacunarity: " + number(c.lacunarity) + " gives " + where + " " + number(exact[a]) +
                        " cells along the " + axes[a] + " at octave " + std::to_string(k + 1) +
                        "; tiling needs whole numbers of cells at every octave (for example lacunarity 2 or 3)");
    }
    if (period.x > spec.width)
      throw SpecError("--octaves: " + where + " reaches " + std::to_string(period.x) + " cells along the width " +
                      std::to_string(spec.width) + " at octave " + std::to_string(k + 1) +
                      "; cells must be at least one texel wide: allowed range 1 to " + std::to_string(k) +
                      " octaves here, or fewer cells");
    if (std::abs(frequency * spec.width - period.x) > 1e-5f * period.x)
      throw SpecError("--lacunarity: " + number(c.lacunarity) + " does not keep the octave periods exact");
  }
}

}  // namespace

const char* type_name(NoiseType type) {
  switch (type) {
    case NoiseType::worley: return "worley";
    case NoiseType::inverted_worley: return "inverted-worley";
    case NoiseType::perlin: return "perlin";
    case NoiseType::perlin_worley: return "perlin-worley";
  }
  return "?";
}

NoiseType parse_type(const std::string& name) {
  for (NoiseType t : {NoiseType::worley, NoiseType::inverted_worley, NoiseType::perlin, NoiseType::perlin_worley})
    if (name == type_name(t)) return t;
  throw SpecError("--type: unknown noise type '" + name +
                  "' (allowed: worley, inverted-worley, perlin, perlin-worley)");
}

const char* channel_letter(int channel) {
  static const char* const letters[] = {"r", "g", "b", "a"};
  return channel >= 0 && channel < 4 ? letters[channel] : "?";
}

void validate(const TextureSpec& spec) {
  const std::pair<const char*, int> sizes[] = {
      {"--width", spec.width}, {"--height", spec.height}, {"--depth", spec.depth}};
  for (const auto& [option, size] : sizes)
    if (size < 1) throw SpecError(std::string(option) + ": " + std::to_string(size) + " is not a positive size");
  if (spec.channels.empty() || spec.channels.size() > 4)
    throw SpecError("--channels: " + std::to_string(spec.channels.size()) +
                    " channels; allowed 1 to 4 (r, rg, rgb, rgba)");
  for (size_t k = 0; k < spec.channels.size(); ++k) {
    const ChannelSpec& c = spec.channels[k];
    const std::string where = std::string("channel ") + channel_letter(static_cast<int>(k));
    const std::string cells_option = "--cells (or --" + std::string(channel_letter(static_cast<int>(k))) + " cells=N)";
    if (!(c.lacunarity >= 1.0f && c.lacunarity <= 8.0f))
      throw SpecError("--lacunarity: " + number(c.lacunarity) + " is out of range (allowed range 1 to 8)");
    if (!(c.gain >= 0.0f && c.gain <= 2.0f))
      throw SpecError("--gain: " + number(c.gain) + " is out of range (allowed range 0 to 2)");
    validate_fbm(spec, where, cells_option, c.cells, c.octaves, c);
    if (c.type == NoiseType::perlin_worley)
      validate_fbm(spec, where + " (its Worley part)",
                   "--" + std::string(channel_letter(static_cast<int>(k))) + " worley-cells=N", c.worley_cells,
                   c.worley_octaves, c);
  }
}

glsl::NoiseChannel channel_params(const TextureSpec& spec, int channel) {
  const ChannelSpec& c = spec.channels.at(static_cast<size_t>(channel));
  glsl::NoiseChannel p{};
  switch (c.type) {
    case NoiseType::worley: p.type = glsl::NOISE_WORLEY; break;
    case NoiseType::inverted_worley: p.type = glsl::NOISE_INVERTED_WORLEY; break;
    case NoiseType::perlin: p.type = glsl::NOISE_PERLIN; break;
    case NoiseType::perlin_worley: p.type = glsl::NOISE_PERLIN_WORLEY; break;
  }
  p.fbm = fbm_params(spec, c.cells, c.octaves, c, channel_seed(spec.seed, channel, false));
  p.worley = c.type == NoiseType::perlin_worley
                 ? fbm_params(spec, c.worley_cells, c.worley_octaves, c, channel_seed(spec.seed, channel, true))
                 : p.fbm;
  return p;
}

std::vector<std::string> preset_names() { return {"shape", "erosion"}; }

TextureSpec preset(const std::string& name, std::uint32_t seed) {
  TextureSpec spec;
  spec.seed = seed;
  auto worley_fbm = [](int cells) {
    ChannelSpec c;
    c.type = NoiseType::inverted_worley;
    c.cells = cells;
    c.octaves = 3;
    return c;
  };
  if (name == "shape") {
    // Schneider 2015 and Hillaire 2016: low-frequency Perlin-Worley for the base shape and
    // inverted Worley fBm at increasing frequencies for its detail, in one 128^3 RGBA texture.
    spec.width = spec.height = spec.depth = 128;
    ChannelSpec r;
    r.type = NoiseType::perlin_worley;
    r.cells = 4;
    r.octaves = 4;
    r.worley_cells = 4;
    r.worley_octaves = 3;
    spec.channels = {r, worley_fbm(4), worley_fbm(8), worley_fbm(16)};
  } else if (name == "erosion") {
    // Higher-frequency detail that erodes the shape's edges: 32^3 RGB.
    spec.width = spec.height = spec.depth = 32;
    spec.channels = {worley_fbm(2), worley_fbm(4), worley_fbm(8)};
  } else {
    throw SpecError("--preset: unknown preset '" + name + "' (allowed: shape, erosion)");
  }
  return spec;
}

ChannelSpec default_channel(const ChannelSpec& base, int k, int width) {
  ChannelSpec c = base;
  for (int j = 0; j < k && 2 * c.cells <= width; ++j) c.cells *= 2;
  for (int j = 0; j < k && 2 * c.worley_cells <= width; ++j) c.worley_cells *= 2;
  return c;
}

}  // namespace nephele::noise
