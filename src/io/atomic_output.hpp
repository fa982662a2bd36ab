#pragma once
// Output sets: the files one command writes appear whole or not at all (docs/formats.md,
// "Output sets"). The new files are written into a fresh directory made by mkdtemp, every
// write, fsync and close is checked, and only a complete set replaces the old one:
// - Scope::directory: the set owns its directory (generate, report, render --scene --out).
//   Files of the old directory that the set does not write are carried over (hard links),
//   then the new directory is exchanged with the old one in one renameat2(RENAME_EXCHANGE).
// - Scope::files: the set is only its files, in a directory shared with unrelated files
//   (noise --out FILE, render --out FILE). A manifest is committed first, then the files are
//   renamed one by one; a run killed half-way is completed by the next run into the same place.
// While a set is open, SIGINT and SIGTERM remove its temporary directory before the process
// ends; temporary directories of killed runs (.nephele-NAME-PID-XXXXXX) are cleaned up by the
// next set opened next to them.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace nephele::io {

class OutputSet {
 public:
  enum class Scope { directory, files };

  // Opens a set in `directory` (created if missing). Scope::directory falls back to
  // Scope::files where the directory cannot be exchanged: `.`, a mount point, or a parent
  // that this user may not write.
  OutputSet(std::filesystem::path directory, Scope scope);
  ~OutputSet();  // an uncommitted set removes its temporary directory; the old set stays
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;

  // Writes `name` (relative, may contain sub-directories, no `..`) into the new set. Throws
  // std::runtime_error naming the final path when any write, fsync or close fails.
  void write(const std::string& name, const void* data, std::size_t size);
  void write(const std::string& name, const std::string& text) { write(name, text.data(), text.size()); }
  void write(const std::string& name, const std::vector<unsigned char>& bytes) {
    write(name, bytes.data(), bytes.size());
  }

  // Makes the new set visible at once (Scope::directory) or file by file after its manifest
  // (Scope::files). SIGINT and SIGTERM wait until it is done.
  void commit();

  std::filesystem::path final_path(const std::string& name) const { return directory_ / name; }
  const std::filesystem::path& temporary_directory() const { return temporary_; }
  Scope scope() const { return scope_; }

  // Prefix of every temporary directory name.
  static constexpr const char* temporary_prefix = ".nephele-";

 private:
  void commit_directory();
  void commit_files();

  std::filesystem::path directory_;  // where the set appears, as the caller named it
  std::filesystem::path target_;     // the directory entry that is exchanged (a link's target)
  std::filesystem::path temporary_;  // the new set while it is written
  Scope scope_;
  std::vector<std::string> names_;
  bool done_ = false;  // committed, or left for the next run to complete
  int slot_ = -1;      // signal-cleanup slot
};

// Writes `path` in place (created or truncated, never through a symbolic link), fsyncs and
// closes it; throws std::runtime_error naming the path on any failure.
void write_file(const std::filesystem::path& path, const void* data, std::size_t size);
inline void write_text_file(const std::filesystem::path& path, const std::string& text) {
  write_file(path, text.data(), text.size());
}

}  // namespace nephele::io
