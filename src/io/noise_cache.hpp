#pragma once
// A disk cache of computed arrays of floats (the ground renderer's noise volume), so that
// renders of one scene do not rebuild them: one file per key under a directory, written
// atomically (a temporary file renamed into place), the least recently used files removed
// when the directory passes its size cap. A damaged, foreign or mismatched file is a miss,
// never an error, and a cache that cannot be written is skipped. docs/performance.md.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace nephele::render {
class NoiseVolume;
}

namespace nephele::io {

// The default directory: $XDG_CACHE_HOME/nephele, else $HOME/.cache/nephele (the XDG Base
// Directory Specification's default); empty when neither variable is set.
std::filesystem::path default_cache_directory();

// Bytes the cache keeps at most by default: 256 MiB (the default 64^3 noise volume is 2 MiB;
// a 256^3 one 128 MiB).
constexpr std::uintmax_t default_cache_cap_bytes = std::uintmax_t(256) << 20;

class FloatCache {
 public:
  FloatCache(std::filesystem::path directory, std::uintmax_t cap_bytes = default_cache_cap_bytes);
  // The values stored under `key` when there are exactly `count` of them; marks the file used.
  std::optional<std::vector<float>> load(const std::string& key, std::size_t count) const;
  // Stores `values` under `key` (replacing any), then trims the cache to its cap. Returns false
  // (and leaves no partial file) when the directory cannot be written.
  bool store(const std::string& key, const std::vector<float>& values) const;
  // The file that holds `key` (its name is a hash of the key; the key itself is inside).
  std::filesystem::path file_of(const std::string& key) const;
  const std::filesystem::path& directory() const { return directory_; }

 private:
  void trim() const;
  std::filesystem::path directory_;
  std::uintmax_t cap_bytes_;
};

// The ground renderer's noise volume of `size` and `seed` (current GL context): from the cache in
// `directory` when it holds one (the same bits as making it), else made and stored there. An
// empty directory means no cache. `note` (if given) says which happened and how long it took.
std::unique_ptr<render::NoiseVolume> cached_noise_volume(int size, std::uint32_t seed,
                                                         const std::filesystem::path& directory,
                                                         std::string* note = nullptr);

}  // namespace nephele::io
