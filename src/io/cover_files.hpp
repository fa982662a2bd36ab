#pragma once
// The files of a generated global cover: six face EXRs, the equirectangular EXR and PNG
// preview, and the cover.json sidecar.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cover/global_cover.hpp"
#include "cover/tiled_cover.hpp"
#include "gpu/egl_context.hpp"
#include "core/image.hpp"
#include "core/json.hpp"
#include "files/atomic_output.hpp"
#include "files/image_files.hpp"

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

// The cover's parameters as the sidecar records them (keys from the parameter table).
json::Value cover_parameters_json(const cover::CoverParameters& parameters);

// What the sidecar records of a cover, computed whole or in tiles.
struct CoverSummary {
  cover::CoverParameters parameters;  // as run (the curl mode resolved)
  cover::CoverageCalibration calibration;
  std::optional<cover::BandCalibration> bands;
  std::optional<cover::WarpDiagnostics> diagnostics;
  std::vector<cover::PassTiming> timings;  // in tiles: each pass's time summed over the tiles
  int tiles = 0;                           // 0: computed whole
};
CoverSummary cover_summary(const cover::GlobalCover& cover);

// The sidecar's contents (parameters, conventions, result, timings).
json::Value cover_sidecar(const CoverSummary& cover, const gpu::ContextInfo& context,
                          const std::vector<cover::PassTiming>& export_timings, const CoverFileOptions& options = {});
json::Value cover_sidecar(const cover::GlobalCover& cover, const gpu::ContextInfo& context,
                          const std::vector<cover::PassTiming>& export_timings, const CoverFileOptions& options = {});

// What write_cover_files measured: the time of each step, and the bytes of the files.
struct CoverExport {
  std::vector<cover::PassTiming> timings;
  double bytes = 0;
};

// The largest cube face the PNG preview is made from (the preview 4 times as wide): 8192 x 4096
// pixels; larger covers are box-filtered down to it first.
constexpr int preview_face_limit = 2048;

// Six faces of `size` (GL order, rows from t = 0) box-filtered to `reduced` texels per face edge:
// each reduced texel the mean of the texels whose centres lie in it. The faces as they are
// when `reduced` >= `size`.
std::vector<float> reduced_faces(int size, const std::vector<float>& texels, int reduced);
// The PNG preview's map of six faces of `size`: their equirect map, of the faces reduced to
// preview_face_limit first where larger.
core::ImageData preview_image(int size, const std::vector<float>& texels);

// The channels of the cover's EXR files (faces and equirect), in order: the coverage as Y, the
// optical thickness and the cloud-top height in km above sea level, 0 where clear
// (docs/formats.md; shaders/lib/cloud_properties.glsl).
inline const std::vector<std::string> cover_channels = {"Y", "tau", "cloud_top"};
// The EXR encoding of the cover's files: Y as --precision says (float by default: covers just
// above the threshold can be below half's smallest value), tau and cloud_top as half (3 digits
// are more than either is known to; half the bytes to encode and store).
files::ImageEncoding cover_exr_encoding(const CoverFileOptions& options);

using cover::CoverPlanes;
// The planes' values interleaved as the EXR files' channels (cover_channels), from value `first`
// of each plane, `count` of them.
std::vector<float> interleaved_channels(const CoverPlanes& planes, std::size_t first, std::size_t count);

// Images of a cover in host memory, each encoded and written by write_cover_images where present.
struct CoverImages {
  int face_size = 0;
  std::shared_ptr<const CoverPlanes> faces;         // cover_{px,...}.exr: six faces a plane, GL order
  std::shared_ptr<const core::ImageData> equirect;  // cover_equirect.exr, the channels interleaved
  std::shared_ptr<const core::ImageData> preview;   // cover_equirect.png, the coverage
};
// Encodes the images in parallel and writes them into `outputs`, adding the timings and bytes.
void write_cover_images(files::OutputSet& outputs, const CoverImages& images, const CoverFileOptions& options,
                        CoverExport& result);

// Writes the files into `outputs` and commits it. The images are encoded in parallel (each
// EXR also with OpenEXR's own threads), the faces while the GPU resamples the equirect map.
CoverExport write_cover_files(files::OutputSet& outputs, const cover::GlobalCover& cover,
                              const gpu::ContextInfo& context, const CoverFileOptions& options = {});

}  // namespace nephele::io
