#pragma once
#include <string>
#include <vector>

#include "core/error.hpp"
#include "cover/cover_parameters.hpp"

namespace nephele::cli {

// Exit codes shared by all commands (declared once, in src/core/error.hpp).
constexpr int exit_ok = core::exit_ok;
constexpr int exit_failure = core::exit_failure;
constexpr int exit_usage = core::exit_bad_input;
constexpr int exit_no_context = core::exit_environment;

int run_generate(const std::vector<std::string>& arguments);
int run_assemble(const std::vector<std::string>& arguments);
// The cover's parameters from generate's arguments (a tile part records them; assemble reads).
cover::CoverParameters parse_generate_parameters(const std::vector<std::string>& arguments);
int run_bench(const std::vector<std::string>& arguments);
int run_noise(const std::vector<std::string>& arguments);
int run_report(const std::vector<std::string>& arguments);
int run_render(const std::vector<std::string>& arguments);
int bench_render(const std::vector<std::string>& arguments);
int run_model(const std::vector<std::string>& arguments);
int bench_model(const std::vector<std::string>& arguments);
int bench_export(const std::vector<std::string>& arguments);
int run_export(const std::vector<std::string>& arguments);
int run_view(const std::vector<std::string>& arguments);
int run_stats(const std::vector<std::string>& arguments);
int bench_view(const std::vector<std::string>& arguments);

}  // namespace nephele::cli
