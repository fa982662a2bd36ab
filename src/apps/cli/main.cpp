// nephele: planetary cloud cover, generated on the GPU.
#include <string>
#include <vector>

#include "apps/cli/command_line.hpp"
#include "core/large_pages.hpp"

int main(int argc, char** argv) {
  nephele::core::use_large_pages();
  return nephele::cli::run_command_line(std::vector<std::string>(argv + 1, argv + argc));
}
