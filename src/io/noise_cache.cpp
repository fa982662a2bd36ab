#include "io/noise_cache.hpp"

#include "core/hash.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <random>

#include "gpu/pass_timer.hpp"
#include "render/cloud_renderer.hpp"

namespace nephele::io {
namespace {

namespace fs = std::filesystem;

constexpr char magic[8] = {'N', 'E', 'P', 'H', 'C', 'A', 'C', '1'};
constexpr const char* prefix = "cache-";
constexpr const char* suffix = ".bin";

using core::fnv1a;

}  // namespace

fs::path default_cache_directory() {
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg && fs::path(xdg).is_absolute())
    return fs::path(xdg) / "nephele";
  if (const char* home = std::getenv("HOME"); home && *home) return fs::path(home) / ".cache" / "nephele";
  return {};
}

FloatCache::FloatCache(fs::path directory, std::uintmax_t cap_bytes)
    : directory_(std::move(directory)), cap_bytes_(cap_bytes) {}

fs::path FloatCache::file_of(const std::string& key) const {
  char name[64];
  std::snprintf(name, sizeof name, "%s%016llx%s", prefix, static_cast<unsigned long long>(fnv1a(key)), suffix);
  return directory_ / name;
}

// File: magic, key length (uint64), key, value count (uint64), values (native float32).
std::optional<std::vector<float>> FloatCache::load(const std::string& key, std::size_t count) const {
  const fs::path path = file_of(key);
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  char head[sizeof magic];
  std::uint64_t key_length = 0, stored_count = 0;
  if (!in.read(head, sizeof head) || std::memcmp(head, magic, sizeof magic) != 0) return std::nullopt;
  if (!in.read(reinterpret_cast<char*>(&key_length), sizeof key_length) || key_length != key.size()) return std::nullopt;
  std::string stored_key(key.size(), '\0');
  if (!in.read(stored_key.data(), static_cast<std::streamsize>(key.size())) || stored_key != key) return std::nullopt;
  if (!in.read(reinterpret_cast<char*>(&stored_count), sizeof stored_count) || stored_count != count) return std::nullopt;
  std::vector<float> values(count);
  if (!in.read(reinterpret_cast<char*>(values.data()), static_cast<std::streamsize>(count * sizeof(float))))
    return std::nullopt;
  if (in.peek() != std::char_traits<char>::eof()) return std::nullopt;  // longer than it says: not ours
  std::error_code ignored;
  fs::last_write_time(path, fs::file_time_type::clock::now(), ignored);  // used: trimmed last
  return values;
}

bool FloatCache::store(const std::string& key, const std::vector<float>& values) const {
  std::error_code error;
  fs::create_directories(directory_, error);
  if (error) return false;
  const fs::path final_path = file_of(key);
  // A name of its own per writer, so that concurrent writers never share a temporary file.
  const fs::path temporary = directory_ / (".tmp-" + std::to_string(::getpid()) + "-" +
                                           std::to_string(std::random_device{}()) + suffix);
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    const std::uint64_t key_length = key.size(), count = values.size();
    out.write(magic, sizeof magic);
    out.write(reinterpret_cast<const char*>(&key_length), sizeof key_length);
    out.write(key.data(), static_cast<std::streamsize>(key.size()));
    out.write(reinterpret_cast<const char*>(&count), sizeof count);
    out.write(reinterpret_cast<const char*>(values.data()), static_cast<std::streamsize>(values.size() * sizeof(float)));
    out.flush();
    if (!out) {
      out.close();
      fs::remove(temporary, error);
      return false;
    }
  }
  // rename() replaces the old file at once: readers see the old or the new file, whole.
  fs::rename(temporary, final_path, error);
  if (error) {
    fs::remove(temporary, error);
    return false;
  }
  trim();
  return true;
}

void FloatCache::trim() const {
  struct Entry {
    fs::path path;
    fs::file_time_type time;
    std::uintmax_t bytes;
  };
  std::vector<Entry> entries;
  std::uintmax_t total = 0;
  std::error_code error;
  for (const auto& item : fs::directory_iterator(directory_, error)) {
    const std::string name = item.path().filename().string();
    if (name.rfind(prefix, 0) != 0 || !item.is_regular_file(error)) continue;
    const std::uintmax_t bytes = item.file_size(error);
    if (error) continue;
    entries.push_back({item.path(), item.last_write_time(error), bytes});
    total += bytes;
  }
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) { return a.time < b.time; });
  for (const Entry& e : entries) {
    if (total <= cap_bytes_) break;
    if (fs::remove(e.path, error)) total -= e.bytes;
  }
}

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
    const FloatCache cache(directory);
    const std::string key = "noise_volume size " + std::to_string(size) + " seed " + std::to_string(seed) + " " +
                            render::NoiseVolume::recipe_key();
    const std::size_t count = render::NoiseVolume::channels * static_cast<std::size_t>(size) * size * size;
    if (auto values = cache.load(key, count)) {
      noise = std::make_unique<render::NoiseVolume>(size, seed, *values);
      what = "noise volume: from the cache " + cache.file_of(key).string();
    } else {
      noise = std::make_unique<render::NoiseVolume>(size, seed);
      what = cache.store(key, noise->level0()) ? "noise volume: made and cached in " + cache.file_of(key).string()
                                              : "noise volume: made (the cache " + directory.string() +
                                                    " could not be written)";
    }
  });
  if (note != nullptr) *note = what + " (" + std::to_string(ms) + " ms)";
  return noise;
}

}  // namespace nephele::io
