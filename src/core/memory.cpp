#include "core/memory.hpp"

#include <fstream>
#include <sstream>
#include <string>

namespace nephele::core {

double host_memory_available_bytes() {
  std::ifstream meminfo("/proc/meminfo");
  std::string line;
  // Line by line: some lines (HugePages_Total) have no unit, which would derail a word stream.
  while (std::getline(meminfo, line)) {
    std::istringstream fields(line);
    std::string key, unit;
    double kilobytes = 0;
    if (fields >> key >> kilobytes >> unit && key == "MemAvailable:" && unit == "kB") return kilobytes * 1024.0;
  }
  return 0.0;
}

}  // namespace nephele::core
