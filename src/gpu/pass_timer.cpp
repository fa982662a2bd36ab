#include "gpu/pass_timer.hpp"

#include <epoxy/gl.h>

namespace nephele::gpu {

void PassTimer::restart() {
  glFinish();
  start_ = std::chrono::steady_clock::now();
}

double PassTimer::milliseconds() const {
  glFinish();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count();
}

DeviceTimer::~DeviceTimer() {
  if (!queries_.empty()) glDeleteQueries(static_cast<GLsizei>(queries_.size()), queries_.data());
}

void DeviceTimer::begin() {
  GLuint query = 0;
  glCreateQueries(GL_TIME_ELAPSED, 1, &query);
  queries_.push_back(query);
  glBeginQuery(GL_TIME_ELAPSED, query);
}

void DeviceTimer::end() { glEndQuery(GL_TIME_ELAPSED); }

double DeviceTimer::milliseconds() const {
  GLuint64 total = 0;
  for (GLuint query : queries_) {
    GLuint64 nanoseconds = 0;
    glGetQueryObjectui64v(query, GL_QUERY_RESULT, &nanoseconds);
    total += nanoseconds;
  }
  // llvmpipe answers 1 ns per query for any compute work: that is no measurement.
  if (total <= queries_.size()) return 0.0;
  return static_cast<double>(total) / 1e6;
}

}  // namespace nephele::gpu
