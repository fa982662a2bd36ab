// The command server of the tests (command_server.hpp) runs a command as the executable would:
// the same exit code and output, the caller's environment and working directory.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>

#include "cli_support.hpp"

namespace fs = std::filesystem;
using namespace nephele;

namespace {

// The command in the server; nothing when the server is off (NEPHELE_TEST_COMMAND_SERVER=0).
std::optional<test::Run> in_server(const std::vector<std::string>& environment, const std::vector<std::string>& words) {
  test::TemporaryDirectory place(true);
  const fs::path log = place.path / "log";
  const std::optional<int> code = test::run_in_command_server(environment, words, log);
  if (!code) return std::nullopt;
  return test::Run{*code, test::read_file(log)};
}

bool server_is_off() {
  if (in_server({}, {"--version"})) return false;
  test::skip_case("the command server is off (NEPHELE_TEST_COMMAND_SERVER=0)");
  return true;
}

}  // namespace

TEST_CASE("a command in the command server exits and prints as the executable does", "[cli]") {
  if (server_is_off()) return;
  const std::string exe = NEPHELE_EXECUTABLE;
  for (const std::string arguments : {"--version", "frobnicate", "generate --size 0", "render --view nowhere"}) {
    INFO(arguments);
    const test::Run process = test::run_command(exe + " " + arguments);
    const test::Run served = *in_server({}, *test::shell_words(arguments));
    CHECK(served.exit_code == process.exit_code);
    CHECK(served.output == process.output);
  }
  // Among them a success and a refusal (bad input, exit code 2).
  CHECK(in_server({}, {"--version"})->exit_code == 0);
  CHECK(in_server({}, {"frobnicate"})->exit_code == 2);
}

TEST_CASE("a command in the command server takes the caller's environment and working directory", "[cli]") {
  if (server_is_off()) return;
  // An EGL platform that does not exist: the command reaches GL and exits 3 naming it.
  const test::Run no_gl =
      *in_server({"NEPHELE_EGL_PLATFORM=vulkan"}, {"model", "--example", "towering", "--size", "8", "--no-preview"});
  CHECK(no_gl.exit_code == 3);
  CHECK_THAT(no_gl.output, Catch::Contains("NEPHELE_EGL_PLATFORM is 'vulkan'"));
  // A relative --out lands in the caller's working directory, whatever it was when the server
  // started.
  test::TemporaryDirectory place(true);
  const fs::path before = fs::current_path();
  fs::current_path(place.path);
  const test::Run made = *in_server({}, {"noise", "--size", "4", "--cells", "1", "--out", "relative.raw"});
  fs::current_path(before);
  INFO(made.output);
  CHECK(made.exit_code == 0);
  CHECK(fs::exists(place.path / "relative.raw"));
}
