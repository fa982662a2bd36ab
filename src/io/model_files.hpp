#pragma once
// Files of a cloud model's density volume (nephele model; docs/model.md, "Files"): the raw
// float32 volume, its JSON sidecar, an EXR slice atlas, the model as a cloud model file and,
// when nephele was built with OpenVDB, a .vdb grid. One output set: all or nothing.
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "core/image.hpp"
#include "core/json.hpp"
#include "model/cloud_model.hpp"

namespace nephele::io {

// Extinction per metre of density 1, as the sidecar and the .vdb record it.
constexpr double density_to_extinction_per_m = model::density_to_extinction_per_m;

// The slice atlas: slices z in a grid of `columns` tiles, slice z at tile (z % columns,
// z / columns); image row j of a tile is y = j. columns = ceil(sqrt(size)).
int atlas_columns(int size);
std::vector<float> model_atlas(const std::vector<float>& values, int size);

json::Value model_sidecar(const model::CloudModel& model, int size, const std::vector<float>& values,
                          const json::Value& run, bool with_vdb);

// Exposure of preview.png before the regional renderer's tone mapping (render::tone_map).
constexpr double preview_exposure = 4.0;

// Writes density.raw, density.json, density_atlas.exr, model.cloud.json (and density.vdb, and
// preview.png from the linear radiance `preview` unless it is null) into `directory` as one
// output set. Returns the names written.
std::vector<std::string> write_model_files(const std::filesystem::path& directory, const model::CloudModel& model,
                                           int size, const std::vector<float>& values, const json::Value& run,
                                           const core::ImageData* preview = nullptr);

// The .vdb of a volume (io/vdb_file.cpp): a FOG_VOLUME float grid named "density", background
// 0, only voxels above 0 active, voxel size extent / size metres, voxel (i, j, k) centred at
// ((i + 1/2) s, (j + 1/2) s, (k + 1/2) s) metres (z up). Empty when built without OpenVDB.
bool vdb_available();
std::string vdb_bytes(const model::CloudModel& model, int size, const std::vector<float>& values);
// The same kind of grids for any width x height x depth volume (nephele export --preset
// openvdb): one FOG_VOLUME float grid per name, values x fastest, voxel size `voxel_size`.
std::string vdb_grids_bytes(const std::vector<std::string>& names, const std::vector<std::vector<float>>& grids,
                            int width, int height, int depth, double voxel_size);

// What a .vdb holds, read back through OpenVDB (for tests and checks): the grid names, the
// 'density' grid's class, background, voxel size, world position of voxel (0, 0, 0) and its
// active voxels.
struct VdbVoxel {
  int x, y, z;
  float value;
};
struct VdbContents {
  std::vector<std::string> grids;
  bool fog_volume = false;
  float background = -1;
  double voxel_size = 0;
  std::array<double, 3> origin{};
  long active = 0;
  double extinction_per_m = 0;
  std::vector<VdbVoxel> values;
};
VdbContents read_vdb(const std::string& path);

}  // namespace nephele::io
