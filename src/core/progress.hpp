#pragma once
// Progress of long work on stderr: a bar with the estimated time left when stderr is a
// terminal, otherwise a plain line at most every few seconds (logs stay readable). Work that
// ends within `quiet_below_s` prints nothing, and `--quiet` silences it altogether. A
// background heartbeat repeats the report while one step runs long (a single GPU dispatch
// gives no updates of its own), so the output never stalls.
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <string>
#include <thread>

namespace nephele::core {

class Progress {
 public:
  struct Settings {
    bool enabled = true;           // false for --quiet
    bool terminal = false;         // redraw one line with \r; else print lines
    double quiet_below_s = 1.0;    // nothing is shown before this much time has passed
    double line_interval_s = 5.0;  // between plain lines
    double redraw_interval_s = 0.1;
    bool heartbeat = true;  // repeat the report from a background thread while a step runs
    std::FILE* stream = stderr;
  };
  // Settings for stderr: enabled unless quiet, terminal when stderr is a TTY.
  static Settings for_stderr(bool quiet);

  Progress(std::string label, double total, Settings settings);
  ~Progress();  // finishes the line if a bar was drawn: "done", or "stopped" when an exception unwinds it
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // Sets the work done so far (in the units of `total`) and what is being done now.
  void update(double done, const std::string& stage = "");
  void finish();

  // The text of one report, e.g. "generate: warp 40% (12.0 s, about 18 s left)"; exposed for tests.
  static std::string format(const std::string& label, const std::string& stage, double fraction, double elapsed_s,
                            bool with_bar);

 private:
  using Clock = std::chrono::steady_clock;
  double elapsed() const;
  void show(double t);  // with mutex_ held
  void end(bool stopped);
  void heartbeat();
  std::string label_;
  double total_;
  Settings settings_;
  Clock::time_point start_;
  double done_ = 0;
  std::string stage_;
  double last_shown_ = -1e9;
  bool drawn_ = false;
  bool finished_ = false;
  int exceptions_at_start_ = 0;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::thread heartbeat_;
};

}  // namespace nephele::core
