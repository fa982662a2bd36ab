#pragma once
// Running the nephele executable from tests: its exit code and output, temporary directories,
// whole files as text.
#include <sys/wait.h>
#include <wordexp.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <sstream>
#include <string>

#include "case_tags.hpp"
#include "command_server.hpp"

namespace nephele::test {

struct Run {
  int exit_code;
  std::string output;  // stdout and stderr
};

inline std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// A fresh path for a command's stdout and stderr.
inline std::filesystem::path new_log() {
  return std::filesystem::temp_directory_path() / ("nephele_run_" + std::to_string(std::random_device{}()) + ".log");
}

// The log's text, and the log removed.
inline std::string take_log(const std::filesystem::path& log) {
  std::string output = read_file(log);
  std::filesystem::remove(log);
  return output;
}

// Runs a shell command line with stdout and stderr captured in a temporary log.
inline Run run_command(const std::string& command) {
  starting_slow_work("a subprocess");
  const std::filesystem::path log = new_log();
  const int status = std::system((command + " > " + log.string() + " 2>&1").c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, take_log(log)};
}

// The words of `text` as sh would split and expand them (quotes, variables), or nothing where
// the text needs more of the shell than that (redirections, pipes, command substitution).
inline std::optional<std::vector<std::string>> shell_words(const std::string& text) {
  wordexp_t expanded{};
  if (::wordexp(text.c_str(), &expanded, WRDE_NOCMD) != 0) return std::nullopt;
  std::vector<std::string> words(expanded.we_wordv, expanded.we_wordv + expanded.we_wordc);
  ::wordfree(&expanded);
  return words;
}

// nephele with the arguments exactly as given, after `environment` (VAR=value ... or empty): in
// the command server (command_server.hpp) where its words are plain, else as a process.
inline Run run_as_given(const std::string& environment, const std::string& arguments) {
  const auto variables = shell_words(environment);
  const auto words = shell_words(arguments);
  const bool only_variables = variables && std::all_of(variables->begin(), variables->end(), [](const std::string& w) {
                                return w.find('=') != std::string::npos && w.find('=') > 0;
                              });
  if (only_variables && words) {
    starting_slow_work("a subprocess");
    const std::filesystem::path log = new_log();
    if (const std::optional<int> code = run_in_command_server(*variables, *words, log)) return {*code, take_log(log)};
  }
  return run_command(environment + " " + std::string(NEPHELE_EXECUTABLE) + " " + arguments);
}

// As run_as_given, but renders get --no-cache, so that the tests never read or fill the user's
// noise cache (the cache's own tests name a directory through XDG_CACHE_HOME and use
// run_as_given).
inline Run run_with_environment(const std::string& environment, const std::string& arguments) {
  const bool render = arguments.rfind("render", 0) == 0 && (arguments.size() == 6 || arguments[6] == ' ');
  return run_as_given(environment, render ? "render --no-cache" + arguments.substr(6) : arguments);
}

inline Run run(const std::string& arguments) { return run_with_environment("", arguments); }

// Without an OpenGL context (an EGL platform that does not exist): a refusal that comes before
// any GL work exits 2, while anything that reaches GL exits 3.
inline Run run_without_gl(const std::string& arguments) {
  return run_with_environment("NEPHELE_EGL_PLATFORM=vulkan", arguments);
}

// A fresh path under the temporary directory, removed with everything in it at the end of the
// scope; created at once with create = true (else left to the command under test).
struct TemporaryDirectory {
  std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("nephele_test_" + std::to_string(std::random_device{}()));
  explicit TemporaryDirectory(bool create = false) {
    if (create) std::filesystem::create_directories(path);
  }
  ~TemporaryDirectory() { std::filesystem::remove_all(path); }
  TemporaryDirectory(const TemporaryDirectory&) = delete;
  TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;
  bool empty() const { return std::filesystem::is_empty(path); }
};

}  // namespace nephele::test
