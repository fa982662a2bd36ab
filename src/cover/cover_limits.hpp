#pragma once
// Whether a cover of a given size fits the driver's limits and the memory available, checked
// before any allocation so that a size too large is bad input (exit code 2).
#include <string>

#include "cover/flow_kind.hpp"
#include "gpu/context.hpp"

namespace nephele::cover {

// Throws core::InputError naming `option`, the size and the allowed range when `size` does not
// fit. Needs `context` current.
void check_cover_fits(const gpu::Context& context, int size, const std::string& option = "--size",
                      Flow flow = Flow::steady);

// Whether the driver can allocate the RGBA32F cube maps of a whole cover of `size` per face (its
// cube map limit, and what it answers for a proxy texture: llvmpipe takes no texture over 1 GiB,
// 4092 per face). Covers it cannot are computed in tiles, whose maps are strips of one face.
// Needs a context current.
bool whole_cube_fits_driver(int size);

// Whether generate computes a cover of `size` in tiles when no tile count is asked for: where the
// whole cover's bytes exceed `budget` (0: no budget), or where the driver cannot allocate its
// cube maps (whole_cube_fits_driver). Needs a context current.
bool cover_needs_tiles(int size, Flow flow, double budget);

// The memory a cover's passes may take when --memory-budget is 0: the GPU's free memory, or with
// a software renderer (whose textures are host memory) half the host's available memory; 0
// when unknown.
double default_memory_budget_bytes(const gpu::Context& context);
// Bytes the passes take for the whole cube map (GPU maps, and the host copies of the files).
double whole_cover_bytes(int size, Flow flow);
// Bytes a tile of `rows` rows (its halo included) takes: its maps, the read-back densities and
// the tables every tile shares (texel weights, the curl grid).
double tile_bytes(int size, int rows);
// The fewest tiles (a multiple of 6) whose passes fit `budget` bytes. Throws core::InputError
// naming --memory-budget when even tiles of one row do not fit.
int tile_count_for_budget(int size, double budget, const std::string& option = "--memory-budget");

}  // namespace nephele::cover
