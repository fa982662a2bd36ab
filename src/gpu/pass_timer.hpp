#pragma once
// The one timer of GPU passes (cover, noise, render and the benches).
#include <chrono>

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

}  // namespace nephele::gpu
