#include "apps/cli/cover_exports.hpp"

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "apps/cli/options.hpp"
#include "cover/equirect.hpp"
#include "files/image_files.hpp"
#include "params/table.hpp"

namespace nephele::cli {

std::vector<const io::ExportPreset*> parse_cover_exports(const std::string& list, int face_size) {
  const std::string allowed(params::run::cover_exports.allowed);
  std::vector<const io::ExportPreset*> presets;
  std::stringstream names(list);
  for (std::string name; std::getline(names, name, ',');) {
    const auto& all = io::export_presets();
    const auto found = std::find_if(all.begin(), all.end(), [&](const io::ExportPreset& p) { return p.name == name; });
    if (found == all.end()) throw UsageError("--export", name, std::string(params::run::export_preset.allowed));
    if (found->volume) throw UsageError("--export", name, "a cover preset", "exports volumes, not covers");
    if (std::find(presets.begin(), presets.end(), &*found) != presets.end())
      throw UsageError("--export", list, allowed, "names " + name + " twice (as --files refuses faces,faces)");
    presets.push_back(&*found);
    io::check_texture_limit(*presets.back(), face_size);
  }
  if (presets.empty() || list.back() == ',')
    throw UsageError("--export", list, allowed, "names no preset or ends with a comma");
  return presets;
}

void check_exports_read_faces(const std::vector<const io::ExportPreset*>& presets, const io::CoverFileOptions& files) {
  if (presets.empty()) return;
  if (!files.faces || files.half || !files::is_lossless_exr_compression(files.compression))
    throw UsageError("--export", "",
                     "--files with faces, --precision float and a lossless --exr-compression (none, rle, zips, zip, "
                     "piz)",
                     "reads the faces of a cover made in tiles, so they must hold its floats exactly");
}

void write_cover_exports(files::OutputSet& set, const std::vector<const io::ExportPreset*>& presets,
                         const io::CoverFaces& faces) {
  io::ExportOptions options;
  options.resample_equirect = cover::equirect_from_faces;
  for (const io::ExportPreset* preset : presets) {
    const std::filesystem::path folder = set.temporary_directory() / "export" / preset->name;
    std::filesystem::create_directories(folder);
    files::OutputSet preset_set(folder, files::OutputSet::Scope::directory);
    io::write_export(preset_set, *preset, faces, options);
    preset_set.commit();
  }
}

void write_cover_exports_from_faces(files::OutputSet& set, const std::vector<const io::ExportPreset*>& presets) {
  if (presets.empty()) return;
  write_cover_exports(set, presets, io::read_cover_faces(set.temporary_directory()));
}

}  // namespace nephele::cli
