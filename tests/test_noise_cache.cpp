// The disk cache (src/files/float_cache.hpp) of noise volumes (src/io/noise_cache.hpp), generated covers
// (src/io/cover_cache.hpp) and the orbit view's derived maps (src/io/planet_textures.hpp), and its use by
// nephele render.
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <future>
#include <limits>
#include <thread>

#include "cli_support.hpp"
#include "core/hash.hpp"
#include "files/float_cache.hpp"
#include "cover/cover_parameters.hpp"
#include "cover/surface_bias.hpp"
#include "io/cover_cache.hpp"
#include "io/noise_cache.hpp"

namespace fs = std::filesystem;
using namespace nephele;
using test::read_file;
using test::Run;
using test::TemporaryDirectory;

TEST_CASE("the float cache returns what was stored and misses on another key, count or a damaged file",
          "[fast][cache]") {
  TemporaryDirectory dir(true);
  const files::FloatCache cache(dir.path / "nephele");
  const std::vector<float> values = {1.0f, -2.5f, 3.25f, 0.0f};
  CHECK_FALSE(cache.load("a", 4));
  REQUIRE(cache.store("a", values));
  CHECK(cache.load("a", 4) == values);
  CHECK_FALSE(cache.load("b", 4));
  CHECK_FALSE(cache.load("a", 3));
  // Replacing keeps one file, whole.
  REQUIRE(cache.store("a", {5.0f, 6.0f, 7.0f, 8.0f}));
  CHECK(cache.load("a", 4) == std::vector<float>{5.0f, 6.0f, 7.0f, 8.0f});
  // A truncated file is a miss, as is one with bytes after its values.
  const fs::path file = cache.file_of("a");
  const std::string bytes = read_file(file);
  std::ofstream(file, std::ios::binary) << bytes.substr(0, bytes.size() - 2);
  CHECK_FALSE(cache.load("a", 4));
  std::ofstream(file, std::ios::binary) << bytes << "x";
  CHECK_FALSE(cache.load("a", 4));
  // No temporary files are left.
  for (const auto& entry : fs::directory_iterator(cache.directory()))
    CHECK(entry.path().filename().string().rfind(".tmp-", 0) != 0);
}

TEST_CASE("the float cache removes the least recently used files beyond its cap", "[fast][cache]") {
  TemporaryDirectory dir(true);
  // Each file: 8 magic + 8 + 1 key + 8 count + 8 hash + 4000 values = 4033 bytes; the cap holds two.
  const std::uintmax_t file_bytes = 8 + 8 + 1 + 8 + 8 + 1000 * 4;
  const files::FloatCache cache(dir.path, 2 * file_bytes + 100);
  const std::vector<float> values(1000, 0.5f);
  REQUIRE(cache.store("a", values));
  REQUIRE(fs::file_size(cache.file_of("a")) == file_bytes);
  REQUIRE(cache.store("b", values));
  // Order by modification time: the file system's clock may be coarse, so set it.
  const auto now = fs::file_time_type::clock::now();
  fs::last_write_time(cache.file_of("a"), now - std::chrono::hours(2));
  fs::last_write_time(cache.file_of("b"), now - std::chrono::hours(1));
  REQUIRE(cache.load("a", 1000));  // a is now the most recently used
  REQUIRE(cache.store("c", values));
  CHECK(fs::exists(cache.file_of("a")));
  CHECK_FALSE(fs::exists(cache.file_of("b")));
  CHECK(fs::exists(cache.file_of("c")));
}

namespace {

// Mesa keeps its shader cache under XDG_CACHE_HOME as well. The renders below move nephele's
// cache and name Mesa's where it was, so that Mesa does not compile every shader anew (about
// 4 s a render on llvmpipe); nephele's cache is what they test.
std::string mesa_cache_where_it_was() {
  const auto variable = [](const char* name) {
    const char* value = std::getenv(name);
    return std::string(value ? value : "");
  };
  std::string directory = variable("MESA_SHADER_CACHE_DIR");
  if (directory.empty() && !variable("XDG_CACHE_HOME").empty())
    directory = variable("XDG_CACHE_HOME") + "/mesa_shader_cache";
  if (directory.empty()) directory = variable("HOME") + "/.cache/mesa_shader_cache";
  return "MESA_SHADER_CACHE_DIR=" + directory;
}

// nephele with `arguments`, its cache under `home` and Mesa's where it was.
Run render_with_cache_home(const fs::path& home, const std::string& arguments) {
  return test::run_as_given(mesa_cache_where_it_was() + " XDG_CACHE_HOME=" + home.string(), arguments);
}

}  // namespace

TEST_CASE("render reuses the cached noise volume and global cover with the same image, and --no-cache leaves no cache",
          "[cache][cli]") {
  TemporaryDirectory cache_home(true), out(true), unused_home(true);
  const std::string arguments =
      " render --view gurten --time 2026-06-21T08:00Z --size 32x18 --view-steps 6 --light-steps 2 --terrain flat "
      "--land-cover none --verbose --quiet --out ";  // morning: no convective volumes to build, which the cache does
                                                     // not hold; no ground to load, which it does not hold either
  auto render = [&](const fs::path& home, const std::string& name, const std::string& extra = "") {
    return render_with_cache_home(home, arguments + (out.path / name).string() + extra);
  };
  const Run first = render(cache_home.path, "first.png");
  INFO(first.output);
  REQUIRE(first.exit_code == 0);
  CHECK(first.output.find("noise volume: made and cached") != std::string::npos);
  // The global cover that stands in for the weather is cached as well (io/cover_cache.hpp).
  CHECK(first.output.find("global cover: made and cached") != std::string::npos);
  const Run second = render(cache_home.path, "second.png");
  INFO(second.output);
  REQUIRE(second.exit_code == 0);
  CHECK(second.output.find("noise volume: from the cache") != std::string::npos);
  CHECK(second.output.find("global cover: from the cache") != std::string::npos);
  const Run uncached = render(unused_home.path, "uncached.png", " --no-cache");
  REQUIRE(uncached.exit_code == 0);
  // (Mesa keeps its own shader cache there; nephele's directory must not appear.)
  CHECK_FALSE(fs::exists(unused_home.path / "nephele"));
  CHECK(read_file(out.path / "first.png") == read_file(out.path / "second.png"));
  CHECK(read_file(out.path / "first.png") == read_file(out.path / "uncached.png"));
}

namespace {

// Bytes of a cache file for a one-letter key and n values (the layout in files/float_cache.hpp).
constexpr std::uintmax_t header_bytes_one_letter_key = 8 + 8 + 1 + 8 + 8;
std::uintmax_t entry_bytes(std::size_t n) { return header_bytes_one_letter_key + n * sizeof(float); }

// Overwrites `bytes` at `offset` in the file, in place.
void patch(const fs::path& file, std::uintmax_t offset, const void* bytes, std::size_t size) {
  std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
  f.seekp(static_cast<std::streamoff>(offset));
  f.write(static_cast<const char*>(bytes), static_cast<std::streamsize>(size));
  REQUIRE(f.good());
}

std::vector<float> ramp(std::size_t n) {
  std::vector<float> values(n);
  for (std::size_t i = 0; i < n; ++i) values[i] = 0.25f * static_cast<float>(i) - 7.0f;
  return values;
}

void write_bytes(const fs::path& file, std::uintmax_t size) {
  std::ofstream(file, std::ios::binary) << std::string(size, 'x');
}

// The only file named cache-*.bin in `directory` whose key begins with `kind` (the layout in
// files/float_cache.hpp: 8 bytes of magic, 8 of the key's length, the key); empty when there is
// none or several.
fs::path the_entry(const fs::path& directory, const std::string& kind) {
  fs::path found;
  int n = 0;
  for (const auto& item : fs::directory_iterator(directory))
    if (item.path().filename().string().rfind("cache-", 0) == 0 &&
        read_file(item.path()).compare(16, kind.size(), kind) == 0) {
      found = item.path();
      ++n;
    }
  return n == 1 ? found : fs::path();
}

}  // namespace

TEST_CASE("a hash's hex digits are its 16 nibbles, most significant first", "[fast][cache]") {
  CHECK(core::hex_digits(0) == "0000000000000000");
  CHECK(core::hex_digits(0x0123456789abcdefull) == "0123456789abcdef");
  CHECK(core::hex_digits(~0ull) == "ffffffffffffffff");
  // A cache file's name carries its key's FNV-1a so.
  const files::FloatCache cache("/nowhere");
  CHECK(cache.file_of("a").filename() == "cache-" + core::hex_digits(core::fnv1a(std::string("a"))) + ".bin");
}

TEST_CASE("the payload hash changes with any one flipped bit and with the length or seed", "[fast][cache]") {
  std::vector<unsigned char> bytes(101);  // three 32-byte blocks and a tail of a word and 5 bytes
  for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<unsigned char>(i * 37 + 11);
  const std::uint64_t h = core::block_hash(bytes.data(), bytes.size(), 5);
  CHECK(core::block_hash(bytes.data(), bytes.size(), 5) == h);
  CHECK(core::block_hash(bytes.data(), bytes.size(), 6) != h);
  int unchanged = 0;
  for (std::size_t i = 0; i < bytes.size(); ++i)
    for (int bit = 0; bit < 8; ++bit) {
      bytes[i] ^= static_cast<unsigned char>(1 << bit);
      unchanged += core::block_hash(bytes.data(), bytes.size(), 5) == h;
      bytes[i] ^= static_cast<unsigned char>(1 << bit);
    }
  CHECK(unchanged == 0);
  // Zero bytes of different lengths (the tail is zero-padded; the length tells them apart).
  std::vector<std::uint64_t> of_length;
  const std::vector<unsigned char> zeros(70, 0);
  for (std::size_t n = 0; n <= zeros.size(); ++n) of_length.push_back(core::block_hash(zeros.data(), n));
  std::sort(of_length.begin(), of_length.end());
  CHECK(std::adjacent_find(of_length.begin(), of_length.end()) == of_length.end());
}

TEST_CASE("a cache entry whose payload was altered is rebuilt and not served", "[fast][cache]") {
  TemporaryDirectory dir(true);
  const files::FloatCache cache(dir.path);
  const std::vector<float> values = ramp(1000);
  const fs::path file = cache.file_of("a");
  REQUIRE(cache.store("a", values));
  const std::string good = read_file(file);
  // The values fill the end of the file; the hash precedes them.
  const std::uintmax_t payload = good.size() - 4000;
  SECTION("one flipped bit") {
    const char flipped = static_cast<char>(good[payload + 2001] ^ 0x10);
    patch(file, payload + 2001, &flipped, 1);
  }
  SECTION("a value overwritten with NaN") {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    patch(file, payload + 4 * 500, &nan, sizeof nan);
  }
  SECTION("a value overwritten with infinity and the hash made to match") {
    std::vector<float> bad = values;
    bad[500] = std::numeric_limits<float>::infinity();
    const std::uint64_t hash = core::block_hash(bad.data(), bad.size() * sizeof(float), core::fnv1a("a"));
    patch(file, payload + 4 * 500, &bad[500], sizeof(float));
    patch(file, payload - 8, &hash, sizeof hash);
  }
  SECTION("the hash overwritten") {
    const std::uint64_t hash = 0x0123456789abcdefull;
    patch(file, payload - 8, &hash, sizeof hash);
  }
  SECTION("a file of the previous version (no hash)") {
    // NEPHCAC1: magic, key length, key, count, values.
    std::string old = "NEPHCAC1";
    const std::uint64_t key_length = 1, count = 1000;
    old.append(reinterpret_cast<const char*>(&key_length), 8).append("a");
    old.append(reinterpret_cast<const char*>(&count), 8);
    old.append(reinterpret_cast<const char*>(values.data()), 4000);
    std::ofstream(file, std::ios::binary | std::ios::trunc) << old;
  }
  SECTION("a payload zeroed at the same size (a torn write)") {
    const std::string zeros(4000, '\0');
    patch(file, payload, zeros.data(), zeros.size());
  }
  CHECK_FALSE(cache.load("a", 1000));
  // The next store replaces the entry, which is then served again.
  REQUIRE(cache.store("a", values));
  CHECK(read_file(file) == good);
  CHECK(cache.load("a", 1000) == values);
}

TEST_CASE("the float cache refuses to store values that are not finite", "[fast][cache]") {
  TemporaryDirectory dir(true);
  const files::FloatCache cache(dir.path);
  CHECK_FALSE(cache.store("a", {1.0f, std::numeric_limits<float>::quiet_NaN()}));
  CHECK_FALSE(cache.store("b", {-std::numeric_limits<float>::infinity()}));
  CHECK(dir.empty());
}

TEST_CASE("a FIFO named like a cache entry is a miss without blocking and a store replaces it", "[fast][cache]") {
  TemporaryDirectory dir(true);
  const files::FloatCache cache(dir.path);
  const fs::path file = cache.file_of("a");
  REQUIRE(::mkfifo(file.c_str(), 0600) == 0);
  // Opening a FIFO for reading waits for a writer: if the load has not returned after 20 s,
  // open the FIFO's writing end to release it, so that the test fails instead of hanging.
  auto load = std::async(std::launch::async, [&] { return cache.load("a", 4); });
  const bool returned = load.wait_for(std::chrono::seconds(20)) == std::future_status::ready;
  if (!returned) {
    const int writer = ::open(file.c_str(), O_WRONLY | O_NONBLOCK);
    if (writer >= 0) ::close(writer);
  }
  CHECK(returned);
  CHECK_FALSE(load.get());
  const std::vector<float> values = {1.0f, 2.0f, 3.0f, 4.0f};
  REQUIRE(cache.store("a", values));
  CHECK(fs::is_regular_file(fs::symlink_status(file)));
  CHECK(cache.load("a", 4) == values);
}

TEST_CASE("a symbolic link or directory named like a cache entry is a miss and never written through",
          "[fast][cache]") {
  TemporaryDirectory dir(true), elsewhere(true);
  const files::FloatCache cache(dir.path), other(elsewhere.path);
  const std::vector<float> values = ramp(8);
  // A link to a valid entry of the same key: not followed (rename never makes a link).
  REQUIRE(other.store("a", values));
  fs::create_symlink(other.file_of("a"), cache.file_of("a"));
  CHECK_FALSE(cache.load("a", 8));
  REQUIRE(cache.store("a", ramp(8)));
  CHECK(fs::is_regular_file(fs::symlink_status(cache.file_of("a"))));
  CHECK(fs::file_size(other.file_of("a")) == entry_bytes(8));  // the target is untouched
  // A directory: a miss; the store cannot replace it and skips the cache.
  fs::create_directory(cache.file_of("b"));
  CHECK_FALSE(cache.load("b", 8));
  CHECK_FALSE(cache.store("b", values));
  CHECK(fs::is_directory(cache.file_of("b")));
  for (const auto& entry : fs::directory_iterator(cache.directory()))
    CHECK(entry.path().filename().string().rfind(".tmp-", 0) != 0);
}

TEST_CASE("the cache trim removes temporary files of killed writers and counts those of live ones", "[fast][cache]") {
  TemporaryDirectory dir(true);
  const std::uintmax_t file_bytes = entry_bytes(1000);
  const files::FloatCache cache(dir.path, 2 * file_bytes + 100);
  const auto now = fs::file_time_type::clock::now();
  const std::string pid = std::to_string(::getpid());
  // 2^22 + 1 is above the kernel's largest PID (PID_MAX_LIMIT): no such process exists.
  const fs::path dead = dir.path / ".tmp-4194305-1.bin", old = dir.path / (".tmp-" + pid + "-2.bin"),
                 live = dir.path / (".tmp-" + pid + "-3.bin");
  write_bytes(dead, 50);
  write_bytes(old, 50);
  fs::last_write_time(old, now - std::chrono::hours(2));  // this process's PID, but too old
  write_bytes(live, file_bytes);
  REQUIRE(cache.store("a", ramp(1000)));
  CHECK_FALSE(fs::exists(dead));
  CHECK_FALSE(fs::exists(old));
  CHECK(fs::exists(live));
  fs::last_write_time(cache.file_of("a"), now - std::chrono::hours(1));
  // a, the live temporary file and b pass the cap: a, the oldest entry, goes.
  REQUIRE(cache.store("b", ramp(1000)));
  CHECK_FALSE(fs::exists(cache.file_of("a")));
  CHECK(fs::exists(cache.file_of("b")));
  CHECK(fs::exists(live));
}

TEST_CASE("the cache trim ignores what a symbolic link points to and never removes the entry just stored",
          "[fast][cache]") {
  TemporaryDirectory dir(true), elsewhere(true);
  const std::uintmax_t file_bytes = entry_bytes(1000);
  const files::FloatCache cache(dir.path, 3 * file_bytes + 100);
  REQUIRE(cache.store("a", ramp(1000)));
  REQUIRE(cache.store("b", ramp(1000)));
  // A large target dated in the future behind a name of the cache's: by its target it would
  // pass the cap and be the most recently used, so that every real entry would go first.
  const fs::path big = elsewhere.path / "big.bin";
  write_bytes(big, 1);
  fs::resize_file(big, 64 * file_bytes);
  fs::last_write_time(big, fs::file_time_type::clock::now() + std::chrono::hours(24));
  const fs::path link = dir.path / "cache-00000000000000ff.bin";
  fs::create_symlink(big, link);
  REQUIRE(cache.store("c", ramp(1000)));
  CHECK(fs::exists(cache.file_of("a")));
  CHECK(fs::exists(cache.file_of("b")));
  CHECK(fs::exists(cache.file_of("c")));
  CHECK_FALSE(fs::exists(fs::symlink_status(link)));  // the link is removed, its target kept
  CHECK(fs::file_size(big) == 64 * file_bytes);
  // An entry larger than the whole cap stays; the others go.
  const files::FloatCache tiny(dir.path, 100);
  REQUIRE(tiny.store("d", ramp(1000)));
  CHECK(tiny.load("d", 1000) == ramp(1000));
  CHECK_FALSE(fs::exists(cache.file_of("a")));
  CHECK_FALSE(fs::exists(cache.file_of("b")));
  CHECK_FALSE(fs::exists(cache.file_of("c")));
}

namespace {

const char* const small_render =
    " render --view gurten --size 32x18 --view-steps 6 --light-steps 2 --terrain flat"
    " --land-cover none --verbose --quiet --out ";

// nephele render with its cache under `home` (XDG_CACHE_HOME).
Run render_with_cache(const fs::path& home, const fs::path& png) {
  return test::run_as_given(mesa_cache_where_it_was() + " XDG_CACHE_HOME=" + home.string(),
                            small_render + png.string());
}

// The same as a process stopped after 120 s, so that a render that blocks fails (exit code 124)
// instead of hanging the test.
Run render_with_cache_or_timeout(const fs::path& home, const fs::path& png) {
  return test::run_command("timeout 120 env " + mesa_cache_where_it_was() + " XDG_CACHE_HOME=" + home.string() + " " +
                           NEPHELE_EXECUTABLE + small_render + png.string());
}

}  // namespace

// One first render serves both damages (a render on llvmpipe takes about 1.5 s, most of it the
// process's set-up).
TEST_CASE("render rebuilds a cached noise volume whose bytes were altered, and is not blocked by a FIFO in its place",
          "[cache][cli]") {
  TemporaryDirectory cache_home(true), out(true);
  const Run first = render_with_cache(cache_home.path, out.path / "first.png");
  INFO(first.output);
  REQUIRE(first.exit_code == 0);
  // (The render's global cover has an entry of its own beside the noise volume's.)
  const fs::path entry = the_entry(cache_home.path / "nephele", "noise_volume");
  REQUIRE_FALSE(entry.empty());
  const std::string good = read_file(entry);
  {
    INFO("altered bytes");
    const char flipped = static_cast<char>(good[good.size() - 4096] ^ 0x40);
    patch(entry, good.size() - 4096, &flipped, 1);
    const Run second = render_with_cache(cache_home.path, out.path / "second.png");
    INFO(second.output);
    REQUIRE(second.exit_code == 0);
    CHECK(second.output.find("noise volume: made and cached") != std::string::npos);
    CHECK(read_file(entry) == good);
    CHECK(read_file(out.path / "first.png") == read_file(out.path / "second.png"));
  }
  {
    INFO("a FIFO in place of the entry");
    fs::remove(entry);
    REQUIRE(::mkfifo(entry.c_str(), 0600) == 0);
    const Run third = render_with_cache_or_timeout(cache_home.path, out.path / "third.png");
    INFO(third.output);
    REQUIRE(third.exit_code == 0);  // 124: it blocked until the timeout
    CHECK(third.output.find("noise volume: made and cached") != std::string::npos);
    CHECK(fs::is_regular_file(fs::symlink_status(entry)));
    CHECK(read_file(entry) == good);
    CHECK(read_file(out.path / "first.png") == read_file(out.path / "third.png"));
  }
}

TEST_CASE("a cover's cache key changes with its parameters, its mask's values and the program, not with names alone",
          "[fast][cache]") {
  // The program's own file is readable here, so the key carries its fingerprint.
  const std::string program = files::program_fingerprint();
  REQUIRE(program.size() == 16);
  cover::CoverParameters p;
  p.size = 32;
  const std::string key = io::cover_cache_key(p);
  CHECK(key == io::cover_cache_key(p));
  CHECK(key.find("program " + program) != std::string::npos);
  cover::CoverParameters other_seed = p;
  other_seed.seed = p.seed + 1;
  CHECK(io::cover_cache_key(other_seed) != key);
  cover::CoverParameters other_time = p;
  other_time.time = "2026-01-01T00:00:00Z";
  CHECK(io::cover_cache_key(other_time) != key);
  cover::CoverParameters other_size = p;
  other_size.size = 64;
  CHECK(io::cover_cache_key(other_size) != key);
  // Two masks of one name and size but other values: other covers, other keys.
  auto mask = std::make_shared<cover::SurfaceMask>();
  mask->columns = 4;
  mask->rows = 2;
  mask->land = std::vector<float>(8, 0.0f);
  mask->source = "a mask";
  cover::CoverParameters with_mask = p;
  with_mask.surface = mask;
  auto changed = std::make_shared<cover::SurfaceMask>(*mask);
  changed->land[3] = 1.0f;
  cover::CoverParameters with_changed = p;
  with_changed.surface = changed;
  CHECK(io::cover_cache_key(with_mask) != key);
  CHECK(io::cover_cache_key(with_changed) != io::cover_cache_key(with_mask));
  // A profile of one name with other fractions.
  cover::CoverParameters other_profile = p;
  other_profile.profile.fraction.back() += 0.01;
  CHECK(io::cover_cache_key(other_profile) != key);
}

TEST_CASE("render --view orbit reads its cover and its derived maps from the cache the second time, the same image",
          "[cache][cli]") {
  TemporaryDirectory cache_home(true), out(true), unused_home(true);
  const std::string arguments = " render --view orbit --size 64x36 --verbose --quiet --out ";
  auto render = [&](const fs::path& home, const std::string& name, const std::string& extra = "") {
    return render_with_cache_home(home, arguments + (out.path / name).string() + extra);
  };
  const Run first = render(cache_home.path, "first.png");
  INFO(first.output);
  REQUIRE(first.exit_code == 0);
  CHECK(first.output.find("global cover: made and cached") != std::string::npos);
  CHECK(first.output.find("maps from the cache") == std::string::npos);
  const Run second = render(cache_home.path, "second.png");
  INFO(second.output);
  REQUIRE(second.exit_code == 0);
  CHECK(second.output.find("global cover: from the cache") != std::string::npos);
  // The default maps (xplanet's day and night, ETOPO5's water and relief) as decoded and derived.
  CHECK(second.output.find("maps from the cache: sea_free_day etopo5_water etopo5_relief night_decoded") !=
        std::string::npos);
  const Run uncached = render(unused_home.path, "uncached.png", " --no-cache");
  REQUIRE(uncached.exit_code == 0);
  CHECK_FALSE(fs::exists(unused_home.path / "nephele"));
  CHECK(read_file(out.path / "first.png") == read_file(out.path / "second.png"));
  CHECK(read_file(out.path / "first.png") == read_file(out.path / "uncached.png"));
}
