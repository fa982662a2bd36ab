// Output sets appear whole or not at all (docs/formats.md, "Output sets").
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "io/atomic_output.hpp"

extern char** environ;

namespace fs = std::filesystem;
using namespace nephele;
using test::read_file;
using test::run;
using test::run_command;
using test::TemporaryDirectory;

namespace {

// A process id that no process has: above the kernel's largest pid_max (2^22).
constexpr const char* dead_pid = "2147483646";

void put(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  io::write_text_file(path, text);
}

// Entries of `place` whose name starts with `prefix`.
std::vector<fs::path> entries_starting(const fs::path& place, const std::string& prefix) {
  std::vector<fs::path> found;
  for (const auto& entry : fs::directory_iterator(place))
    if (entry.path().filename().string().compare(0, prefix.size(), prefix) == 0) found.push_back(entry.path());
  return found;
}

// The temporary directories of sets opened for `out` (Scope::directory: next to it).
std::vector<fs::path> temporaries_of(const fs::path& out) {
  return entries_starting(out.parent_path(), ".nephele-" + out.filename().string() + "-");
}

// Starts nephele with `arguments`, output discarded; returns its process id.
pid_t spawn_nephele(const std::vector<std::string>& arguments) {
  std::vector<std::string> words{NEPHELE_EXECUTABLE};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int error = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (error != 0) throw std::runtime_error("could not start nephele");
  return pid;
}

// Polls until a temporary directory of `out` exists, or the child ended (then: none found).
std::vector<fs::path> wait_for_temporary(pid_t child, const fs::path& out) {
  for (;;) {
    auto found = temporaries_of(out);
    if (!found.empty()) return found;
    int status = 0;
    if (waitpid(child, &status, WNOHANG) == child) return {};
    usleep(1000);
  }
}

// The set of a run into `out` (generate's files) with `text` in every file.
void write_generate_like_set(io::OutputSet& set, const std::string& text) {
  for (const char* name : {"cover_px.exr", "cover_equirect.png", "cover.json"}) set.write(name, text);
}

}  // namespace

TEST_CASE("a set that fails before its commit leaves the complete old set and no temporary", "[output]") {
  TemporaryDirectory place(true);
  const fs::path out = place.path / "cubemaps";
  {
    io::OutputSet set(out, io::OutputSet::Scope::directory);
    write_generate_like_set(set, "old");
    set.commit();
  }
  try {
    io::OutputSet set(out, io::OutputSet::Scope::directory);
    set.write("cover_px.exr", "new");
    set.write("cover_equirect.png", "new");
    throw std::runtime_error("the writer of cover.json failed");  // as a failed encode or write would
  } catch (const std::runtime_error&) {
  }
  for (const char* name : {"cover_px.exr", "cover_equirect.png", "cover.json"}) CHECK(read_file(out / name) == "old");
  CHECK(temporaries_of(out).empty());
}

TEST_CASE("a write the set cannot make throws naming the final path and keeps the old set", "[output]") {
  TemporaryDirectory place(true);
  const fs::path out = place.path / "cubemaps";
  {
    io::OutputSet set(out, io::OutputSet::Scope::directory);
    write_generate_like_set(set, "old");
    set.commit();
  }
  {
    io::OutputSet set(out, io::OutputSet::Scope::directory);
    set.write("cover_px.exr", "new");
    const std::string too_long(300, 'x');  // beyond NAME_MAX (255): the file system refuses it
    try {
      set.write(too_long + ".json", "new");
      FAIL("no error");
    } catch (const std::runtime_error& e) {
      CHECK_THAT(e.what(), Catch::Contains((out / too_long).string()));
    }
  }
  CHECK(read_file(out / "cover_px.exr") == "old");
  CHECK(temporaries_of(out).empty());
}

TEST_CASE("files in the output directory that are not part of the set survive its commit", "[output]") {
  TemporaryDirectory place(true);
  const fs::path out = place.path / "cubemaps";
  put(out / "README.md", "readme");
  put(out / "notes" / "a.txt", "notes");
  put(out / "cover.json", "old");
  fs::create_symlink("README.md", out / "link.md");
  struct stat before {};
  ::stat((out / "README.md").c_str(), &before);
  {
    io::OutputSet set(out, io::OutputSet::Scope::directory);
    write_generate_like_set(set, "new");
    // Until the commit, readers see only the old set.
    CHECK_FALSE(fs::exists(out / "cover_px.exr"));
    set.commit();
  }
  CHECK(read_file(out / "cover.json") == "new");
  CHECK(read_file(out / "cover_px.exr") == "new");
  CHECK(read_file(out / "README.md") == "readme");
  CHECK(read_file(out / "notes" / "a.txt") == "notes");
  CHECK(fs::read_symlink(out / "link.md") == "README.md");
  struct stat after {};
  ::stat((out / "README.md").c_str(), &after);
  CHECK(after.st_ino == before.st_ino);  // carried over as a hard link, not copied
  CHECK(temporaries_of(out).empty());
}

TEST_CASE("a set of files in a shared directory replaces only its files", "[output]") {
  TemporaryDirectory place(true);
  put(place.path / "unrelated.txt", "mine");
  put(place.path / "noise.png", "old");
  put(place.path / "noise.json", "old");
  {
    io::OutputSet set(place.path, io::OutputSet::Scope::files);
    set.write("noise.png", "new");
    set.write("noise.json", "new");
    CHECK(read_file(place.path / "noise.png") == "old");
    set.commit();
  }
  CHECK(read_file(place.path / "noise.png") == "new");
  CHECK(read_file(place.path / "noise.json") == "new");
  CHECK(read_file(place.path / "unrelated.txt") == "mine");
  CHECK(entries_starting(place.path, ".nephele-").empty());
}

TEST_CASE("a symbolic link at a temporary name is not written through", "[output]") {
  TemporaryDirectory place(true);
  put(place.path / "victim.txt", "victim");
  io::OutputSet set(place.path / "out", io::OutputSet::Scope::directory);
  fs::create_symlink(place.path / "victim.txt", set.temporary_directory() / "cover.json");
  CHECK_THROWS_AS(set.write("cover.json", "new"), std::runtime_error);
  CHECK(read_file(place.path / "victim.txt") == "victim");
}

TEST_CASE("names outside the set's directory are refused", "[output]") {
  TemporaryDirectory place(true);
  io::OutputSet set(place.path / "out", io::OutputSet::Scope::directory);
  CHECK_THROWS_AS(set.write("../x.png", "x"), std::invalid_argument);
  CHECK_THROWS_AS(set.write("/tmp/x.png", "x"), std::invalid_argument);
  set.write("x.png", "x");
  CHECK_THROWS_AS(set.write("x.png", "again"), std::invalid_argument);
}

TEST_CASE("stale temporary directories of dead runs are removed, links with their names are not followed",
          "[output]") {
  TemporaryDirectory place(true);
  const fs::path out = place.path / "cubemaps";
  const fs::path stale = place.path / (std::string(".nephele-cubemaps-") + dead_pid + "-abcdef");
  put(stale / "cover_px.exr", "half-written");
  put(place.path / "victim" / "keep.txt", "victim");
  const fs::path link = place.path / (std::string(".nephele-victim-") + dead_pid + "-zzzzzz");
  fs::create_directory_symlink(place.path / "victim", link);
  {
    io::OutputSet set(out, io::OutputSet::Scope::directory);
    CHECK_FALSE(fs::exists(stale));
  }
  CHECK(read_file(place.path / "victim" / "keep.txt") == "victim");
  CHECK(fs::is_symlink(link));
}

TEST_CASE("the next run completes a file set whose renames a killed run left half done", "[output]") {
  TemporaryDirectory place(true);
  put(place.path / "noise.png", "new");  // renamed before the run was killed
  put(place.path / "noise.json", "old");
  const fs::path stale = place.path / (std::string(".nephele-files-") + dead_pid + "-abcdef");
  put(stale / "noise.json", "new");
  put(stale / ".nephele-manifest", "noise.png\nnoise.json\n");
  { io::OutputSet set(place.path, io::OutputSet::Scope::files); }
  CHECK(read_file(place.path / "noise.png") == "new");
  CHECK(read_file(place.path / "noise.json") == "new");
  CHECK_FALSE(fs::exists(stale));
}

namespace {

// Runs nephele under `ulimit -f blocks` (1024-byte blocks) with SIGXFSZ ignored, so that a write
// beyond the limit fails with EFBIG as on a full disk.
test::Run run_with_file_limit(int blocks, const std::string& arguments) {
  return run_command("bash -c 'trap \"\" XFSZ; ulimit -f " + std::to_string(blocks) + "; exec " +
                     std::string(NEPHELE_EXECUTABLE) + " " + arguments + "'");
}

std::vector<std::pair<fs::path, std::string>> snapshot(const fs::path& directory) {
  std::vector<std::pair<fs::path, std::string>> files;
  for (const auto& entry : fs::directory_iterator(directory)) files.emplace_back(entry.path(), read_file(entry.path()));
  return files;
}

}  // namespace

TEST_CASE("a write that runs out of space exits non-zero naming the file and keeps the old set", "[output][cli]") {
  TemporaryDirectory place(true);
  SECTION("generate") {
    const fs::path out = place.path / "cubemaps";
    REQUIRE(run("generate --size 64 --seed 1 --out " + out.string()).exit_code == 0);
    put(out / "README.md", "not part of the set");
    const auto old = snapshot(out);
    // 64 blocks = 64 KiB: above every face (~13 KB at size 64), below the 256 x 128 float
    // equirect EXR (~110 KB).
    const auto result = run_with_file_limit(64, "generate --size 64 --seed 2 --out " + out.string());
    CHECK(result.exit_code != 0);
    CHECK_THAT(result.output, Catch::Contains((out / "cover_equirect.exr").string()));
    for (const auto& [path, bytes] : old) CHECK(read_file(path) == bytes);
    CHECK(snapshot(out).size() == old.size());
    CHECK(temporaries_of(out).empty());
  }
  SECTION("noise PNG, whose encoder does not report a failed write itself") {
    const fs::path out = place.path / "noise.png";
    REQUIRE(run("noise --width 64 --height 64 --depth 64 --seed 1 --out " + out.string()).exit_code == 0);
    put(place.path / "unrelated.txt", "not part of the set");
    const auto old = snapshot(place.path);
    // 16 blocks = 16 KiB: above the sidecar (~1 KB), below the 4096 x 64 8-bit atlas (~100 KB).
    const auto result = run_with_file_limit(16, "noise --width 64 --height 64 --depth 64 --seed 2 --out " + out.string());
    CHECK(result.exit_code != 0);
    CHECK_THAT(result.output, Catch::Contains(out.string()));
    for (const auto& [path, bytes] : old) CHECK(read_file(path) == bytes);
    CHECK(snapshot(place.path).size() == old.size());
  }
}

TEST_CASE("SIGTERM during a run removes its temporary directory", "[output][cli]") {
  TemporaryDirectory place(true);
  const fs::path out = place.path / "cubemaps";
  const pid_t child = spawn_nephele({"generate", "--size", "512", "--out", out.string()});
  REQUIRE_FALSE(wait_for_temporary(child, out).empty());
  kill(child, SIGTERM);
  int status = 0;
  waitpid(child, &status, 0);
  CHECK(WIFSIGNALED(status));
  CHECK(WTERMSIG(status) == SIGTERM);
  CHECK(temporaries_of(out).empty());
}

TEST_CASE("the temporary directory of a SIGKILLed run is removed and reported by the next run", "[output][cli]") {
  TemporaryDirectory place(true);
  const fs::path out = place.path / "cubemaps";
  const pid_t child = spawn_nephele({"generate", "--size", "512", "--out", out.string()});
  const auto temporaries = wait_for_temporary(child, out);
  REQUIRE(temporaries.size() == 1);
  kill(child, SIGKILL);
  int status = 0;
  waitpid(child, &status, 0);
  REQUIRE(fs::exists(temporaries.front()));  // SIGKILL leaves no chance to clean up
  const auto next = run("generate --size 8 --out " + out.string());
  CHECK(next.exit_code == 0);
  CHECK_THAT(next.output, Catch::Contains("removed " + temporaries.front().string()));
  CHECK(temporaries_of(out).empty());
}

TEST_CASE("scene outputs outside --out or named twice exit 2 naming the scene file and key", "[output][cli]") {
  TemporaryDirectory place(true);
  const std::string cases[] = {R"(["../x.png"])", R"(["/tmp/x.png"])", R"(["sub/../../x.png"])",
                               R"(["a.png", "a.png"])", R"(["a.png", "./a.png"])"};
  for (const auto& outputs : cases) {
    INFO(outputs);
    const fs::path scene = place.path / "scene.json";
    put(scene, R"({"view": "gurten", "size": "32x18", "outputs": )" + outputs + "}");
    const auto result = run("render --scene " + scene.string() + " --out " + (place.path / "out").string());
    CHECK(result.exit_code == 2);
    CHECK_THAT(result.output, Catch::Contains(scene.string()) && Catch::Contains("'outputs'"));
    CHECK_FALSE(fs::exists(place.path / "x.png"));
  }
}
