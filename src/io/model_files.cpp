#include "io/cloud_model_files.hpp"
#include "io/model_files.hpp"

#include <algorithm>
#include <cmath>

#include "files/atomic_output.hpp"
#include "files/image_files.hpp"
#include "render/cloud_renderer.hpp"
#include "nephele/version.hpp"

namespace nephele::io {

int atlas_columns(int size) { return int(std::ceil(std::sqrt(double(size)))); }

std::vector<float> model_atlas(const std::vector<float>& values, int size) {
  const int columns = atlas_columns(size), rows = (size + columns - 1) / columns;
  const size_t width = size_t(columns) * size;
  std::vector<float> atlas(width * size_t(rows) * size, 0.0f);
  for (int z = 0; z < size; ++z)
    for (int y = 0; y < size; ++y) {
      const float* src = values.data() + (size_t(z) * size + y) * size;
      float* dst = atlas.data() + (size_t(z / columns) * size + y) * width + size_t(z % columns) * size;
      std::copy(src, src + size, dst);
    }
  return atlas;
}

json::Value model_sidecar(const model::CloudModel& model, int size, const std::vector<float>& values,
                          const json::Value& run, bool with_vdb) {
  json::Value root;
  root.set("program", "nephele model");
  root.set("version", version);
  root.set("size", size);
  root.set("extent_m", model.extent_m);
  root.set("voxel_size_m", model.extent_m / size);
  root.set("raw", "density.raw");
  root.set("raw_layout",
           "float32 little-endian, x fastest, then y, then z (up): voxel (x, y, z) at index (z * size + y) * size + x, "
           "its centre at ((x, y, z) + 0.5) * voxel_size_m metres from the volume's corner");
  const int columns = atlas_columns(size);
  root.set("atlas", "density_atlas.exr");
  root.set("atlas_layout", "single-channel float EXR, " + std::to_string(columns) +
                               " slices per row: slice z at tile (z % " + std::to_string(columns) + ", z / " +
                               std::to_string(columns) + "), tile row 0 is y = 0; unused tiles are 0");
  if (with_vdb) {
    root.set("vdb", "density.vdb");
    root.set("vdb_layout",
             "FOG_VOLUME float grid 'density', background 0, voxels above 0 active, voxel size voxel_size_m, "
             "index (x, y, z) = the raw volume's voxel, z up");
  }
  root.set("value", "density in [0, 1] (the clamped blend of the model's primitives)");
  root.set("density_to_extinction_per_m", density_to_extinction_per_m);
  root.set("extinction_note",
           "sigma_t = density * 0.075 / m (LWC 0.5 g/m^3, r_e 10 um); in Blender set the Principled "
           "Volume's Density to 0.075 for this extinction in metres");
  float lo = 0, hi = 0;
  size_t nonzero = 0;
  if (!values.empty()) {
    lo = *std::min_element(values.begin(), values.end());
    hi = *std::max_element(values.begin(), values.end());
    nonzero = size_t(std::count_if(values.begin(), values.end(), [](float v) { return v > 0.0f; }));
  }
  json::Value range;
  range.set("min", lo);
  range.set("max", hi);
  root.set("range", range);
  root.set("nonzero_voxels", static_cast<unsigned long>(nonzero));
  root.set("model", "model.cloud.json");
  if (!run.is_null()) root.set("run", run);
  return root;
}

std::vector<std::string> write_model_files(const std::filesystem::path& directory, const model::CloudModel& model,
                                           int size, const std::vector<float>& values, const json::Value& run,
                                           const core::ImageData* preview) {
  files::OutputSet outputs(directory, files::OutputSet::Scope::directory);
  std::vector<std::string> names = {"density.raw", "density_atlas.exr", "model.cloud.json", "density.json"};
  outputs.write("density.raw", values.data(), values.size() * sizeof(float));
  const int columns = atlas_columns(size), rows = (size + columns - 1) / columns;
  const core::ImageData atlas{columns * size, rows * size, 1, model_atlas(values, size)};
  outputs.write("density_atlas.exr", files::encode_image(atlas, files::exr_encoding({"Y"}), "density_atlas.exr"));
  outputs.write("model.cloud.json", io::write_cloud_model(model));
  const bool vdb = vdb_available();
  if (vdb) {
    outputs.write("density.vdb", vdb_bytes(model, size, values));
    names.push_back("density.vdb");
  }
  if (preview) {
    outputs.write("preview.png", files::encode_image(render::tone_map(*preview, preview_exposure),
                                                     files::png_encoding(8), "preview.png"));
    names.push_back("preview.png");
  }
  outputs.write("density.json", json::write(model_sidecar(model, size, values, run, vdb)));
  outputs.commit();
  return names;
}

}  // namespace nephele::io
