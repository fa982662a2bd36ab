// The disk cache of noise volumes (src/io/noise_cache.hpp) and its use by nephele render.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <thread>

#include "cli_support.hpp"
#include "io/noise_cache.hpp"

namespace fs = std::filesystem;
using namespace nephele;
using test::read_file;
using test::Run;
using test::TemporaryDirectory;

TEST_CASE("the float cache returns what was stored and misses on another key, count or a damaged file",
          "[cache]") {
  TemporaryDirectory dir(true);
  const io::FloatCache cache(dir.path / "nephele");
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

TEST_CASE("the float cache removes the least recently used files beyond its cap", "[cache]") {
  TemporaryDirectory dir(true);
  // Each file: 8 magic + 8 + 1 key + 8 count + 4000 values = 4025 bytes; the cap holds two.
  const std::uintmax_t file_bytes = 8 + 8 + 1 + 8 + 1000 * 4;
  const io::FloatCache cache(dir.path, 2 * file_bytes + 100);
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

TEST_CASE("render reuses the cached noise volume with the same image, and --no-cache leaves no cache",
          "[cache][cli]") {
  TemporaryDirectory cache_home(true), out(true), unused_home(true);
  const std::string arguments = " render --view gurten --size 32x18 --view-steps 6 --light-steps 2 --verbose --quiet --out ";
  auto render = [&](const fs::path& home, const std::string& name, const std::string& extra = "") {
    return test::run_command("XDG_CACHE_HOME=" + home.string() + " " + NEPHELE_EXECUTABLE + arguments +
                             (out.path / name).string() + extra);
  };
  const Run first = render(cache_home.path, "first.png");
  INFO(first.output);
  REQUIRE(first.exit_code == 0);
  CHECK(first.output.find("noise volume: made and cached") != std::string::npos);
  const Run second = render(cache_home.path, "second.png");
  INFO(second.output);
  REQUIRE(second.exit_code == 0);
  CHECK(second.output.find("noise volume: from the cache") != std::string::npos);
  const Run uncached = render(unused_home.path, "uncached.png", " --no-cache");
  REQUIRE(uncached.exit_code == 0);
  // (Mesa keeps its own shader cache there; nephele's directory must not appear.)
  CHECK_FALSE(fs::exists(unused_home.path / "nephele"));
  CHECK(read_file(out.path / "first.png") == read_file(out.path / "second.png"));
  CHECK(read_file(out.path / "first.png") == read_file(out.path / "uncached.png"));
}
