#pragma once
// The writers of the cover export presets, one file per target family, and what they share
// (io/export_common.cpp). export_presets.cpp lists them in its registry; nothing else calls
// them. docs/export.md describes each preset's files and conventions.
#include <array>
#include <string>
#include <vector>

#include "core/image.hpp"
#include "files/atomic_output.hpp"
#include "files/mip_chain.hpp"
#include "files/texture_containers.hpp"
#include "io/export_presets.hpp"

namespace nephele::io {

// Plain images (export_images.cpp).
ExportWriter write_equirect;
ExportWriter write_gl_faces;
// Texture containers (export_containers.cpp).
ExportWriter write_ktx2;
ExportWriter write_dds;
ExportWriter write_exr_cube;
// Planetaria and simulators (export_simulators.cpp).
ExportWriter write_celestia;
ExportWriter write_flightgear;
ExportWriter write_eve;
// Game engines and renderers (export_engines.cpp).
ExportWriter write_unity;
ExportWriter write_godot;
ExportWriter write_unreal;
ExportWriter write_blender;

// The celestia preset's CloudNormalMap of an equirect of coverage (4N x 2N, row 0 north), the
// height relief_m times the coverage: RGB in [0, 1], red east, green south, blue up (Celestia's
// tangent frame), each (1 + component)/2 (export_simulators.cpp).
core::ImageData celestia_normal_map(const core::ImageData& map, double relief_m);
// A KTX2 or DDS cube map of the cover with its full mip chain (files/mip_chain.hpp).
struct CubeContainer {
  std::string name;   // the file's name in the output set
  bool ktx2 = false;  // KTX2, else DDS
  files::TexelFormat format = files::TexelFormat::r16f;
  files::GreyLayout layout = files::GreyLayout::grey;
};
// Writes `containers` face by face (files::ContainerWriter), each face's chain made once for all
// of them, so that a cover of any size needs one face's chain in memory, not the cube's (8.6 GB
// of floats at 16384); the names appended in order.
void write_cube_containers(files::OutputSet& out, std::vector<std::string>& names, const CoverFaces& faces,
                           const std::vector<CubeContainer>& containers, const ExportOptions& options);
// Tells options.progress, where there is one, the share done and the stage.
void report_progress(const ExportOptions& options, double done, const std::string& stage);
// Face f of the cover as a one-channel image.
core::ImageData face_image(const CoverFaces& faces, int face);
// The equirect of docs/conventions.md (4 content x 2 content, -180 deg at the left edge,
// geodetic rows; content 0: the face size), resampled by options.resample_equirect, the same
// pass as `generate` (FlightGear's tiles want another size).
core::ImageData equirect_image(const CoverFaces& faces, const ExportOptions& options, int content = 0);
// Whether the equirect presets sample the faces on the CPU (cover::equirect_region) instead of
// the GPU pass: beyond options.gpu_equirect_faces. The map is then made region by region (the
// tiles of FlightGear and Celestia), never whole; the values are the GPU's up to float rounding.
bool equirect_on_cpu(int face_size, const ExportOptions& options);
// Pointers to the six faces of face_size^2 floats each that follow one another from `texels`.
std::array<const float*, 6> face_pointers(int face_size, const float* texels);
// One channel of `values` as an image, or white with `values` in alpha (`white_alpha`).
core::ImageData grey_image(int width, int height, std::vector<float> values, bool white_alpha = false);
// --name becomes a folder and file names: keeps it to a portable word (core::InputError).
void check_addon_name(const std::string& name);
// The preset's README.txt, with `body` and the note on linear data, listed after its files.
void add_readme(files::OutputSet& out, std::vector<std::string>& names, const ExportPreset& preset,
                const CoverFaces& faces, const std::string& body);

}  // namespace nephele::io
