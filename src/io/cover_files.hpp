#pragma once
// The files of a generated global cover: six face EXRs, the equirectangular EXR and PNG
// preview, and the cover.json sidecar.
#include <filesystem>
#include <string>
#include <vector>

#include "cover/global_cover.hpp"
#include "gpu/egl_context.hpp"
#include "core/json.hpp"
#include "io/atomic_output.hpp"

namespace nephele::io {

// Face file suffixes in GL face order +X, -X, +Y, -Y, +Z, -Z.
inline const char* const face_suffixes[6] = {"px", "nx", "py", "ny", "pz", "nz"};

// Names of the files write_cover_files produces.
std::vector<std::string> cover_file_names();

// The sidecar's contents (parameters, conventions, result, timings).
json::Value cover_sidecar(const cover::GlobalCover& cover, const gpu::ContextInfo& context,
                          const std::vector<cover::PassTiming>& export_timings);

// Writes every file into `outputs` and commits it. Returns the time of each export step.
std::vector<cover::PassTiming> write_cover_files(OutputSet& outputs, const cover::GlobalCover& cover,
                                                 const gpu::ContextInfo& context);

}  // namespace nephele::io
