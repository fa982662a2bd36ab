#pragma once
// nephele export for volumes: a noise volume (`nephele noise --out NAME.raw`) or a model's
// density (`nephele model`) turned into a slice atlas in rows and columns or an OpenVDB file
// (docs/export.md, "atlas" and "openvdb").
#include <filesystem>
#include <string>
#include <vector>

#include "files/atomic_output.hpp"

namespace nephele::io {

struct VolumeData {
  int width = 0, height = 0, depth = 0, channels = 0;
  std::vector<std::string> channel_names;  // "r", "g", ... or "density"
  std::vector<float> values;               // channels interleaved, x fastest, then y, then z
  double voxel_size = 1;                   // metres for a model; 1 (texels) for noise
  std::string source;                      // "nephele noise" or "nephele model"
};

// Reads the sidecar of a raw volume (a noise NAME.json with format raw-float32-little-endian,
// or a model's density.json) and its raw file. Throws core::InputError naming VOLUME, the file
// and the field when the sidecar, its sizes or the raw file's length are wrong.
VolumeData read_volume(const std::filesystem::path& sidecar);

// Columns and rows of the slice atlas: columns = ceil(sqrt(depth)) (a near-square atlas), fewer
// when columns * width would exceed max_texture_edge. Throws core::InputError when the rows
// then exceed it too.
struct AtlasGrid {
  int columns = 0, rows = 0;
};
AtlasGrid atlas_grid(int width, int height, int depth);

// Writes the preset's files ("atlas" or "openvdb") and README.txt into `outputs`.
std::vector<std::string> write_volume_export(files::OutputSet& outputs, const std::string& preset,
                                             const VolumeData& volume);

}  // namespace nephele::io
