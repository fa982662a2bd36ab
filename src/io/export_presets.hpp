#pragma once
// nephele export: a cover directory written by `generate` turned into what one target reads
// (docs/export.md). Each preset writes its files and a README.txt into one output set.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "files/atomic_output.hpp"

namespace nephele::io {

// The six faces of a cover, GL order +X, -X, +Y, -Y, +Z, -Z, rows from t = 0.
struct CoverFaces {
  int size = 0;
  std::vector<float> texels;  // 6 * size * size: the coverage
  // The cloud's optical thickness and cloud-top height (km), as texels; empty for faces without
  // the tau and cloud_top channels (covers of earlier versions, a user's own coverage).
  std::vector<float> optical_thickness, cloud_top;
};

// Reads cover_px.exr ... cover_nz.exr of `directory`. Throws core::InputError naming COVER_DIR
// when the directory, a face or its size is wrong.
// Reads the six faces: square, of one size, with the channel Y alone or Y, tau and cloud_top
// (io::cover_channels), the coverage finite in [0, 1], tau and the top finite and >= 0;
// anything else is core::InputError naming the file (and the texel). read_cover_face_size reads
// only the headers, so that size limits are checked before the pixels are read.
CoverFaces read_cover_faces(const std::filesystem::path& directory);
int read_cover_face_size(const std::filesystem::path& directory);

struct ExportOptions {
  std::string ktx2_format = "r16f";     // ktx2: r16f, r32f, r8
  std::string name = "nephele_clouds";  // celestia: the add-on's folder and file names
  // celestia: the CloudMap's tile edge as a virtual texture (a power of two from 64); 0 writes one
  // map where it fits max_texture_edge and a virtual texture of 1024-texel tiles beyond.
  int celestia_tile = 0;
  // The largest face size whose equirect presets resample the cube map on the GPU
  // (resample_equirect), whole; beyond it celestia and flightgear sample their tiles from the
  // faces on the CPU (io/export_writers.hpp, equirect_on_cpu). 4096: the 4N map is one
  // texture of 16384 and the cube map fits llvmpipe's 1 GiB per texture.
  int gpu_equirect_faces = 4096;
  // Told the share of the preset's work done (0 to 1) and what runs now, by the presets whose
  // work grows with the cover (containers face by face, tiles one by one); may be empty.
  std::function<void(double done, const std::string& stage)> progress;
  // Resamples the six faces to a width x height equirect (cover::equirect_from_faces): the GPU
  // pass that the presets with needs_equirect use, given by the caller, so that io runs none.
  std::vector<float> (*resample_equirect)(int face_size, const std::vector<float>& texels, int width,
                                          int height) = nullptr;
};

struct ExportPreset;
// A preset's writer: its files (README.txt included) into `out`, their names appended to
// `names` in the order written (one file per target family: io/export_writers.hpp).
using ExportWriter = void(files::OutputSet& out, std::vector<std::string>& names, const ExportPreset& preset,
                          const CoverFaces& faces, const ExportOptions& options);

// One row of the preset registry: everything about a preset is here, its writer included.
struct ExportPreset {
  std::string name;               // --preset word
  std::string summary;            // one line for --help and the README
  bool needs_equirect;            // resamples the cube map (ExportOptions::resample_equirect)
  bool volume = false;            // reads a volume's sidecar (io/volume_export.hpp) instead of a cover
  bool takes_format = false;      // reads --format (ExportOptions::ktx2_format)
  bool takes_name = false;        // reads --name (ExportOptions::name)
  ExportWriter* write = nullptr;  // nullptr for a volume preset
  // The longest image edge it writes for face size n; nullptr for a volume preset.
  long long (*widest_edge)(int face_size) = nullptr;
};
// The presets in the order --help lists them.
const std::vector<ExportPreset>& export_presets();
// "equirect|gl-faces|..." for the parameter table's check; throws core::InputError for an unknown name.
const ExportPreset& find_export_preset(const std::string& name);

// The widest texture an export writes: OpenGL 4.5's guaranteed GL_MAX_TEXTURE_SIZE, the limit of
// llvmpipe, most GPUs and Unity (docs/export.md).
constexpr int max_texture_edge = 16384;
// FlightGear's tile edge for face size n: the smallest power of two >= n, at least 128 (the
// border is tile/128 pixels).
int flightgear_tile_size(int face_size);
// The longest image edge `preset` writes for face size n.
long long widest_image_edge(const ExportPreset& preset, int face_size);
// Throws core::InputError naming COVER_DIR, the preset, the edge and the limit when the preset
// would write an image over max_texture_edge: checked before any work, never a late failure.
void check_texture_limit(const ExportPreset& preset, int face_size);

// Throws core::InputError for an option the preset would refuse (celestia's and eve's --name,
// ktx2's --format), so that it is refused before --out is created and before any work.
void check_export_options(const ExportPreset& preset, const ExportOptions& options);

// Writes the preset's files (README.txt included) into `outputs` without committing it, and
// returns their names in the order written. Equirect presets need a current GL context.
std::vector<std::string> write_export(files::OutputSet& outputs, const ExportPreset& preset, const CoverFaces& faces,
                                      const ExportOptions& options = {});

}  // namespace nephele::io
