#pragma once
// The whole command line of nephele as a function: main() calls it, and so does the test
// suite's command server (tests/command_server.hpp), which runs it in a forked child instead of
// starting the executable anew.
#include <string>
#include <vector>

namespace nephele::cli {

// Runs `arguments` (without the program name) and returns the exit code: 0 done, 1 failed,
// 2 bad input, 3 no OpenGL context (core/error.hpp). Messages go to stderr.
int run_command_line(const std::vector<std::string>& arguments);

}  // namespace nephele::cli
