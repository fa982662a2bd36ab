#pragma once
#include <string>
#include <vector>

namespace nephele::cli {

// Exit codes shared by all commands.
enum ExitCode { exit_ok = 0, exit_failure = 1, exit_usage = 2, exit_no_context = 3 };

int run_generate(const std::vector<std::string>& arguments);
int run_bench(const std::vector<std::string>& arguments);
int run_noise(const std::vector<std::string>& arguments);
int run_report(const std::vector<std::string>& arguments);
int run_render(const std::vector<std::string>& arguments);
int bench_render(const std::vector<std::string>& arguments);

}  // namespace nephele::cli
