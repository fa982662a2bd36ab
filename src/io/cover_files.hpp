#pragma once
// The files of a generated global cover: six face EXRs, the equirectangular EXR and PNG
// preview, and the cover.json sidecar.
#include <filesystem>
#include <string>
#include <vector>

#include "cover/global_cover.hpp"
#include "gpu/egl_context.hpp"
#include "core/json.hpp"
#include "files/atomic_output.hpp"

namespace nephele::io {

// Face file suffixes in GL face order +X, -X, +Y, -Y, +Z, -Z.
inline const char* const face_suffixes[6] = {"px", "nx", "py", "ny", "pz", "nz"};

// Which images are written and how (generate's --files, --precision, --exr-compression).
// What no file asks for is not computed: without the equirect EXR and PNG the cube map is
// not resampled, without faces they are not read back.
struct CoverFileOptions {
  bool faces = true;     // cover_{px,...}.exr
  bool equirect = true;  // cover_equirect.exr
  bool preview = true;   // cover_equirect.png
  bool half = false;     // EXR samples as 16-bit half instead of 32-bit float
  std::string compression = "zip";
};
// Parses generate's --files list ("faces,equirect,png", any non-empty subset, no repeats);
// throws core::InputError naming the option, the value and the allowed words.
void parse_cover_files(const std::string& list, CoverFileOptions& options);

// Names of the files write_cover_files produces (cover.json last).
std::vector<std::string> cover_file_names(const CoverFileOptions& options = {});

// The sidecar's contents (parameters, conventions, result, timings).
json::Value cover_sidecar(const cover::GlobalCover& cover, const gpu::ContextInfo& context,
                          const std::vector<cover::PassTiming>& export_timings, const CoverFileOptions& options = {});

// What write_cover_files measured: the time of each step, and the bytes of the files.
struct CoverExport {
  std::vector<cover::PassTiming> timings;
  double bytes = 0;
};

// Writes the files into `outputs` and commits it. The images are encoded in parallel (each
// EXR also with OpenEXR's own threads), the faces while the GPU resamples the equirect map.
CoverExport write_cover_files(files::OutputSet& outputs, const cover::GlobalCover& cover,
                              const gpu::ContextInfo& context, const CoverFileOptions& options = {});

}  // namespace nephele::io
