#pragma once
// The commands of `nephele`: one table that main's usage, its dispatch and its error for an
// unknown command are made from.
#include <string>
#include <vector>

namespace nephele::cli {

struct Command {
  const char* name;
  std::string summary;  // one line for `nephele --help`
  int (*run)(const std::vector<std::string>& arguments);
};

// In the order `nephele --help` lists them.
const std::vector<Command>& commands();
// The command of that name; nullptr when there is none.
const Command* find_command(const std::string& name);
// "usage: nephele COMMAND [options]", the commands and their summaries, the exit codes.
std::string usage();

}  // namespace nephele::cli
