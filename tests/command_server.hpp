#pragma once
// Runs nephele's command line in a child forked from a small server process instead of starting
// the executable anew. A fresh `nephele` spends about 0.4 s loading its 265 shared libraries
// (OpenImageIO alone brings OpenCV, FFmpeg, GDAL, ...) before it reads its arguments, and the
// suite runs nearly 300 commands. The server is forked first thing in main, while the test
// process has one thread and no GL context, so each child starts from the same clean image a
// new process would have: libraries loaded, nothing run. The child sets the caller's environment
// and working directory, sends stdout and stderr to the log, calls cli::run_command_line (what
// main() calls) and exits with its code; a crash or signal ends the child, not the test.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace nephele::test {

// Forks the server. Call it before anything else in main; NEPHELE_TEST_COMMAND_SERVER=0 leaves
// it off (every command then starts the executable, as a user would).
void start_command_server();

// Runs the command line `words` with the caller's environment plus `environment` (NAME=value),
// stdout and stderr written to `log`. Returns the exit code (-1 when a signal ended it), or
// nothing when the server is off or busy with another thread's command: then run it as a process.
std::optional<int> run_in_command_server(const std::vector<std::string>& environment,
                                         const std::vector<std::string>& words, const std::filesystem::path& log);

}  // namespace nephele::test
