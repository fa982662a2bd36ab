#pragma once
// A set of output files written under temporary names and renamed into place only when all
// of them are complete, so an interrupted or failed run never leaves a half-written file
// where a good one was.
#include <filesystem>
#include <string>
#include <vector>

namespace nephele::io {

class OutputSet {
 public:
  explicit OutputSet(std::filesystem::path directory);
  ~OutputSet();  // removes the temporaries of an uncommitted set
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;

  // The temporary path to write `name` to (same directory and extension, hidden name).
  std::filesystem::path temporary_for(const std::string& name);
  std::filesystem::path final_path(const std::string& name) const { return directory_ / name; }
  // Renames every temporary to its final name.
  void commit();

 private:
  std::filesystem::path directory_;
  std::vector<std::pair<std::filesystem::path, std::filesystem::path>> files_;  // temp, final
  bool committed_ = false;
};

void write_text_file(const std::filesystem::path& path, const std::string& text);

}  // namespace nephele::io
