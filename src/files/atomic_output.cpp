#include "core/file_descriptor.hpp"
#include "files/atomic_output.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <climits>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <iostream>
#include <mutex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <utility>

#include "core/error.hpp"

namespace nephele::files {
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

// ---- Signals: while a set is open, every signal whose default action ends the process removes
// the open sets' temporary directories, then ends the process as the signal would have. Only
// signals at their default action are caught: one that the program ignores (nephele ignores
// SIGXFSZ, so that a write beyond `ulimit -f` fails with a message) or handles itself does not
// end the run. A slot's state moves by compare-and-swap, so a signal on any thread either
// removes a set's directory before its commit starts, or, sent from outside, waits until the
// commit is done.
enum SlotState : int { slot_free, slot_claimed, slot_open, slot_committing, slot_removing, slot_removed };
struct Slot {
  std::atomic<int> state{slot_free};
  char path[PATH_MAX];
};
constexpr int slot_count = 16;
Slot slots[slot_count];
std::atomic<int> pending_signal{0};
bool handler_installed[NSIG] = {};
int open_sets = 0;
std::mutex install_mutex;

// The signals whose default action ends the process (signal(7)); SIGKILL and SIGSTOP cannot be
// caught.
std::vector<int> ending_signals() {
  std::vector<int> list = {SIGHUP,  SIGINT,  SIGQUIT, SIGILL,  SIGTRAP, SIGABRT, SIGBUS,    SIGFPE,  SIGUSR1, SIGSEGV,
                           SIGUSR2, SIGPIPE, SIGALRM, SIGTERM, SIGXCPU, SIGXFSZ, SIGVTALRM, SIGPROF, SIGIO,   SIGSYS};
#ifdef SIGSTKFLT
  list.push_back(SIGSTKFLT);
#endif
#ifdef SIGPWR
  list.push_back(SIGPWR);
#endif
  for (int s = SIGRTMIN; s <= SIGRTMAX; ++s) list.push_back(s);
  return list;
}

// Raised by the instruction that faulted, or by abort(): these cannot wait for a commit, since
// returning from the handler would repeat the fault (abort() ends the process regardless).
bool raised_by_the_program(int signal_number) {
  return signal_number == SIGSEGV || signal_number == SIGBUS || signal_number == SIGFPE || signal_number == SIGILL ||
         signal_number == SIGSYS || signal_number == SIGTRAP || signal_number == SIGABRT;
}

void remove_open_sets_and_reraise(int signal_number) noexcept {
  for (Slot& slot : slots) {
    int expected = slot_open;
    if (slot.state.compare_exchange_strong(expected, slot_removing)) {
      remove_tree_at(AT_FDCWD, slot.path);
      slot.state.store(slot_removed);
    }
  }
  // A handler (or destructor) on another thread may be removing a set: the process ends after it.
  for (Slot& slot : slots)
    while (slot.state.load() == slot_removing) {
      const timespec pause{0, 1000000};
      ::nanosleep(&pause, nullptr);
    }
  struct sigaction action {};
  action.sa_handler = SIG_DFL;
  sigemptyset(&action.sa_mask);
  ::sigaction(signal_number, &action, nullptr);
  ::raise(signal_number);  // inside the handler: delivered when it returns; the default action ends the process
}

void on_signal(int signal_number) {
  const int saved_errno = errno;
  if (!raised_by_the_program(signal_number))
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
      for (const int s : ending_signals()) {
        struct sigaction current {};
        handler_installed[s] =
            ::sigaction(s, nullptr, &current) == 0 && !(current.sa_flags & SA_SIGINFO) && current.sa_handler == SIG_DFL;
        if (!handler_installed[s]) continue;
        struct sigaction action {};
        action.sa_handler = on_signal;
        sigfillset(&action.sa_mask);   // no second signal cuts a removal short
        action.sa_flags = SA_RESTART;  // a signal that waits for a commit does not fail its system calls
        ::sigaction(s, &action, nullptr);
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
    for (int s = 1; s < NSIG; ++s)
      if (handler_installed[s]) {
        handler_installed[s] = false;
        struct sigaction current {};
        if (::sigaction(s, nullptr, &current) != 0 || current.sa_handler != on_signal) continue;  // not ours now
        struct sigaction action {};
        action.sa_handler = SIG_DFL;
        sigemptyset(&action.sa_mask);
        ::sigaction(s, &action, nullptr);
      }
}

// ---- files and directories

using Fd = core::FileDescriptor;

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
  if (!core::write_exactly(file.get(), data, size)) throw os_error("could not write " + shown, errno);
  if (::fsync(file.get()) != 0) throw os_error("could not write " + shown + " (fsync)", errno);
  if (!file.close()) throw os_error("could not write " + shown + " (close)", errno);
}

// The whole content of `fd`; `what` begins the error message.
std::string read_all(int fd, const std::string& what) {
  std::string bytes;
  char buffer[65536];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw os_error(what, errno);
    if (n == 0) return bytes;
    bytes.append(buffer, static_cast<std::size_t>(n));
  }
}

void copy_file_at(int from, int to, const char* name, mode_t mode, const std::string& shown) {
  Fd in(::openat(from, name, O_RDONLY | O_NOFOLLOW | O_CLOEXEC));
  if (in.get() < 0) throw os_error("could not carry over " + shown, errno);
  const std::string bytes = read_all(in.get(), "could not carry over " + shown);
  const int out = ::openat(to, name, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, mode & 07777);
  if (out < 0) throw os_error("could not carry over " + shown, errno);
  write_all(out, bytes.data(), bytes.size(), shown);
}

// Copies the file `from` to the new file `to` (its parent directories created), checked and
// synced like every write of a set.
void copy_file(const fs::path& from, const fs::path& to, const std::string& shown) {
  Fd in(::open(from.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC));
  struct stat st {};
  if (in.get() < 0 || ::fstat(in.get(), &st) != 0) throw os_error("could not copy " + from.string(), errno);
  const std::string bytes = read_all(in.get(), "could not copy " + from.string());
  std::error_code error;
  fs::create_directories(to.parent_path(), error);
  const int out = ::open(to.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, st.st_mode & 07777);
  if (out < 0) throw os_error("could not write " + shown, errno);
  write_all(out, bytes.data(), bytes.size(), shown);
}

// Holds an exclusive flock on the directory `place` until the descriptor closes (the kernel
// releases it when the process ends, however it ends): commits into one place take turns.
// Where the directory cannot be opened for reading, or its file system has no flock (some
// network file systems), the commit goes ahead unlocked.
Fd lock_place(const fs::path& place) {
  Fd fd(::open(place.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  if (fd.get() < 0) return fd;
  while (::flock(fd.get(), LOCK_EX) != 0)
    if (errno != EINTR) return Fd();
  return fd;
}

// The process's umask, without changing it: /proc/self/status shows it (Linux 4.7 and later);
// umask() reads it only by setting it, which a file created meanwhile by another thread would see.
mode_t current_umask() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.compare(0, 6, "Umask:") == 0) return static_cast<mode_t>(std::strtoul(line.c_str() + 6, nullptr, 8));
  const mode_t mask = ::umask(022);
  ::umask(mask);
  return mask;
}

// Whether `path` is the root of a mount, which cannot be renamed. statx says so for bind mounts
// of a directory of the same file system too (Linux 5.8 and later); the device number, the
// fallback, only for another file system (a bind mount is then found when the exchange fails).
bool is_mount_point(const fs::path& path, const fs::path& parent) {
#ifdef STATX_ATTR_MOUNT_ROOT
  struct statx sx {};
  if (::statx(AT_FDCWD, path.c_str(), 0, STATX_BASIC_STATS, &sx) == 0 &&
      (sx.stx_attributes_mask & STATX_ATTR_MOUNT_ROOT))
    return (sx.stx_attributes & STATX_ATTR_MOUNT_ROOT) != 0;
#endif
  struct stat st {
  }, parent_st{};
  return ::stat(path.c_str(), &st) == 0 && ::stat(parent.c_str(), &parent_st) == 0 && st.st_dev != parent_st.st_dev;
}

// Whether a component of the relative `name` starts with the temporary prefix.
bool reserved(const fs::path& name) {
  const std::string prefix = OutputSet::temporary_prefix;
  for (const fs::path& part : name)
    if (part.string().compare(0, prefix.size(), prefix) == 0) return true;
  return false;
}

// What keeps the file `name` from being renamed into `directory`: a directory at its name, or
// something other than a directory where one of its parent directories goes. Empty if nothing;
// else the problem, with the path in `*at`.
std::string target_problem(const fs::path& directory, const std::string& name, fs::path* at) {
  const fs::path relative = fs::path(name).lexically_normal();
  fs::path path = directory;
  for (auto part = relative.begin(); part != relative.end(); ++part) {
    path /= *part;
    const bool last = std::next(part) == relative.end();
    struct stat st {};
    // The file itself is never followed (rename replaces a link); its parents may be links.
    if ((last ? ::lstat(path.c_str(), &st) : ::stat(path.c_str(), &st)) != 0) return {};
    *at = path;
    if (last && S_ISDIR(st.st_mode)) return "is a directory, where a file of the output set goes";
    if (!last && !S_ISDIR(st.st_mode)) return "is not a directory, but files of the output set go inside it";
  }
  return {};
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
    struct stat old_entry {
    }, new_entry{};
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
                         "; the rest of the set stays in " + temporary.string() +
                         " and is put in place by the "
                         "next run into " +
                         directory.string(),
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
  if (stale.empty()) return;
  const Fd lock = lock_place(place);  // the roll forward renames into `place`, as a commit does
  for (const std::string& name : stale) {
    const fs::path path = place / name;
    if (name.compare(0, std::strlen(".nephele-aside-"), ".nephele-aside-") == 0) {
      std::cerr << "nephele: warning: " << path.string()
                << " holds an output directory set aside by a run that was killed; it is left as it is\n";
      continue;
    }
    struct stat st {};
    if (::lstat(path.c_str(), &st) != 0) continue;  // completed by another run meanwhile
    if (::lstat((path / manifest_name).c_str(), &st) == 0) {
      try {
        move_into_place(path, place, read_manifest(path / manifest_name));
      } catch (const std::exception& e) {
        // Kept, since it holds the only copy of those files; this run goes on, so that one
        // obstacle (such as a directory made at a file's name) does not stop every later run.
        std::cerr << "nephele: warning: could not complete the output set of an interrupted run: " << e.what() << "\n";
        continue;
      }
      std::cerr << "nephele: completed the output set of an interrupted run from " << path.string() << "\n";
    }
    remove_tree_at(AT_FDCWD, path.c_str());
    std::cerr << "nephele: removed " << path.string() << ", the temporary directory of an interrupted run\n";
  }
}

// mkdtemp of PLACE/.nephele-LABEL-PID-XXXXXX; with `slot`, registered for the signal handler.
fs::path make_temporary(const fs::path& place, const std::string& label, int* error, int* slot = nullptr) {
  const std::string short_label = label.substr(0, 160);  // NAME_MAX is 255
  std::string pattern =
      fs::absolute(place / (OutputSet::temporary_prefix + short_label + "-" + std::to_string(::getpid()) + "-XXXXXX"))
          .lexically_normal()
          .string();
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
    if (name == "." || name == ".." || target == target.root_path()) scope_ = Scope::files;
    if (is_mount_point(target, parent)) scope_ = Scope::files;
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
    if (create_error)
      throw std::runtime_error("could not create " + directory_.string() + ": " + create_error.message());
    target = directory_;
    clean_stale(directory_);
    temporary_ = make_temporary(directory_, "files", &error, &slot_);
    if (temporary_.empty()) throw os_error("could not create a temporary directory in " + directory_.string(), error);
  }
  target_ = target;
  if (scope_ == Scope::directory) {
    // The new directory keeps the old one's permissions, or gets those of mkdir (mkdtemp's are 0700).
    const bool exists = ::stat(target_.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
    ::chmod(temporary_.c_str(), exists ? st.st_mode & 07777 : 0777 & ~current_umask());
  }
}

OutputSet::~OutputSet() {
  if (!done_ && slot_ >= 0) {
    int expected = slot_open;
    if (!slots[slot_].state.compare_exchange_strong(expected, slot_removing))
      for (;;) ::pause();  // a signal handler on another thread removes the set and ends the process
  }
  if (!done_) remove_tree_at(AT_FDCWD, temporary_.c_str());
  release_slot(slot_);
}

void OutputSet::write(const std::string& name, const void* data, std::size_t size) {
  const fs::path path = reserve(name);
  const std::string shown =
      final_path(fs::path(name).lexically_normal().string()).string() + " (temporary " + path.string() + ")";
  // O_EXCL and O_NOFOLLOW: nothing that appeared at the temporary name, a symbolic link
  // least of all, is ever written through.
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
  if (fd < 0) throw os_error("could not write " + shown, errno);
  write_all(fd, data, size, shown);
}

fs::path OutputSet::reserve(const std::string& name) {
  const fs::path relative = fs::path(name).lexically_normal();
  const std::string first = relative.empty() ? std::string() : relative.begin()->string();
  if (done_) throw std::logic_error("output set " + directory_.string() + " is already committed");
  if (name.empty() || relative.is_absolute() || first == ".." || first == "." || reserved(relative) ||
      name.find('\n') != std::string::npos)
    throw std::invalid_argument("output name '" + name + "' must be a relative path inside " + directory_.string() +
                                " (no '..', no part starting with " + temporary_prefix + ")");
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
  std::error_code probe;  // a name the system refuses fails at the open that follows, named
  const fs::file_type type = fs::symlink_status(path, probe).type();
  if (!probe && type != fs::file_type::not_found)
    throw std::runtime_error("could not write " + shown + ": something is already at the temporary name");
  names_.push_back(relative.string());
  return path;
}

void OutputSet::commit() {
  if (done_) throw std::logic_error("output set " + directory_.string() + " is already committed");
  // Taken while a signal may still remove the set, so that a run waiting here can be stopped.
  const fs::path place = scope_ == Scope::files ? directory_ : target_.has_parent_path() ? target_.parent_path() : ".";
  const Fd lock = lock_place(place);
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
    // Reopened for the handlers, or, once the manifest is committed, left to the next run.
    if (slot_ >= 0) slots[slot_].state.store(done_ ? slot_claimed : slot_open);
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
    // A directory of the user's at a file's name would go with the old set: refused instead.
    check_targets();
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
  } else if (falls_back_to_files(errno)) {
    commit_directory_as_files();
    return;
  } else if (errno == EINVAL || errno == ENOSYS || errno == ENOTSUP) {
    // No RENAME_EXCHANGE on this file system: the old directory is renamed aside, then the new
    // one in; between the two renames the directory does not exist (docs/formats.md).
    int error = 0;
    const fs::path aside = make_temporary(parent, "aside-" + target_.filename().string(), &error);
    if (aside.empty()) throw os_error("could not create a directory next to " + directory_.string(), error);
    if (::rename(target_.c_str(), aside.c_str()) != 0) {
      const int rename_error = errno;
      ::rmdir(aside.c_str());
      if (falls_back_to_files(rename_error)) {
        commit_directory_as_files();
        return;
      }
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

// The directory is a mount point found only now (a bind mount where statx cannot tell, or one
// mounted while the set was written): the set's files are committed one by one as a file set,
// from a temporary directory inside the mount, since no rename crosses into it. The caller holds
// the lock of the directory's parent; the file set takes the directory's own, as file sets do.
void OutputSet::commit_directory_as_files() {
  const Fd lock = lock_place(directory_);
  int error = 0;
  const fs::path files = make_temporary(directory_, "files", &error);
  if (files.empty()) throw os_error("could not create a temporary directory in " + directory_.string(), error);
  try {
    for (const std::string& name : names_)
      copy_file(temporary_ / name, files / name,
                final_path(name).string() + " (temporary " + (files / name).string() + ")");
  } catch (...) {
    remove_tree_at(AT_FDCWD, files.c_str());
    throw;
  }
  remove_tree_at(AT_FDCWD, temporary_.c_str());
  temporary_ = files;
  // While committing, no handler reads the slot; a failure before the manifest reopens it.
  if (slot_ >= 0 && temporary_.string().size() < PATH_MAX)
    std::memcpy(slots[slot_].path, temporary_.c_str(), temporary_.string().size() + 1);
  scope_ = Scope::files;
  commit_files();
}

void OutputSet::check_targets() const {
  for (const std::string& name : names_) {
    fs::path at;
    const std::string problem = target_problem(directory_, name, &at);
    if (!problem.empty())
      throw std::runtime_error(at.string() + " " + problem + "; nothing was replaced (remove or rename it)");
  }
}

void OutputSet::commit_files() {
  // A rename that fails half-way would leave a mix of old and new files: what would make one
  // fail is looked for first (other nephele runs wait for the lock meanwhile).
  check_targets();
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

bool falls_back_to_files(int error) { return error == EBUSY || error == EXDEV; }

void check_output_files(const fs::path& directory, const std::vector<std::string>& names, const std::string& field) {
  for (const std::string& name : names) {
    if (reserved(fs::path(name)))
      throw core::InputError(field, name, "",
                             std::string("starts with ") + OutputSet::temporary_prefix +
                                 ", which names the temporary directories of output sets (clean-ups remove them)");
    fs::path at;
    const std::string problem = target_problem(directory, name, &at);
    if (!problem.empty()) throw core::InputError(field, at.string(), "", problem + " (remove or rename it)");
  }
}

void check_output_directory(const fs::path& directory, const std::string& field) {
  fs::path normal = directory.lexically_normal();
  if (normal.filename().empty()) normal = normal.parent_path();  // "out/" is "out"
  if (reserved(normal.filename()))
    throw core::InputError(field, directory.string(), "",
                           std::string("starts with ") + OutputSet::temporary_prefix +
                               ", which names the temporary directories of output sets (clean-ups remove them)");
  std::error_code error;
  if (fs::exists(directory, error) && !fs::is_directory(directory, error))
    throw core::InputError(field, directory.string(), "DIR", "exists and is not a directory");
}

void replace_file(const fs::path& path, const std::vector<FilePiece>& pieces) {
  const fs::path directory = path.has_parent_path() ? path.parent_path() : fs::path(".");
  std::string name = (directory / ("." + path.filename().string() + ".XXXXXX")).string();
  const int fd = ::mkostemp(name.data(), O_CLOEXEC);
  if (fd < 0) throw os_error("could not write " + path.string(), errno);
  try {
    Fd file(fd);
    for (const FilePiece& piece : pieces)
      if (!core::write_exactly(file.get(), piece.data, piece.size))
        throw os_error("could not write " + path.string(), errno);
    if (::fchmod(file.get(), 0666 & ~current_umask()) != 0) throw os_error("could not write " + path.string(), errno);
    if (::fsync(file.get()) != 0) throw os_error("could not write " + path.string() + " (fsync)", errno);
    if (!file.close()) throw os_error("could not write " + path.string() + " (close)", errno);
    if (::rename(name.c_str(), path.c_str()) != 0) throw os_error("could not write " + path.string(), errno);
  } catch (...) {
    ::unlink(name.c_str());
    throw;
  }
  sync_directory(directory);
}

void write_file(const fs::path& path, const void* data, std::size_t size) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0666);
  if (fd < 0) throw os_error("could not write " + path.string(), errno);
  write_all(fd, data, size, path.string());
}

}  // namespace nephele::files
