#pragma once
// The parts of a cover computed in tiles (generate --tiles COUNT --tile A-B, nephele assemble;
// docs/scale.md; the format in docs/formats.md, "Tile parts"). One file per tile,
// tile_NNNNNN.part, written whole or not at all (files::replace_file), so that the tasks of a
// job array share the directory and a task run again replaces its parts:
//   8 bytes   "NEPHTIL3"
//   8 bytes   L, the header's length (unsigned, little-endian)
//   L bytes   the header, JSON: the tile's place, its density range and diagnosis sums, its
//             timings, the densities' byte count, the block hashes of the densities, the
//             cloud tops and the cover contrasts, and the cover it belongs to
//   B bytes   the tile's owned densities, float32 little-endian, row by row (face_size a row)
//   B bytes   their cloud-top heights (km), the same way
//   B bytes   their cover contrasts (cover_density.glsl), the same way
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/json.hpp"
#include "cover/tiled_cover.hpp"

namespace nephele::io {

std::string tile_part_name(int index);  // tile_000007.part

// What identifies the cover a part belongs to: the generate arguments that made it (without
// --tile and --out) and the parameters as the sidecar records them; parts of one cover have
// equal identities.
json::Value cover_identity(const std::vector<std::string>& arguments, const cover::CoverParameters& parameters);

void write_tile_part(const std::filesystem::path& directory, const cover::TileDensity& tile, int tile_count,
                     const json::Value& identity);

// A part's header, read and checked (everything but the densities).
struct TilePart {
  std::filesystem::path path;
  cover::TileDensity tile;  // density empty until read_tile_densities
  int tile_count = 0;
  json::Value identity;
  std::uint64_t density_hash = 0;
  std::uint64_t cloud_top_hash = 0;
  std::uint64_t contrast_hash = 0;
  std::uint64_t data_offset = 0;
};

// The part of tile `index` in `directory` when it is complete (its header reads, its file holds
// all its densities) and belongs to the cover `identity` with `tile_count` tiles; nullopt when
// there is none. Throws core::InputFileError naming the file when it belongs to another cover.
std::optional<TilePart> find_tile_part(const std::filesystem::path& directory, int index, int tile_count,
                                       const json::Value& identity);
// The header of a part file; throws core::InputFileError naming the file and the field.
TilePart read_tile_header(const std::filesystem::path& path);
// The densities of a part, checked against the header's hash; throws core::InputFileError.
std::vector<float> read_tile_densities(const TilePart& part);
// Its cloud-top heights and cover contrasts, checked the same way.
std::vector<float> read_tile_cloud_tops(const TilePart& part);
std::vector<float> read_tile_cover_contrasts(const TilePart& part);

}  // namespace nephele::io
