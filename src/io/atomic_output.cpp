#include "io/atomic_output.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <climits>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <mutex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <utility>

namespace nephele::io {
namespace fs = std::filesystem;
namespace {

constexpr const char* manifest_name = ".nephele-manifest";

std::runtime_error os_error(const std::string& what, int error) {
  return std::runtime_error(what + ": " + std::strerror(error));
}

// Removes `name` under the directory `parent` and everything below it, never following a
// symbolic link (openat O_NOFOLLOW; unlinkat removes the link itself). Only system calls, so
// that the signal handler can use it too.
void remove_tree_at(int parent, const char* name) noexcept;

// Removes every entry of the open directory `fd`.
void remove_entries(int fd) noexcept {
  // Entries removed while the directory is read may shift the listing: read it again until a
  // pass removes nothing (bounded, in case something cannot be removed).
  for (int pass = 0; pass < 16; ++pass) {
    bool removed = false;
    ::lseek(fd, 0, SEEK_SET);
    alignas(8) char buffer[4096];
    long n;
    while ((n = ::syscall(SYS_getdents64, fd, buffer, sizeof buffer)) > 0) {
      for (long offset = 0; offset < n;) {
        const auto* entry = reinterpret_cast<const struct dirent64*>(buffer + offset);
        offset += entry->d_reclen;
        const char* child = entry->d_name;
        if (child[0] == '.' && (child[1] == '\0' || (child[1] == '.' && child[2] == '\0'))) continue;
        if (entry->d_type == DT_DIR) {
          remove_tree_at(fd, child);
          removed = true;
        } else if (::unlinkat(fd, child, 0) == 0) {
          removed = true;
        } else if (errno == EISDIR) {  // a directory of unknown d_type
          remove_tree_at(fd, child);
          removed = true;
        }
      }
    }
    if (!removed) break;
  }
}

void remove_tree_at(int parent, const char* name) noexcept {
  // A handler on another thread may race the main thread creating a file in the directory:
  // a few rounds until the directory itself is gone.
  for (int round = 0; round < 4; ++round) {
    const int fd = ::openat(parent, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (fd < 0) {
      ::unlinkat(parent, name, 0);
      return;
    }
    remove_entries(fd);
    ::close(fd);
    if (::unlinkat(parent, name, AT_REMOVEDIR) == 0 || errno != ENOTEMPTY) return;
  }
}

// ---- SIGINT / SIGTERM: remove the open sets' temporary directories, then end as the signal
// would have. A slot's state moves by compare-and-swap, so a signal on any thread either
// removes a set's directory before its commit starts, or waits until the commit is done.
enum SlotState : int { slot_free, slot_claimed, slot_open, slot_committing, slot_removing };
struct Slot {
  std::atomic<int> state{slot_free};
  char path[PATH_MAX];
};
constexpr int slot_count = 16;
Slot slots[slot_count];
std::atomic<int> pending_signal{0};
const int handled_signals[2] = {SIGINT, SIGTERM};
struct sigaction previous_actions[2];
bool handler_installed[2] = {false, false};
int open_sets = 0;
std::mutex install_mutex;

void remove_open_sets_and_reraise(int signal_number) noexcept {
  for (Slot& slot : slots) {
    int expected = slot_open;
    if (slot.state.compare_exchange_strong(expected, slot_removing)) remove_tree_at(AT_FDCWD, slot.path);
  }
  for (int i = 0; i < 2; ++i)
    if (handled_signals[i] == signal_number) ::sigaction(signal_number, &previous_actions[i], nullptr);
  ::raise(signal_number);  // delivered when the handler returns: the default action ends the process
}

void on_signal(int signal_number) {
  const int saved_errno = errno;
  for (Slot& slot : slots)
    if (slot.state.load() == slot_committing) {
      pending_signal.store(signal_number);  // the commit re-raises it when it is done
      errno = saved_errno;
      return;
    }
  remove_open_sets_and_reraise(signal_number);
  errno = saved_errno;
}

// Takes a free slot for the temporary directory `pattern` (mkdtemp fills in its XXXXXX inside
// the slot, so that the handler knows the directory from the moment it exists) and installs
// the handlers with the first open set.
int claim_slot(const std::string& pattern) {
  if (pattern.size() >= PATH_MAX) return -1;
  for (int i = 0; i < slot_count; ++i) {
    int expected = slot_free;
    if (!slots[i].state.compare_exchange_strong(expected, slot_claimed)) continue;
    std::memcpy(slots[i].path, pattern.c_str(), pattern.size() + 1);
    std::lock_guard<std::mutex> lock(install_mutex);
    if (open_sets++ == 0)
      for (int k = 0; k < 2; ++k) {
        struct sigaction current {};
        ::sigaction(handled_signals[k], nullptr, &current);
        handler_installed[k] = current.sa_handler != SIG_IGN;  // an ignored signal stays ignored
        if (!handler_installed[k]) continue;
        struct sigaction action {};
        action.sa_handler = on_signal;
        sigemptyset(&action.sa_mask);
        ::sigaction(handled_signals[k], &action, &previous_actions[k]);
      }
    slots[i].state.store(slot_open);
    return i;
  }
  return -1;  // more than slot_count open sets: the next run cleans up after a signal
}

void release_slot(int slot) {
  if (slot < 0) return;
  slots[slot].state.store(slot_free);
  std::lock_guard<std::mutex> lock(install_mutex);
  if (--open_sets == 0)
    for (int k = 0; k < 2; ++k)
      if (handler_installed[k]) ::sigaction(handled_signals[k], &previous_actions[k], nullptr);
}

// ---- files and directories

class Fd {
 public:
  explicit Fd(int fd = -1) : fd_(fd) {}
  ~Fd() {
    if (fd_ >= 0) ::close(fd_);
  }
  Fd(Fd&& other) noexcept : fd_(other.release()) {}
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  int get() const { return fd_; }
  int release() { return std::exchange(fd_, -1); }

 private:
  int fd_;
};

Fd open_directory(const fs::path& path) {
  Fd fd(::open(path.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  if (fd.get() < 0) throw os_error("could not open directory " + path.string(), errno);
  return fd;
}

// fsync of a directory makes its entries (new names, renames) durable.
void sync_directory(const fs::path& path) {
  Fd fd(::open(path.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  if (fd.get() < 0) throw os_error("could not open directory " + path.string(), errno);
  if (::fsync(fd.get()) != 0 && errno != EINVAL) throw os_error("could not sync directory " + path.string(), errno);
}

// Writes, fsyncs and closes `fd`; `shown` names the file in errors.
void write_all(int fd, const void* data, std::size_t size, const std::string& shown) {
  Fd file(fd);
  const char* bytes = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t written = ::write(file.get(), bytes, size);
    if (written < 0) {
      if (errno == EINTR) continue;
      throw os_error("could not write " + shown, errno);
    }
    bytes += written;
    size -= static_cast<std::size_t>(written);
  }
  if (::fsync(file.get()) != 0) throw os_error("could not write " + shown + " (fsync)", errno);
  if (::close(file.release()) != 0) throw os_error("could not write " + shown + " (close)", errno);
}

void copy_file_at(int from, int to, const char* name, mode_t mode, const std::string& shown) {
  Fd in(::openat(from, name, O_RDONLY | O_NOFOLLOW | O_CLOEXEC));
  if (in.get() < 0) throw os_error("could not carry over " + shown, errno);
  const int out = ::openat(to, name, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, mode & 07777);
  if (out < 0) throw os_error("could not carry over " + shown, errno);
  std::string bytes;
  char buffer[65536];
  for (;;) {
    const ssize_t n = ::read(in.get(), buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      ::close(out);
      throw os_error("could not carry over " + shown, errno);
    }
    if (n == 0) break;
    bytes.append(buffer, static_cast<std::size_t>(n));
  }
  write_all(out, bytes.data(), bytes.size(), shown);
}

// Carries the entries of `from` that the new set did not write over into `to`: files as hard
// links (a copy where the file system refuses the link), directories merged, symbolic links
// recreated as links.
void carry_over(int from, int to, const fs::path& shown) {
  DIR* listing = ::fdopendir(::dup(from));
  if (!listing) throw os_error("could not read " + shown.string(), errno);
  std::vector<std::string> names;
  while (const dirent* entry = ::readdir(listing)) {
    const std::string name = entry->d_name;
    if (name != "." && name != "..") names.push_back(name);
  }
  ::closedir(listing);
  for (const std::string& name : names) {
    const std::string child = (shown / name).string();
    struct stat old_entry {}, new_entry {};
    if (::fstatat(from, name.c_str(), &old_entry, AT_SYMLINK_NOFOLLOW) != 0) continue;  // gone meanwhile
    const bool in_new_set = ::fstatat(to, name.c_str(), &new_entry, AT_SYMLINK_NOFOLLOW) == 0;
    if (S_ISDIR(old_entry.st_mode)) {
      if (in_new_set && !S_ISDIR(new_entry.st_mode)) continue;  // replaced by a file of the set
      if (!in_new_set && ::mkdirat(to, name.c_str(), 0700) != 0) throw os_error("could not carry over " + child, errno);
      Fd old_dir(::openat(from, name.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC));
      Fd new_dir(::openat(to, name.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC));
      if (old_dir.get() < 0 || new_dir.get() < 0) throw os_error("could not carry over " + child, errno);
      if (!in_new_set) ::fchmod(new_dir.get(), old_entry.st_mode & 07777);
      carry_over(old_dir.get(), new_dir.get(), shown / name);
      if (::fsync(new_dir.get()) != 0 && errno != EINVAL) throw os_error("could not sync " + child, errno);
    } else if (in_new_set) {
      continue;  // the new set's file replaces the old one
    } else if (S_ISREG(old_entry.st_mode)) {
      if (::linkat(from, name.c_str(), to, name.c_str(), 0) != 0)
        copy_file_at(from, to, name.c_str(), old_entry.st_mode, child);
    } else if (S_ISLNK(old_entry.st_mode)) {
      std::vector<char> target(static_cast<std::size_t>(old_entry.st_size) + 2);
      const ssize_t n = ::readlinkat(from, name.c_str(), target.data(), target.size() - 1);
      if (n < 0) throw os_error("could not carry over " + child, errno);
      target[static_cast<std::size_t>(n)] = '\0';
      if (::symlinkat(target.data(), to, name.c_str()) != 0) throw os_error("could not carry over " + child, errno);
    } else {
      throw std::runtime_error("could not carry over " + child +
                               ": not a regular file, directory or symbolic link (move it out of the output "
                               "directory)");
    }
  }
}

// Renames the set's files from `temporary` to `directory` in their order, then syncs the
// directories they entered. Throws naming the first file that could not be moved.
void move_into_place(const fs::path& temporary, const fs::path& directory, const std::vector<std::string>& names) {
  std::set<fs::path> touched;
  for (const std::string& name : names) {
    const fs::path source = temporary / name, target = directory / name;
    struct stat st {};
    if (::lstat(source.c_str(), &st) != 0) continue;  // already moved by an earlier attempt
    std::error_code ignored;
    fs::create_directories(target.parent_path().empty() ? fs::path(".") : target.parent_path(), ignored);
    if (::rename(source.c_str(), target.c_str()) != 0)
      throw os_error("could not rename " + source.string() + " to " + target.string() +
                         "; the rest of the set stays in " + temporary.string() + " and is put in place by the "
                         "next run into " + directory.string(),
                     errno);
    touched.insert(target.parent_path().empty() ? fs::path(".") : target.parent_path());
  }
  for (const fs::path& d : touched) sync_directory(d);
}

std::vector<std::string> read_manifest(const fs::path& path) {
  std::vector<std::string> names;
  std::ifstream in(path, std::ios::binary);
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) names.push_back(line);
  return names;
}

// .nephele-LABEL-PID-XXXXXX (and .nephele-aside-LABEL-PID-XXXXXX): the process id, or 0 for
// other names.
long temporary_owner(const std::string& name) {
  const std::string prefix = OutputSet::temporary_prefix;
  if (name.size() < prefix.size() + 9 || name.compare(0, prefix.size(), prefix) != 0) return 0;
  const std::size_t random_dash = name.size() - 7;
  if (name[random_dash] != '-') return 0;
  const std::size_t pid_dash = name.rfind('-', random_dash - 1);
  if (pid_dash == std::string::npos || pid_dash < prefix.size() || pid_dash + 1 == random_dash) return 0;
  long pid = 0;
  for (std::size_t i = pid_dash + 1; i < random_dash; ++i) {
    if (name[i] < '0' || name[i] > '9' || pid > 1000000000L) return 0;
    pid = pid * 10 + (name[i] - '0');
  }
  return pid;
}

// Temporary directories in `place` left by runs that no longer exist (SIGKILL, power loss):
// a committed manifest is completed (its files renamed into `place`), the rest removed; the
// old directory set aside during a fallback exchange is kept and reported.
void clean_stale(const fs::path& place) {
  DIR* listing = ::opendir(place.c_str());
  if (!listing) return;
  std::vector<std::string> stale;
  while (const dirent* entry = ::readdir(listing)) {
    const std::string name = entry->d_name;
    const long pid = temporary_owner(name);
    if (pid <= 0 || pid == static_cast<long>(::getpid())) continue;
    struct stat st {};
    if (::lstat((place / name).c_str(), &st) != 0 || !S_ISDIR(st.st_mode) || st.st_uid != ::geteuid()) continue;
    if (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;  // its run may still be going
    stale.push_back(name);
  }
  ::closedir(listing);
  for (const std::string& name : stale) {
    const fs::path path = place / name;
    if (name.compare(0, std::strlen(".nephele-aside-"), ".nephele-aside-") == 0) {
      std::cerr << "nephele: warning: " << path.string()
                << " holds an output directory set aside by a run that was killed; it is left as it is\n";
      continue;
    }
    struct stat st {};
    if (::lstat((path / manifest_name).c_str(), &st) == 0) {
      move_into_place(path, place, read_manifest(path / manifest_name));
      std::cerr << "nephele: completed the output set of an interrupted run from " << path.string() << "\n";
    }
    remove_tree_at(AT_FDCWD, path.c_str());
    std::cerr << "nephele: removed " << path.string() << ", the temporary directory of an interrupted run\n";
  }
}

// mkdtemp of PLACE/.nephele-LABEL-PID-XXXXXX; with `slot`, registered for the signal handler.
fs::path make_temporary(const fs::path& place, const std::string& label, int* error, int* slot = nullptr) {
  const std::string short_label = label.substr(0, 160);  // NAME_MAX is 255
  std::string pattern = fs::absolute(place / (OutputSet::temporary_prefix + short_label + "-" +
                                              std::to_string(::getpid()) + "-XXXXXX")).string();
  const int claimed = slot ? claim_slot(pattern) : -1;
  char* buffer = claimed >= 0 ? slots[claimed].path : pattern.data();
  if (!::mkdtemp(buffer)) {
    *error = errno;
    release_slot(claimed);
    return {};
  }
  if (slot) *slot = claimed;
  return fs::path(buffer);
}

int exchange(const fs::path& a, const fs::path& b) {
#if defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 28))
  return ::renameat2(AT_FDCWD, a.c_str(), AT_FDCWD, b.c_str(), RENAME_EXCHANGE);
#else
  return static_cast<int>(::syscall(SYS_renameat2, AT_FDCWD, a.c_str(), AT_FDCWD, b.c_str(), 1 /* RENAME_EXCHANGE */));
#endif
}

}  // namespace

OutputSet::OutputSet(fs::path directory, Scope scope) : scope_(scope) {
  directory = directory.lexically_normal();
  if (directory.empty()) directory = ".";
  if (directory.filename().empty()) directory = directory.parent_path();  // "out/" is "out"
  directory_ = directory;
  fs::path target = directory;
  struct stat st {};
  if (::lstat(target.c_str(), &st) == 0 && S_ISLNK(st.st_mode)) target = fs::canonical(target);  // keep the link
  const fs::path parent = target.has_parent_path() ? target.parent_path() : fs::path(".");
  if (scope_ == Scope::directory) {
    const std::string name = target.filename().string();
    struct stat parent_st {};
    if (name == "." || name == ".." || target == target.root_path()) scope_ = Scope::files;
    if (::stat(target.c_str(), &st) == 0 && ::stat(parent.c_str(), &parent_st) == 0 && st.st_dev != parent_st.st_dev)
      scope_ = Scope::files;  // a mount point cannot be renamed
  }
  int error = 0;
  if (scope_ == Scope::directory) {
    std::error_code ignored;
    fs::create_directories(parent, ignored);
    clean_stale(parent);
    temporary_ = make_temporary(parent, target.filename().string(), &error, &slot_);
    if (temporary_.empty() && error != EACCES && error != EPERM && error != EROFS)
      throw os_error("could not create a temporary directory next to " + directory_.string(), error);
    if (temporary_.empty()) scope_ = Scope::files;  // the parent is not ours to write
  }
  if (scope_ == Scope::files) {
    std::error_code create_error;
    fs::create_directories(directory_, create_error);
    if (create_error) throw std::runtime_error("could not create " + directory_.string() + ": " + create_error.message());
    target = directory_;
    clean_stale(directory_);
    temporary_ = make_temporary(directory_, "files", &error, &slot_);
    if (temporary_.empty()) throw os_error("could not create a temporary directory in " + directory_.string(), error);
  }
  target_ = target;
  if (scope_ == Scope::directory && ::stat(target_.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) {
    ::chmod(temporary_.c_str(), st.st_mode & 07777);  // the new directory keeps the old one's permissions
  }
}

OutputSet::~OutputSet() {
  if (!done_ && slot_ >= 0) {
    int expected = slot_open;
    if (!slots[slot_].state.compare_exchange_strong(expected, slot_removing)) return;  // a signal handler has it
  }
  if (!done_) remove_tree_at(AT_FDCWD, temporary_.c_str());
  release_slot(slot_);
}

void OutputSet::write(const std::string& name, const void* data, std::size_t size) {
  const fs::path relative = fs::path(name).lexically_normal();
  const std::string first = relative.empty() ? std::string() : relative.begin()->string();
  if (done_) throw std::logic_error("output set " + directory_.string() + " is already committed");
  if (name.empty() || relative.is_absolute() || first == ".." || first == "." ||
      first.compare(0, std::strlen(temporary_prefix), temporary_prefix) == 0 || name.find('\n') != std::string::npos)
    throw std::invalid_argument("output name '" + name + "' must be a relative path inside " + directory_.string() +
                                " (no '..', not starting with " + temporary_prefix + ")");
  for (const std::string& existing : names_)
    if (existing == relative.string())
      throw std::invalid_argument("output " + final_path(name).string() + " is written twice");
  const fs::path path = temporary_ / relative;
  const std::string shown = final_path(relative.string()).string() + " (temporary " + path.string() + ")";
  if (relative.has_parent_path()) {
    std::error_code error;
    fs::create_directories(temporary_ / relative.parent_path(), error);
    if (error) throw std::runtime_error("could not write " + shown + ": " + error.message());
  }
  // O_EXCL and O_NOFOLLOW: nothing that appeared at the temporary name, a symbolic link
  // least of all, is ever written through.
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
  if (fd < 0) throw os_error("could not write " + shown, errno);
  names_.push_back(relative.string());
  write_all(fd, data, size, shown);
}

void OutputSet::commit() {
  if (done_) throw std::logic_error("output set " + directory_.string() + " is already committed");
  if (slot_ >= 0) {
    int expected = slot_open;
    if (!slots[slot_].state.compare_exchange_strong(expected, slot_committing))
      for (;;) ::pause();  // a signal handler is removing the set and ends the process
  }
  try {
    if (scope_ == Scope::directory)
      commit_directory();
    else
      commit_files();
  } catch (...) {
    if (slot_ >= 0 && !done_) slots[slot_].state.store(slot_open);
    if (const int signal_number = pending_signal.exchange(0)) remove_open_sets_and_reraise(signal_number);
    throw;
  }
  done_ = true;
  if (slot_ >= 0) slots[slot_].state.store(slot_claimed);  // released by the destructor
  if (const int signal_number = pending_signal.exchange(0)) remove_open_sets_and_reraise(signal_number);
}

void OutputSet::commit_directory() {
  const fs::path parent = target_.has_parent_path() ? target_.parent_path() : fs::path(".");
  struct stat st {};
  const bool exists = ::lstat(target_.c_str(), &st) == 0;
  if (exists && !S_ISDIR(st.st_mode)) throw std::runtime_error(directory_.string() + " is no longer a directory");
  if (exists) {
    Fd from = open_directory(target_), to = open_directory(temporary_);
    carry_over(from.get(), to.get(), directory_);
  }
  std::set<fs::path> directories{temporary_};
  for (const std::string& name : names_)
    for (fs::path p = fs::path(name).parent_path(); !p.empty(); p = p.parent_path()) directories.insert(temporary_ / p);
  for (const fs::path& d : directories) sync_directory(d);

  fs::path old_set;  // where the previous directory is after the swap
  if (!exists) {
    if (::rename(temporary_.c_str(), target_.c_str()) != 0)
      throw os_error("could not rename " + temporary_.string() + " to " + directory_.string(), errno);
  } else if (exchange(temporary_, target_) == 0) {
    old_set = temporary_;
  } else if (errno == EINVAL || errno == ENOSYS || errno == ENOTSUP) {
    // No RENAME_EXCHANGE on this file system: the old directory is renamed aside, then the new
    // one in; between the two renames the directory does not exist (docs/formats.md).
    int error = 0;
    const fs::path aside = make_temporary(parent, "aside-" + target_.filename().string(), &error);
    if (aside.empty()) throw os_error("could not create a directory next to " + directory_.string(), error);
    if (::rename(target_.c_str(), aside.c_str()) != 0) {
      const int rename_error = errno;
      ::rmdir(aside.c_str());
      throw os_error("could not rename " + directory_.string() + " aside", rename_error);
    }
    if (::rename(temporary_.c_str(), target_.c_str()) != 0) {
      const int rename_error = errno;
      ::rename(aside.c_str(), target_.c_str());
      throw os_error("could not rename " + temporary_.string() + " to " + directory_.string(), rename_error);
    }
    old_set = aside;
  } else {
    throw os_error("could not exchange " + temporary_.string() + " with " + directory_.string(), errno);
  }
  done_ = true;
  sync_directory(parent);
  if (!old_set.empty()) remove_tree_at(AT_FDCWD, old_set.c_str());
}

void OutputSet::commit_files() {
  // The manifest, complete and durable before the first rename, lets the next run finish the
  // renames of a run that was killed half-way.
  std::string manifest;
  for (const std::string& name : names_) manifest += name + "\n";
  const fs::path part = temporary_ / (std::string(manifest_name) + ".part");
  const int fd = ::open(part.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
  if (fd < 0) throw os_error("could not write " + part.string(), errno);
  write_all(fd, manifest.data(), manifest.size(), part.string());
  if (::rename(part.c_str(), (temporary_ / manifest_name).c_str()) != 0)
    throw os_error("could not write " + (temporary_ / manifest_name).string(), errno);
  sync_directory(temporary_);
  done_ = true;  // from here on the set is completed, by this run or the next
  move_into_place(temporary_, directory_, names_);
  remove_tree_at(AT_FDCWD, temporary_.c_str());
}

void write_file(const fs::path& path, const void* data, std::size_t size) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0666);
  if (fd < 0) throw os_error("could not write " + path.string(), errno);
  write_all(fd, data, size, path.string());
}

}  // namespace nephele::io
