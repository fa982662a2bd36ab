#include "command_server.hpp"

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <mutex>

#include "apps/cli/command_line.hpp"
#include "core/file_descriptor.hpp"

extern char** environ;

namespace nephele::test {
namespace {

int server_socket = -1;  // the test process's end; -1 while there is no server
std::mutex server_mutex;

// A list of strings on the socket: its length, then each string's length and bytes.
bool send_list(int fd, const std::vector<std::string>& list) {
  const auto count = static_cast<std::uint32_t>(list.size());
  if (!core::write_exactly(fd, &count, sizeof count)) return false;
  for (const std::string& s : list) {
    const auto size = static_cast<std::uint32_t>(s.size());
    if (!core::write_exactly(fd, &size, sizeof size) || !core::write_exactly(fd, s.data(), s.size())) return false;
  }
  return true;
}

bool receive_list(int fd, std::vector<std::string>& list) {
  std::uint32_t count = 0;
  if (!core::read_exactly(fd, &count, sizeof count)) return false;
  list.assign(count, std::string());
  for (std::string& s : list) {
    std::uint32_t size = 0;
    if (!core::read_exactly(fd, &size, sizeof size)) return false;
    s.resize(size);
    if (size > 0 && !core::read_exactly(fd, s.data(), size)) return false;
  }
  return true;
}

// In the forked child: the request's process state, then the command line; never returns.
[[noreturn]] void run_child(const std::vector<std::string>& place, const std::vector<std::string>& environment,
                            const std::vector<std::string>& words) {
  ::clearenv();
  for (const std::string& entry : environment) ::putenv(::strdup(entry.c_str()));
  const int log = ::open(place[1].c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  const int nothing = ::open("/dev/null", O_RDONLY);
  if (::chdir(place[0].c_str()) != 0 || log < 0 || nothing < 0) ::_exit(126);
  ::dup2(nothing, 0);
  ::dup2(log, 1);
  ::dup2(log, 2);
  ::close(log);
  ::close(nothing);
  const int code = cli::run_command_line(words);
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  // Not exit(): the finalisers of libraries loaded into the server wait for their own threads
  // (log4cplus, under OpenVDB, joins a thread pool that started before the fork and does not
  // exist in the child). Everything nephele writes is closed and committed before
  // run_command_line returns.
  ::_exit(code);
}

[[noreturn]] void serve(int fd) {
  // The test process may end without a word (a crash, ctest's timeout): the server goes with it.
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (::getppid() == 1) ::_exit(0);
  for (;;) {
    std::vector<std::string> place, environment, words;
    if (!receive_list(fd, place) || !receive_list(fd, environment) || !receive_list(fd, words) || place.size() != 2)
      ::_exit(0);
    const pid_t child = ::fork();
    if (child == 0) {
      ::close(fd);
      run_child(place, environment, words);
    }
    int status = -1;
    if (child > 0)
      while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
      }
    const std::int32_t code = child < 0 ? -1 : WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    if (!core::write_exactly(fd, &code, sizeof code)) ::_exit(0);
  }
}

}  // namespace

void start_command_server() {
  if (const char* off = std::getenv("NEPHELE_TEST_COMMAND_SERVER"); off && std::string(off) == "0") return;
  int ends[2];
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, ends) != 0) return;
  std::fflush(nullptr);  // nothing buffered is written twice
  const pid_t server = ::fork();
  if (server == 0) {
    ::close(ends[0]);
    serve(ends[1]);
  }
  ::close(ends[1]);
  if (server < 0) {
    ::close(ends[0]);
    return;
  }
  server_socket = ends[0];
}

std::optional<int> run_in_command_server(const std::vector<std::string>& environment,
                                         const std::vector<std::string>& words, const std::filesystem::path& log) {
  std::unique_lock<std::mutex> lock(server_mutex, std::try_to_lock);
  if (!lock.owns_lock() || server_socket < 0) return std::nullopt;
  std::vector<std::string> all;
  for (char** e = environ; *e; ++e) all.emplace_back(*e);
  all.insert(all.end(), environment.begin(), environment.end());
  std::int32_t code = -1;
  if (!send_list(server_socket, {std::filesystem::current_path().string(), log.string()}) ||
      !send_list(server_socket, all) || !send_list(server_socket, words) ||
      !core::read_exactly(server_socket, &code, sizeof code)) {
    ::close(server_socket);  // the server is gone: from now on every command is a process
    server_socket = -1;
    return std::nullopt;
  }
  return code;
}

}  // namespace nephele::test
