// nephele's command line: dispatch to the command table and the exit code of each error kind.
#include "apps/cli/command_line.hpp"
#include "core/input_file.hpp"

#include <csignal>
#include <iostream>

#include "apps/cli/command_table.hpp"
#include "apps/cli/commands.hpp"
#include "apps/cli/options.hpp"
#include "core/printable_text.hpp"
#include "gpu/compute_program.hpp"
#include "gpu/egl_context.hpp"
#include "nephele/version.hpp"

namespace {

// Messages quote inputs (paths, values, file fields): printed escaped and cut, so that a crafted
// input cannot send escape sequences to the terminal (core/printable_text.hpp).
std::string shown(const std::exception& e) { return nephele::core::printable(e.what(), 8192, true); }

}  // namespace

int nephele::cli::run_command_line(const std::vector<std::string>& arguments) {
  // A write beyond `ulimit -f` then fails with EFBIG, which the checked writes report naming the
  // file (exit code 1), instead of SIGXFSZ ending the run without a word.
  std::signal(SIGXFSZ, SIG_IGN);
  try {
    if (arguments.empty()) {
      std::cerr << usage();
      return exit_usage;
    }
    const std::string command = arguments[0];
    const std::vector<std::string> rest(arguments.begin() + 1, arguments.end());
    if (command == "--help" || command == "-h" || command == "help") {
      std::cout << usage();
      return exit_ok;
    }
    if (command == "--version") {
      std::cout << "nephele " << nephele::version << "\n";
      return exit_ok;
    }
    if (const Command* c = find_command(command)) return c->run(rest);
    std::string names;
    for (const Command& c : commands()) names += (names.empty() ? "" : ", ") + std::string(c.name);
    throw UsageError("unknown command '" + command + "' (allowed: " + names + ")");
  } catch (const nephele::core::InputError& e) {
    std::cerr << "nephele: " << shown(e) << "\n";
    return exit_usage;
  } catch (const nephele::core::InputFileError& e) {
    // A file the user gave is bad (its message names the file and the field).
    std::cerr << "nephele: " << shown(e) << "\n";
    return exit_usage;
  } catch (const nephele::gpu::ContextError& e) {
    std::cerr << "nephele: " << shown(e) << "\n";
    return exit_no_context;
  } catch (const std::exception& e) {
    std::cerr << "nephele: error: " << shown(e) << "\n";
    return exit_failure;
  }
}
