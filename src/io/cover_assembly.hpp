#pragma once
// The files of a cover computed in tiles, made from its tile parts (nephele assemble, and
// generate for covers beyond its memory budget; docs/scale.md): the calibration over every
// tile's densities, then each tile's cover streamed into the face EXRs row by row, so that no
// more than a tile is held. The files are those write_cover_files writes for the whole map, the
// faces and the equirect EXR to the bit; the PNG preview is downsampled beyond preview_face_limit.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "gpu/egl_context.hpp"
#include "io/cover_files.hpp"
#include "io/cover_tiles.hpp"

namespace nephele::io {

// Host bytes the assembly holds for a cover of `size` per face: a tile's densities and cover
// (the largest tile of `tiles`), the preview's cube, and with the equirect EXR the whole cover
// and its map where they fit `budget` (0: no budget), else the rows the streamed map holds
// (cover/streamed_equirect.hpp).
double assembly_host_bytes(int size, int tiles, const CoverFileOptions& options, double budget);
double whole_equirect_bytes(int size);
// Throws core::InputError naming --memory-budget when the assembly's host bytes pass `budget`
// (0: no budget); generate and assemble check it before any work.
void check_assembly_fits(int size, int tiles, const CoverFileOptions& options, double budget);
// Whether the equirect EXR is made from the whole cover (on the GPU, as generate's whole map),
// which takes whole_equirect_bytes, or streamed from scratch faces on the CPU.
bool equirect_from_whole_cover(int size, int tiles, const CoverFileOptions& options, double budget);

struct AssembledCover {
  CoverSummary summary;
  CoverExport exported;
};

// Writes the cover of `parts` (every tile of one cover, in order) into `outputs` (the caller
// commits it).
// `progress` hears each step ("calibrate", "tile 3 of 24", ...).
AssembledCover write_assembled_cover(files::OutputSet& outputs, const std::vector<TilePart>& parts,
                                     const cover::CoverParameters& parameters, const gpu::ContextInfo& context,
                                     const CoverFileOptions& options, double budget,
                                     const std::function<void(const std::string&)>& progress = {});

// The complete parts of every tile of a cover in `directory`: throws core::InputError naming the
// directory and the tiles that are missing or belong to other covers.
std::vector<TilePart> read_all_tile_parts(const std::filesystem::path& directory, const std::string& field);

}  // namespace nephele::io
