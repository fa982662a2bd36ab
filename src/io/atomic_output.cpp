#include "io/atomic_output.hpp"

#include <unistd.h>

#include <fstream>
#include <stdexcept>
#include <system_error>

namespace nephele::io {

OutputSet::OutputSet(std::filesystem::path directory) : directory_(std::move(directory)) {}

OutputSet::~OutputSet() {
  if (committed_) return;
  for (const auto& [temporary, final_path] : files_) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
  }
}

std::filesystem::path OutputSet::temporary_for(const std::string& name) {
  const std::filesystem::path final_path = directory_ / name;
  const std::string stem = final_path.stem().string();
  const std::string extension = final_path.extension().string();
  const std::filesystem::path temporary =
      directory_ / ("." + stem + ".tmp-" + std::to_string(::getpid()) + extension);
  files_.emplace_back(temporary, final_path);
  return temporary;
}

void OutputSet::commit() {
  for (const auto& [temporary, final_path] : files_) std::filesystem::rename(temporary, final_path);
  committed_ = true;
}

void write_text_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream file(path, std::ios::binary);
  file << text;
  file.close();
  if (!file) throw std::runtime_error("could not write " + path.string());
}

}  // namespace nephele::io
