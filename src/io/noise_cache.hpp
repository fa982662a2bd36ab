#pragma once
// The ground renderer's noise volume, kept in the disk cache of files/float_cache.hpp so that
// renders of one scene do not rebuild it (docs/performance.md).
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

namespace nephele::render {
class NoiseVolume;
}

namespace nephele::io {

// The ground renderer's noise volume of `size` and `seed` (current GL context): from the cache in
// `directory` when it holds one (the same bits as making it), else made and stored there. An
// empty directory means no cache. `note` (if given) says which happened and how long it took.
std::unique_ptr<render::NoiseVolume> cached_noise_volume(int size, std::uint32_t seed,
                                                         const std::filesystem::path& directory,
                                                         std::string* note = nullptr);

}  // namespace nephele::io
