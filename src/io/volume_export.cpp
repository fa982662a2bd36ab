#include "io/volume_export.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include "core/error.hpp"
#include "core/input_file.hpp"
#include "core/json.hpp"
#include "io/export_presets.hpp"
#include "files/image_files.hpp"
#include "io/model_files.hpp"

namespace nephele::io {
namespace {

int positive_int(const json::Value& root, const std::string& key, const std::filesystem::path& path) {
  const json::Value* v = root.find(key);
  if (!v || !v->is_number() || v->as_number() < 1 || v->as_number() > 65536 ||
      v->as_number() != std::floor(v->as_number()))
    throw core::InputError("VOLUME", path.string() + ": " + key, "a whole number from 1 to 65536",
                           v ? "is not" : "is missing");
  return int(v->as_number());
}

}  // namespace

VolumeData read_volume(const std::filesystem::path& sidecar) {
  std::string text;
  try {
    text = core::read_input_file(sidecar.string());  // regular files of at most 16 MiB
  } catch (const core::InputFileError& e) {
    throw core::InputError("VOLUME", sidecar.string(), "the .json of a noise .raw or a model's density.json",
                           std::string("cannot be read: ") + e.what());
  }
  json::Value root;
  try {
    root = json::parse(text);
  } catch (const std::exception& e) {
    throw core::InputError("VOLUME", sidecar.string(), "a JSON sidecar", std::string("is not JSON: ") + e.what());
  }
  VolumeData v;
  std::string raw;
  const json::Value* program = root.find("program");
  v.source = program && program->is_string() ? program->as_string() : "";
  if (v.source == "nephele model") {
    v.width = v.height = v.depth = positive_int(root, "size", sidecar);
    v.channels = 1;
    v.channel_names = {"density"};
    const json::Value* size = root.find("voxel_size_m");
    if (!size || !size->is_number() || !(size->as_number() > 0))
      throw core::InputError("VOLUME", sidecar.string() + ": voxel_size_m", "a positive number of metres");
    v.voxel_size = size->as_number();
    const json::Value* file = root.find("raw");
    raw = file && file->is_string() ? file->as_string() : "";
  } else if (v.source == "nephele noise") {
    const json::Value* format = root.find("format");
    if (!format || !format->is_string() || format->as_string() != "raw-float32-little-endian")
      throw core::InputError("VOLUME", sidecar.string() + ": format",
                             "raw-float32-little-endian (nephele noise --out NAME.raw)");
    v.width = positive_int(root, "width", sidecar);
    v.height = positive_int(root, "height", sidecar);
    v.depth = positive_int(root, "depth", sidecar);
    const json::Value* channels = root.find("channels");
    const std::string names = channels && channels->is_string() ? channels->as_string() : "";
    if (names.empty() || names.size() > 4 || std::string("rgba").compare(0, names.size(), names) != 0)
      throw core::InputError("VOLUME", sidecar.string() + ": channels", "r, rg, rgb or rgba");
    v.channels = int(names.size());
    for (char c : names) v.channel_names.push_back(std::string(1, c));
    const json::Value* file = root.find("file");
    raw = file && file->is_string() ? file->as_string() : "";
  } else {
    throw core::InputError("VOLUME", sidecar.string() + ": program", "nephele noise (a .raw volume) or nephele model");
  }
  if (raw.empty() || raw.find('/') != std::string::npos)
    throw core::InputError("VOLUME", sidecar.string(), "a sidecar naming its raw file beside it", "names none");
  const std::filesystem::path raw_path = sidecar.parent_path() / raw;
  const std::size_t count = std::size_t(v.width) * v.height * v.depth * v.channels;
  // The sidecar's dimensions against the memory budget and the file's size before reading.
  if (4.0 * double(count) > double(core::input_memory_budget_bytes()))
    throw core::InputError("VOLUME", sidecar.string(),
                           "a volume within half the available memory (" +
                               std::to_string(core::input_memory_budget_bytes() >> 20) + " MiB)",
                           "declares " + std::to_string(count) + " float32 values");
  std::string bytes;
  try {
    const std::uint64_t size = core::regular_file_size(raw_path.string());
    if (size != 4 * count)
      throw core::InputError("VOLUME", raw_path.string(), std::to_string(4 * count) + " bytes of float32",
                             "has " + std::to_string(size));
    bytes = core::read_input_file(raw_path.string(), 4 * count);
  } catch (const core::InputFileError& e) {
    throw core::InputError("VOLUME", raw_path.string(), std::to_string(4 * count) + " bytes of float32",
                           std::string("cannot be read: ") + e.what());
  }
  if (bytes.size() != 4 * count)
    throw core::InputError("VOLUME", raw_path.string(), std::to_string(4 * count) + " bytes of float32",
                           "has " + std::to_string(bytes.size()));
  v.values.resize(count);
  std::memcpy(v.values.data(), bytes.data(), bytes.size());  // little-endian, as the sidecar says
  return v;
}

AtlasGrid atlas_grid(int width, int height, int depth) {
  const int most_columns = max_texture_edge / width;
  AtlasGrid g;
  g.columns = std::min({int(std::ceil(std::sqrt(double(depth)))), most_columns, depth});
  if (g.columns >= 1) g.rows = (depth + g.columns - 1) / g.columns;
  if (g.columns < 1 || long(g.rows) * height > max_texture_edge)
    throw core::InputError("VOLUME",
                           std::to_string(width) + " x " + std::to_string(height) + " x " + std::to_string(depth),
                           "a volume whose slices fit a 16384 x 16384 atlas");
  return g;
}

std::vector<std::string> write_volume_export(files::OutputSet& outputs, const std::string& preset,
                                             const VolumeData& v) {
  std::vector<std::string> names;
  const std::string size = std::to_string(v.width) + " x " + std::to_string(v.height) + " x " + std::to_string(v.depth);
  std::string readme = "nephele export, preset " + preset + ", of a volume from " + v.source + " (" + size + ", " +
                       std::to_string(v.channels) + " channel(s)). Details: docs/export.md.\n\n";
  if (preset == "atlas") {
    const AtlasGrid g = atlas_grid(v.width, v.height, v.depth);
    core::ImageData atlas{g.columns * v.width, g.rows * v.height, v.channels,
                          std::vector<float>(std::size_t(g.columns) * v.width * g.rows * v.height * v.channels, 0.0f)};
    const std::size_t row = std::size_t(v.width) * v.channels;
    for (int z = 0; z < v.depth; ++z)
      for (int y = 0; y < v.height; ++y)
        std::memcpy(atlas.pixels.data() + ((std::size_t(z / g.columns) * v.height + y) * atlas.width +
                                           std::size_t(z % g.columns) * v.width) *
                                              v.channels,
                    v.values.data() + (std::size_t(z) * v.height + y) * row, row * sizeof(float));
    static const char* const channel_names[4][4] = {{"Y"}, {"R", "G"}, {"R", "G", "B"}, {"R", "G", "B", "A"}};
    const std::vector<std::string> exr_channels(channel_names[v.channels - 1],
                                                channel_names[v.channels - 1] + v.channels);
    outputs.write("volume_atlas.exr",
                  files::encode_image(atlas, files::exr_encoding(exr_channels), "volume_atlas.exr"));
    files::ImageEncoding png = files::png_encoding(16);
    png.unassociated_alpha = true;  // a second or fourth channel is data, not alpha to divide by
    outputs.write("volume_atlas_16.png", files::encode_image(atlas, png, "volume_atlas_16.png"));
    names = {"volume_atlas.exr", "volume_atlas_16.png"};
    readme += "Files: volume_atlas.exr (float) and volume_atlas_16.png (16-bit, no gamma chunk), " +
              std::to_string(atlas.width) + " x " + std::to_string(atlas.height) + ": " + std::to_string(g.columns) +
              " columns x " + std::to_string(g.rows) + " rows of slices;\nslice z at column z % " +
              std::to_string(g.columns) + ", row z / " + std::to_string(g.columns) +
              " (left to right, top to bottom), image row 0 of a\nslice is y = 0; unused tiles are 0. At most " +
              std::to_string(max_texture_edge) +
              " pixels on each side (a single-row atlas of 160^3 would be\n25600 wide). Unity: Texture Shape 3D, "
              "Columns " +
              std::to_string(g.columns) + ", Rows " + std::to_string(g.rows) +
              "; Unreal: Create Volume Texture with\nSource 2D Tile Size " + std::to_string(v.width) + " x " +
              std::to_string(v.height) + ". sRGB off: the values are data.\n";
  } else if (preset == "openvdb") {
    if (!vdb_available())
      throw core::InputError("--preset", "openvdb", "a nephele built with OpenVDB (libopenvdb-dev)",
                             "is not available");
    std::vector<std::vector<float>> grids(std::size_t(v.channels));
    for (std::size_t i = 0; i < v.values.size(); ++i) grids[i % std::size_t(v.channels)].push_back(v.values[i]);
    std::vector<std::string> grid_names = v.channel_names;
    if (v.channels == 1) grid_names = {"density"};
    outputs.write("volume.vdb", vdb_grids_bytes(grid_names, grids, v.width, v.height, v.depth, v.voxel_size));
    names = {"volume.vdb"};
    std::string list;
    for (const auto& n : grid_names) list += (list.empty() ? "" : ", ") + n;
    readme += "File: volume.vdb, OpenVDB float grids (" + list +
              "), class FOG_VOLUME, background 0, voxels above 0\nactive; voxel (i, j, k) centred at voxel size x "
              "((i, j, k) + 1/2), voxel size " +
              std::to_string(v.voxel_size) + (v.source == "nephele model" ? " metres" : " (texel units)") +
              ", z up. Blender: Add > Volume > Import OpenVDB;\nthe Principled Volume reads `density` by default.\n";
  } else {
    throw core::InputError("--preset", preset, "atlas|openvdb for a volume");
  }
  outputs.write("README.txt", readme);
  names.push_back("README.txt");
  return names;
}

}  // namespace nephele::io
