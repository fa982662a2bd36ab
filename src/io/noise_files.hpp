#pragma once
// Files of a noise texture: a slice atlas (PNG 8 or 16 bit, or float EXR) or a raw float32
// volume, each with a JSON sidecar (docs/noise.md, "Files").
#include <filesystem>
#include <string>
#include <vector>

#include "noise/noise_spec.hpp"
#include "noise/noise_texture.hpp"
#include "core/json.hpp"

namespace nephele::io {

enum class FileFormat { png, exr, raw };

// The format for an output name by its extension (.png, .exr, .raw); throws SpecError naming
// --out otherwise.
FileFormat format_for(const std::filesystem::path& out);

// The slice atlas: depth slices of width x height side by side, slice z at columns
// [z width, (z + 1) width); image row j is y = j. Channels stay interleaved.
std::vector<float> slice_atlas(const noise::Volume& volume);

struct ValueRange {
  float min = 0, max = 0;
};
std::vector<ValueRange> channel_ranges(const noise::Volume& volume);

// Maps each channel's range linearly onto [0, 1] (--stretch); returns the ranges before.
std::vector<ValueRange> stretch_channels(noise::Volume& volume);

// The sidecar: sizes, layout, channels with their parameters and value ranges, seed.
// `stretched_from`: the ranges before stretch_channels, or empty.
json::Value sidecar(const noise::TextureSpec& spec, const noise::Volume& volume, FileFormat format, int png_bits,
                    const std::string& data_file, const std::string& preset, const json::Value& extra,
                    const std::vector<ValueRange>& stretched_from = {});

// Writes `out` and its sidecar (same name, extension .json) as one output set of those two files
// in out's directory (OutputSet::Scope::files). Returns the sidecar's path.
std::filesystem::path write_noise_files(const std::filesystem::path& out, const noise::TextureSpec& spec,
                                        const noise::Volume& volume, int png_bits, const std::string& preset,
                                        const json::Value& extra, const std::vector<ValueRange>& stretched_from = {});

}  // namespace nephele::io
