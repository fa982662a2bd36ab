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
//   A directory set whose directory turns out to be a mount point (a bind mount too) is
//   committed this way.
// Commits into one place take turns (flock on the directory the renames happen in), so two
// runs writing the same files never end with a mix of both.
// While a set is open, every signal whose default action ends the process (HUP, INT, QUIT,
// TERM, PIPE, ALRM, USR1, ...) removes its temporary directory before the process ends as the
// signal would; temporary directories of killed runs (.nephele-NAME-PID-XXXXXX) are cleaned up
// by the next set opened next to them.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace nephele::files {

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

  // Reserves `name` (as write checks it) and returns the path in the temporary directory where the
  // caller writes the file itself, whole and fsynced, before commit: images too large to hold
  // in memory, written row by row (files::ImageRowWriter).
  std::filesystem::path reserve(const std::string& name);

  // Makes the new set visible at once (Scope::directory) or file by file after its manifest
  // (Scope::files). Waits while another commit into the same place runs. Signals from outside
  // wait until it is done. Throws, leaving the old files as they were, when a directory stands
  // at a file's name.
  void commit();

  std::filesystem::path final_path(const std::string& name) const { return directory_ / name; }
  const std::filesystem::path& temporary_directory() const { return temporary_; }
  Scope scope() const { return scope_; }

  // Prefix of every temporary directory name: reserved, since the clean-up of killed runs
  // removes what carries it.
  static constexpr const char* temporary_prefix = ".nephele-";

 private:
  void commit_directory();
  void commit_files();
  // Throws when something in the final place keeps a file of the set from going there (a
  // directory at its name); nothing is replaced then.
  void check_targets() const;
  void commit_directory_as_files();

  std::filesystem::path directory_;  // where the set appears, as the caller named it
  std::filesystem::path target_;     // the directory entry that is exchanged (a link's target)
  std::filesystem::path temporary_;  // the new set while it is written
  Scope scope_;
  std::vector<std::string> names_;
  bool done_ = false;  // committed, or left for the next run to complete
  int slot_ = -1;      // signal-cleanup slot
};

// Whether a directory set whose exchange (or rename) failed with `error` is committed as a
// file set instead: EBUSY and EXDEV, which a mount point gives.
bool falls_back_to_files(int error);

// Checks, before any work, the files a command will write as `names` (relative) in
// `directory`, so that a bad name fails with exit code 2 and not after the run: no component
// of a name may start with OutputSet::temporary_prefix, no directory may stand at a file's
// name, and no file where a directory of the path goes. Throws core::InputError naming `field`
// (an option, or "FILE: 'key'") and the path.
void check_output_files(const std::filesystem::path& directory, const std::vector<std::string>& names,
                        const std::string& field);
// The same for an output directory (--out DIR): its name may not start with the prefix, and
// it must be a directory if it exists.
void check_output_directory(const std::filesystem::path& directory, const std::string& field);

// Writes `path` in place (created or truncated, never through a symbolic link), fsyncs and
// closes it; throws std::runtime_error naming the path on any failure. Not all or nothing: for
// tests and inputs they prepare; the commands write their outputs through OutputSet.
void write_file(const std::filesystem::path& path, const void* data, std::size_t size);
inline void write_text_file(const std::filesystem::path& path, const std::string& text) {
  write_file(path, text.data(), text.size());
}

// Writes `path` whole or not at all, for many writers sharing a directory (the tile parts of
// generate --tiles, written by the tasks of a job array, docs/scale.md): `pieces` go to a
// temporary file beside it (.NAME.XXXXXX, unique on every machine), which is fsynced and
// renamed over `path`. Readers see the old file or the new one. Throws std::runtime_error
// naming the path on any failure, and leaves no temporary file.
struct FilePiece {
  const void* data;
  std::size_t size;
};
void replace_file(const std::filesystem::path& path, const std::vector<FilePiece>& pieces);

}  // namespace nephele::files
