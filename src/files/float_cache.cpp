#include "files/float_cache.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <random>

#include "core/file_descriptor.hpp"
#include "core/hash.hpp"

namespace nephele::files {
namespace {

namespace fs = std::filesystem;

// Version 2 added the content hash; files of version 1 are misses (their magic differs).
constexpr char magic[8] = {'N', 'E', 'P', 'H', 'C', 'A', 'C', '2'};
constexpr const char* prefix = "cache-";
constexpr const char* temporary_prefix = ".tmp-";
constexpr const char* suffix = ".bin";
// A temporary file this old is left over whatever its PID says (PIDs are reused, and a writer
// in another PID namespace may share the directory): writing even 256 MiB takes seconds.
constexpr long stale_temporary_seconds = 3600;

using core::fnv1a;

// The hash stored with a payload: of its bytes, seeded with the key's hash, so that a file
// whose key and values were both replaced still fails unless the pair was written together.
std::uint64_t content_hash(const std::string& key, const float* values, std::size_t count) {
  return core::block_hash(values, count * sizeof(float), fnv1a(key));
}

// Bytes before the values: magic, key length, key, value count, content hash.
std::size_t header_bytes(const std::string& key) { return sizeof magic + 8 + key.size() + 8 + 8; }

using Descriptor = core::FileDescriptor;

bool all_finite(const std::vector<float>& values) {
  return std::all_of(values.begin(), values.end(), [](float v) { return std::isfinite(v); });
}

bool has_affixes(const std::string& name, const std::string& head, const std::string& tail) {
  return name.size() >= head.size() + tail.size() && name.compare(0, head.size(), head) == 0 &&
         name.compare(name.size() - tail.size(), tail.size(), tail) == 0;
}

// A temporary file ".tmp-PID-N.bin" left by a writer that was killed before its rename: its
// process no longer exists (kill(PID, 0) says ESRCH; EPERM means it exists under another
// user), or it is older than stale_temporary_seconds.
bool stale_temporary(const std::string& name, const struct stat& status) {
  if (std::difftime(std::time(nullptr), status.st_mtime) > stale_temporary_seconds) return true;
  const char* digits = name.c_str() + std::strlen(temporary_prefix);
  char* end = nullptr;
  errno = 0;
  const long pid = std::strtol(digits, &end, 10);
  if (errno != 0 || end == digits || *end != '-' || pid <= 0 || pid != static_cast<pid_t>(pid)) return false;
  return ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
}

}  // namespace

const std::string& program_fingerprint() {
  static const std::string fingerprint = [] {
    Descriptor fd(::open("/proc/self/exe", O_RDONLY | O_CLOEXEC));
    struct stat status {};
    if (fd.get() < 0 || ::fstat(fd.get(), &status) != 0 || !S_ISREG(status.st_mode)) return std::string();
    std::vector<unsigned char> bytes(static_cast<std::size_t>(status.st_size));
    if (!core::read_exactly(fd.get(), bytes.data(), bytes.size())) return std::string();
    return core::hex_digits(core::block_hash(bytes.data(), bytes.size()));
  }();
  return fingerprint;
}

fs::path default_cache_directory() {
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg && fs::path(xdg).is_absolute())
    return fs::path(xdg) / "nephele";
  if (const char* home = std::getenv("HOME"); home && *home) return fs::path(home) / ".cache" / "nephele";
  return {};
}

FloatCache::FloatCache(fs::path directory, std::uintmax_t cap_bytes)
    : directory_(std::move(directory)), cap_bytes_(cap_bytes) {}

fs::path FloatCache::file_of(const std::string& key) const {
  return directory_ / (prefix + core::hex_digits(fnv1a(key)) + suffix);
}

std::optional<std::vector<float>> FloatCache::load(const std::string& key, std::size_t count) const {
  const std::size_t header = header_bytes(key);
  if (count > (static_cast<std::size_t>(PTRDIFF_MAX) - header) / sizeof(float)) return std::nullopt;
  const fs::path path = file_of(key);
  // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer, forever;
  // O_NOFOLLOW: a symbolic link is not an entry this cache wrote (rename never makes one).
  Descriptor fd(::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOFOLLOW | O_CLOEXEC));
  if (fd.get() < 0) return std::nullopt;
  // Only a regular file of exactly the size the key and count imply (this also rules out a
  // device, directory or socket, and a truncated or longer file).
  struct stat status {};
  if (::fstat(fd.get(), &status) != 0 || !S_ISREG(status.st_mode) ||
      static_cast<std::uintmax_t>(status.st_size) != header + count * sizeof(float))
    return std::nullopt;
  std::string head(header, '\0');
  if (!core::read_exactly(fd.get(), head.data(), header)) return std::nullopt;
  std::uint64_t key_length = 0, stored_count = 0, stored_hash = 0;
  const char* p = head.data();
  if (std::memcmp(p, magic, sizeof magic) != 0) return std::nullopt;
  std::memcpy(&key_length, p + sizeof magic, 8);
  if (key_length != key.size() || head.compare(sizeof magic + 8, key.size(), key) != 0) return std::nullopt;
  std::memcpy(&stored_count, p + sizeof magic + 8 + key.size(), 8);
  std::memcpy(&stored_hash, p + sizeof magic + 16 + key.size(), 8);
  if (stored_count != count) return std::nullopt;
  std::vector<float> values(count);
  if (!core::read_exactly(fd.get(), values.data(), count * sizeof(float))) return std::nullopt;
  // Damaged bytes (a flipped bit, a torn write after a crash) or values that are not numbers:
  // a miss, which the caller's store replaces.
  if (content_hash(key, values.data(), count) != stored_hash) return std::nullopt;
  if (!all_finite(values)) return std::nullopt;
  ::futimens(fd.get(), nullptr);  // used: trimmed last (the file read, whatever its name is now)
  return values;
}

bool FloatCache::store(const std::string& key, const std::vector<float>& values) const {
  // load() never serves non-finite values, so storing them would only take room.
  if (!all_finite(values)) return false;
  std::error_code error;
  fs::create_directories(directory_, error);
  if (error) return false;
  const fs::path final_path = file_of(key);
  // A name of its own per writer, so that concurrent writers never share a temporary file; the
  // PID lets the trim tell a killed writer's leftovers from a live writer's file.
  const fs::path temporary = directory_ / (temporary_prefix + std::to_string(::getpid()) + "-" +
                                           std::to_string(std::random_device{}()) + suffix);
  {
    // O_EXCL: a new regular file, never something already there under that name (a FIFO
    // would block the open, a symbolic link would redirect the write).
    Descriptor fd(::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666));
    if (fd.get() < 0) return false;
    std::string head(header_bytes(key), '\0');
    const std::uint64_t key_length = key.size(), count = values.size();
    const std::uint64_t hash = content_hash(key, values.data(), values.size());
    char* p = head.data();
    std::memcpy(p, magic, sizeof magic);
    std::memcpy(p + sizeof magic, &key_length, 8);
    std::memcpy(p + sizeof magic + 8, key.data(), key.size());
    std::memcpy(p + sizeof magic + 8 + key.size(), &count, 8);
    std::memcpy(p + sizeof magic + 16 + key.size(), &hash, 8);
    const bool written = core::write_exactly(fd.get(), head.data(), head.size()) &&
                         core::write_exactly(fd.get(), values.data(), values.size() * sizeof(float));
    if (!fd.close() || !written) {
      fs::remove(temporary, error);
      return false;
    }
  }
  // rename() replaces whatever has the name (a file, a FIFO, a symbolic link) at once: readers
  // see the old or the new entry, whole. Over a directory it fails: the cache is skipped.
  if (::rename(temporary.c_str(), final_path.c_str()) != 0) {
    fs::remove(temporary, error);
    return false;
  }
  trim(final_path.filename().string());
  return true;
}

void FloatCache::trim(const std::string& keep) const {
  struct Entry {
    fs::path path;
    struct timespec time;
    std::uintmax_t bytes;
  };
  std::vector<Entry> entries;
  std::uintmax_t total = 0;
  std::error_code error;
  for (const auto& item : fs::directory_iterator(directory_, error)) {
    const std::string name = item.path().filename().string();
    const bool entry = has_affixes(name, prefix, suffix), temporary = has_affixes(name, temporary_prefix, suffix);
    if (!entry && !temporary) continue;
    // lstat, not stat: a symbolic link is judged as itself, never by its target's size or time.
    struct stat status {};
    if (::lstat(item.path().c_str(), &status) != 0) continue;  // gone meanwhile
    if (S_ISDIR(status.st_mode)) continue;                     // not the cache's to remove
    if (!S_ISREG(status.st_mode) || (temporary && stale_temporary(name, status))) {
      // A link, FIFO, socket or device under the cache's names (unlink removes only the name),
      // or a killed writer's temporary file.
      ::unlink(item.path().c_str());
      continue;
    }
    const auto bytes = static_cast<std::uintmax_t>(status.st_size);
    total += bytes;
    // A live writer's temporary file counts but is not ours to remove; nor is the entry just
    // stored, even when it alone passes the cap.
    if (temporary || name == keep) continue;
    entries.push_back({item.path(), status.st_mtim, bytes});
  }
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    return a.time.tv_sec != b.time.tv_sec ? a.time.tv_sec < b.time.tv_sec : a.time.tv_nsec < b.time.tv_nsec;
  });
  for (const Entry& e : entries) {
    if (total <= cap_bytes_) break;
    if (::unlink(e.path.c_str()) == 0) total -= e.bytes;
  }
}

}  // namespace nephele::files
