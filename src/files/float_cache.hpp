#pragma once
// A disk cache of computed arrays of floats (the ground renderer's noise volume, io/noise_cache.hpp), so that
// renders of one scene do not rebuild them: one file per key under a directory, named
// cache-<FNV-1a of the key>.bin. A file holds the magic "NEPHCAC2", the key's length and the key
// (so that a colliding name is a miss), the value count, a 64-bit content hash (core::block_hash
// of the values' bytes, seeded with the key's hash) and the values (native float32). It is
// written to a temporary file .tmp-<PID>-<random>.bin and renamed into place, so readers see a
// whole file or none. A load accepts only a regular file (opened without following a symbolic
// link and without waiting on a FIFO) of exactly the expected size whose hash matches and whose
// values are finite: anything else is a miss, never an error, and the next store replaces it.
// After each store the least recently used entries are removed until the directory holds at most
// the cap; the trim judges every name by lstat (a symbolic link is removed, never counted by its
// target), removes temporary files of writers that no longer run or that are over an hour old,
// counts live ones, and never removes the entry just stored. A cache that cannot be written is
// skipped. docs/performance.md.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace nephele::files {

// The default directory: $XDG_CACHE_HOME/nephele, else $HOME/.cache/nephele (the XDG Base
// Directory Specification's default); empty when neither variable is set.
std::filesystem::path default_cache_directory();

// A fingerprint of the running program's code: core::block_hash of its executable's bytes
// (/proc/self/exe) as 16 hex digits, read once; empty where the file cannot be read. Entries whose
// values the program computes (not only reads) key on it, so that a new build never serves an old
// build's results.
const std::string& program_fingerprint();

// Bytes the cache keeps at most by default: 256 MiB (the default 64^3 noise volume, four
// float channels, is 4 MiB; a 256^3 one 256 MiB, which the trim keeps alone).
constexpr std::uintmax_t default_cache_cap_bytes = std::uintmax_t(256) << 20;

class FloatCache {
 public:
  FloatCache(std::filesystem::path directory, std::uintmax_t cap_bytes = default_cache_cap_bytes);
  // The values stored under `key` when there are exactly `count` of them; marks the file used.
  std::optional<std::vector<float>> load(const std::string& key, std::size_t count) const;
  // Stores `values` under `key` (replacing any), then trims the cache to its cap. Returns false
  // (and leaves no partial file) when the directory cannot be written or a value is not finite.
  bool store(const std::string& key, const std::vector<float>& values) const;
  // The file that holds `key` (its name is a hash of the key; the key itself is inside).
  std::filesystem::path file_of(const std::string& key) const;
  const std::filesystem::path& directory() const { return directory_; }

 private:
  // Removes the least recently used entries, except `keep` (a file name), beyond the cap.
  void trim(const std::string& keep) const;
  std::filesystem::path directory_;
  std::uintmax_t cap_bytes_;
};

}  // namespace nephele::files
