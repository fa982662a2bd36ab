#pragma once
// The one timer of GPU passes (cover, noise, render and the benches).
#include <chrono>
#include <vector>

namespace nephele::gpu {

// Wall-clock milliseconds of GPU work. GL calls only queue work, so the timer drains the queue
// (glFinish) when it starts, so that earlier work is not counted, and when it is read, so that
// all of the pass's work is. Needs a current GL context.
class PassTimer {
 public:
  PassTimer() { restart(); }
  void restart();
  double milliseconds() const;

 private:
  std::chrono::steady_clock::time_point start_;
};

// Runs `work` and returns its time in milliseconds (a PassTimer around it).
template <class Work>
double time_pass(Work&& work) {
  PassTimer timer;
  work();
  return timer.milliseconds();
}

// Device milliseconds of the GPU work queued between begin() and end(), by a GL_TIME_ELAPSED
// query (ARB_timer_query, core since OpenGL 3.3): the time the GPU spent, without the host's
// submission, waits, uploads or read-backs around it. Several begin()/end() intervals add up.
// Queries of this kind do not nest: one DeviceTimer at a time may be between begin() and
// end(). Mesa's llvmpipe answers 0 or 1 ns for compute dispatches (measured for a 250 ms pass;
// its GL_TIMESTAMP counters are written at flushes, not after the work either), so at most
// 1 ns per interval counts as "not measured by this driver" and gives 0; callers fall back to
// the wall clock (PassTimer), which on a CPU driver is the device's time. Needs a current GL
// context.
class DeviceTimer {
 public:
  DeviceTimer() = default;
  ~DeviceTimer();
  DeviceTimer(const DeviceTimer&) = delete;
  DeviceTimer& operator=(const DeviceTimer&) = delete;
  void begin();
  void end();
  double milliseconds() const;  // the sum of the intervals; waits for the results

 private:
  std::vector<unsigned> queries_;
};

// Wall-clock and device milliseconds of `work`.
struct PassTimes {
  double wall_ms = 0;
  double device_ms = 0;
};
template <class Work>
PassTimes time_pass_and_device(Work&& work) {
  PassTimer wall;
  DeviceTimer device;
  device.begin();
  work();
  device.end();
  const double wall_ms = wall.milliseconds();
  return {wall_ms, device.milliseconds()};
}

}  // namespace nephele::gpu
