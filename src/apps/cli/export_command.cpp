// nephele export COVER_DIR --preset NAME --out DIR: a generated cover turned into the files one
// target reads (docs/export.md), written as one output set with a README.txt.
#include <filesystem>
#include <iostream>
#include <memory>

#include "apps/cli/commands.hpp"
#include "apps/cli/options.hpp"
#include "core/progress.hpp"
#include "cover/equirect.hpp"
#include "gpu/egl_context.hpp"
#include "files/atomic_output.hpp"
#include "io/export_presets.hpp"
#include "io/volume_export.hpp"
#include "params/table.hpp"

namespace nephele::cli {

int run_export(const std::vector<std::string>& arguments) {
  namespace run = params::run;
  std::string preset_name, out, format(run::export_format.default_text), name(run::export_name.default_text);
  std::string presets_text;
  for (const auto& p : io::export_presets())
    presets_text += (presets_text.empty() ? "  " : "\n  ") + p.name + ": " + p.summary;
  Options options("export COVER_DIR|VOLUME.json",
                  "Turns a cover directory written by `nephele generate` (cover_px.exr ... cover_nz.exr), or for\n"
                  "atlas and openvdb the sidecar of a volume (nephele noise --out NAME.raw, or a model's\n"
                  "density.json), into the files one target reads, with a README.txt saying where they go\n"
                  "(docs/export.md). Presets:\n" +
                      presets_text,
                  params::export_cover);
  options.bind(run::export_preset, &preset_name);
  options.bind(run::export_out, &out);
  options.bind(run::export_format, &format);
  options.bind(run::export_name, &name);
  std::string cover_dir;  // COVER_DIR comes first; the rest are options
  if (!parse_with_cover_dir(options, arguments, cover_dir)) return exit_ok;
  if (!options.given(run::export_preset))
    throw UsageError("--preset", "", std::string(run::export_preset.allowed), "is missing");
  if (!options.given(run::export_out)) throw UsageError("--out", "", "DIR", "is missing");
  const io::ExportPreset& preset = io::find_export_preset(preset_name);
  // An option the preset does not read is refused rather than ignored.
  if (options.given(run::export_format) && !preset.takes_format)
    throw UsageError("--format", format, "only with --preset ktx2", "is not read by preset " + preset.name);
  if (options.given(run::export_name) && !preset.takes_name)
    throw UsageError("--name", name, "only with --preset celestia or eve", "is not read by preset " + preset.name);
  io::ExportOptions export_options;
  export_options.ktx2_format = format;
  export_options.name = name;
  export_options.resample_equirect = cover::equirect_from_faces;
  io::check_export_options(preset, export_options);  // before --out is created
  // Minutes at 16384 per face: reading the faces, then the preset's own stages.
  core::Progress progress("export " + preset.name, 1.0, core::Progress::for_stderr(false));
  export_options.progress = [&](double done, const std::string& stage) { progress.update(done, stage); };
  io::CoverFaces faces;
  io::VolumeData volume;
  if (preset.volume) {
    volume = io::read_volume(cover_dir);
    if (preset.name == "atlas") io::atlas_grid(volume.width, volume.height, volume.depth);  // fits, before any work
  } else {
    io::check_texture_limit(preset, io::read_cover_face_size(cover_dir));  // headers only: refused before reading
    progress.update(0.0, "reading the faces");
    faces = io::read_cover_faces(cover_dir);
  }

  const std::filesystem::path directory(out);
  files::check_output_directory(directory, "--out");
  std::unique_ptr<gpu::EglContext> context;
  if (preset.needs_equirect) context = std::make_unique<gpu::EglContext>();
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error) throw UsageError("--out", out, "DIR", "cannot be created: " + error.message());
  files::OutputSet outputs(directory, files::OutputSet::Scope::directory);
  const std::vector<std::string> names = preset.volume ? io::write_volume_export(outputs, preset.name, volume)
                                                       : io::write_export(outputs, preset, faces, export_options);
  progress.update(1.0, "commit");
  outputs.commit();
  progress.finish();
  for (const auto& file : names) std::cout << (directory / file).string() << "\n";
  return exit_ok;
}

}  // namespace nephele::cli
