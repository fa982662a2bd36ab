#include "io/noise_cache.hpp"

#include "files/float_cache.hpp"
#include "gpu/pass_timer.hpp"
#include "render/cloud_renderer.hpp"

namespace nephele::io {

namespace fs = std::filesystem;
using files::FloatCache;

std::unique_ptr<render::NoiseVolume> cached_noise_volume(int size, std::uint32_t seed, const fs::path& directory,
                                                         std::string* note) {
  std::unique_ptr<render::NoiseVolume> noise;
  std::string what;
  const double ms = gpu::time_pass([&] {
    if (directory.empty()) {
      noise = std::make_unique<render::NoiseVolume>(size, seed);
      what = "noise volume: made (no cache)";
      return;
    }
    const files::FloatCache cache(directory);
    const std::string key = "noise_volume size " + std::to_string(size) + " seed " + std::to_string(seed) + " " +
                            render::NoiseVolume::recipe_key();
    const std::size_t count = render::NoiseVolume::channels * static_cast<std::size_t>(size) * size * size;
    if (auto values = cache.load(key, count)) {
      noise = std::make_unique<render::NoiseVolume>(size, seed, *values);
      what = "noise volume: from the cache " + cache.file_of(key).string();
    } else {
      noise = std::make_unique<render::NoiseVolume>(size, seed);
      what = cache.store(key, noise->level0())
                 ? "noise volume: made and cached in " + cache.file_of(key).string()
                 : "noise volume: made (the cache " + directory.string() + " could not be written)";
    }
  });
  if (note != nullptr) *note = what + " (" + std::to_string(ms) + " ms)";
  return noise;
}

}  // namespace nephele::io
