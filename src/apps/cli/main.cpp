// nephele: planetary cloud cover, generated on the GPU.
#include <string>
#include <vector>

#include "apps/cli/command_line.hpp"

int main(int argc, char** argv) {
  return nephele::cli::run_command_line(std::vector<std::string>(argv + 1, argv + argc));
}
