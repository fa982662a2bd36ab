#pragma once
// The global cover that render and its orbit view generate when no weather or cover directory is
// given, kept in the disk cache of files/float_cache.hpp: renders of one time and seed (a camera
// moved, an exposure tried) make it once (docs/performance.md, "The cover cache").
#include <filesystem>
#include <string>

#include "cover/cover_parameters.hpp"
#include "render/scene_renderer.hpp"

namespace nephele::io {

// What identifies a cover's values: the parameters as cover.json records them (the curl mode
// resolved), the land/ocean mask's and the latitude profile's values (by their hash, not their
// names), and the program's own code (files::program_fingerprint), since a new build may draw
// other clouds from the same parameters.
std::string cover_cache_key(const cover::CoverParameters& parameters);

// The cover of `parameters` (current GL context): from the cache in `directory` when it holds it
// (the same bits as making it), else made (render::make_global_cover) and stored there. An empty
// directory means no cache. `note` (if given) says which happened and how long it took.
render::GlobalCoverFaces cached_global_cover(const cover::CoverParameters& parameters,
                                             const std::filesystem::path& directory, std::string* note = nullptr);

}  // namespace nephele::io
