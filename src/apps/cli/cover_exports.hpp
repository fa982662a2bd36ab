#pragma once
// --export of generate and assemble: the presets run on the new cover inside its output set,
// each into export/NAME, so that everything appears whole or not at all (docs/export.md).
#include <string>
#include <vector>

#include "files/atomic_output.hpp"
#include "io/cover_files.hpp"
#include "io/export_presets.hpp"

namespace nephele::cli {

// The presets of --export's list for a cover of face_size, each checked (a known cover preset,
// named once, within its texture limit) before any work; throws UsageError naming --export.
std::vector<const io::ExportPreset*> parse_cover_exports(const std::string& list, int face_size);

// A cover made in tiles is exported from its assembled faces, so they must be among the files
// and hold the cover's floats exactly: throws UsageError unless `files` writes faces as float
// with a lossless compression.
void check_exports_read_faces(const std::vector<const io::ExportPreset*>& presets, const io::CoverFileOptions& files);

// Runs `presets` on `faces` into export/NAME of `set`'s temporary directory.
void write_cover_exports(files::OutputSet& set, const std::vector<const io::ExportPreset*>& presets,
                         const io::CoverFaces& faces);
// The same from the faces written into `set` (cover_px.exr ... in its temporary directory).
void write_cover_exports_from_faces(files::OutputSet& set, const std::vector<const io::ExportPreset*>& presets);

}  // namespace nephele::cli
