#include "core/progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <exception>

namespace nephele::core {

Progress::Settings Progress::for_stderr(bool quiet) {
  Settings s;
  s.enabled = !quiet;
  s.terminal = ::isatty(STDERR_FILENO) == 1;
  return s;
}

Progress::Progress(std::string label, double total, Settings settings)
    : label_(std::move(label)),
      total_(total > 0 ? total : 1.0),
      settings_(settings),
      start_(Clock::now()),
      exceptions_at_start_(std::uncaught_exceptions()) {
  if (settings_.enabled && settings_.heartbeat) heartbeat_ = std::thread([this] { heartbeat(); });
}

// Unwound by an exception, the line ends where the work stopped: "done" would claim work that
// did not happen just before the error's message.
Progress::~Progress() { end(std::uncaught_exceptions() > exceptions_at_start_); }

void Progress::heartbeat() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (!finished_) {
    const double t = elapsed();
    // A step that runs long repeats its line no faster than every half second.
    const double interval = std::max(0.5, settings_.terminal ? settings_.redraw_interval_s : settings_.line_interval_s);
    const double next = std::max(settings_.quiet_below_s, drawn_ ? last_shown_ + interval : 0.0);
    if (t >= next) {
      show(t);
      continue;
    }
    wake_.wait_for(lock, std::chrono::duration<double>(next - t));
  }
}

double Progress::elapsed() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

std::string Progress::format(const std::string& label, const std::string& stage, double fraction, double elapsed_s,
                             bool with_bar) {
  fraction = std::clamp(fraction, 0.0, 1.0);
  char numbers[96];
  // The estimate assumes the rest goes at the average rate so far; shown once 1% is done.
  if (fraction >= 0.01 && fraction < 1.0)
    std::snprintf(numbers, sizeof numbers, "%3.0f%% (%.1f s, about %.0f s left)", 100.0 * fraction, elapsed_s,
                  elapsed_s * (1.0 - fraction) / fraction);
  else
    std::snprintf(numbers, sizeof numbers, "%3.0f%% (%.1f s)", 100.0 * fraction, elapsed_s);
  std::string text = label + ": ";
  if (with_bar) {
    constexpr int width = 24;
    const int filled = static_cast<int>(std::floor(fraction * width));
    text += "[" + std::string(filled, '#') + std::string(width - filled, ' ') + "] ";
  }
  text += numbers;
  if (!stage.empty()) text += " " + stage;
  return text;
}

void Progress::update(double done, const std::string& stage) {
  if (!settings_.enabled) return;
  std::lock_guard<std::mutex> lock(mutex_);
  if (finished_) return;
  done_ = done;
  stage_ = stage;
  const double t = elapsed();
  if (t < settings_.quiet_below_s) return;
  const double interval = settings_.terminal ? settings_.redraw_interval_s : settings_.line_interval_s;
  if (drawn_ && t - last_shown_ < interval) return;
  show(t);
}

void Progress::show(double t) {
  const std::string text = format(label_, stage_, done_ / total_, t, settings_.terminal);
  if (settings_.terminal)
    std::fprintf(settings_.stream, "\r%-79s", text.c_str());  // pads over a longer previous line
  else
    std::fprintf(settings_.stream, "%s\n", text.c_str());
  std::fflush(settings_.stream);
  last_shown_ = t;
  drawn_ = true;
}

void Progress::finish() { end(false); }

void Progress::end(bool stopped) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (finished_) return;
    finished_ = true;
  }
  wake_.notify_all();
  if (heartbeat_.joinable()) heartbeat_.join();
  if (!settings_.enabled || !drawn_) return;
  const std::string text = stopped ? format(label_, "stopped", done_ / total_, elapsed(), settings_.terminal)
                                   : format(label_, "done", 1.0, elapsed(), settings_.terminal);
  if (settings_.terminal)
    std::fprintf(settings_.stream, "\r%-79s\n", text.c_str());
  else
    std::fprintf(settings_.stream, "%s\n", text.c_str());
  std::fflush(settings_.stream);
}

}  // namespace nephele::core
