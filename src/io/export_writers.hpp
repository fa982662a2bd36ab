#pragma once
// The writers of the cover export presets, one file per target family, and what they share
// (io/export_common.cpp). export_presets.cpp lists them in its registry; nothing else calls
// them. docs/export.md describes each preset's files and conventions.
#include <string>
#include <vector>

#include "core/image.hpp"
#include "files/atomic_output.hpp"
#include "files/mip_chain.hpp"
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
// The cover's six faces and their mip chain (files/mip_chain.hpp), for the texture containers.
files::MipChain cube_mip_chain(const CoverFaces& faces);
// Face f of the cover as a one-channel image.
core::ImageData face_image(const CoverFaces& faces, int face);
// The equirect of docs/conventions.md (4 content x 2 content, -180 deg at the left edge,
// geodetic rows; content 0: the face size), resampled by options.resample_equirect, the same
// pass as `generate` (FlightGear's tiles want another size).
core::ImageData equirect_image(const CoverFaces& faces, const ExportOptions& options, int content = 0);
// One channel of `values` as an image, or white with `values` in alpha (`white_alpha`).
core::ImageData grey_image(int width, int height, std::vector<float> values, bool white_alpha = false);
// --name becomes a folder and file names: keeps it to a portable word (core::InputError).
void check_addon_name(const std::string& name);
// The preset's README.txt, with `body` and the note on linear data, listed after its files.
void add_readme(files::OutputSet& out, std::vector<std::string>& names, const ExportPreset& preset,
                const CoverFaces& faces, const std::string& body);

}  // namespace nephele::io
