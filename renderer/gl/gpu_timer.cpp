// Timer-query ring (see gpu_timer.h).
#include "renderer/gl/gpu_timer.h"

namespace npr::gl {

GpuTimer::GpuTimer() {
  for (auto& q : queries_) q = createQuery();
}

void GpuTimer::begin() {
  running_ = !pending_[next_];
  if (running_) glBeginQuery(GL_TIME_ELAPSED, queries_[next_].id());
}

void GpuTimer::end() {
  if (!running_) return;
  glEndQuery(GL_TIME_ELAPSED);
  pending_[next_] = true;
  next_ = (next_ + 1) % kSlots;
  running_ = false;
}

std::optional<double> GpuTimer::collect() {
  // Queries finish in the order they were issued: read from the oldest pending one.
  std::optional<double> ms;
  for (int k = 0; k < kSlots; ++k) {
    const int i = (next_ + k) % kSlots;
    if (!pending_[i]) continue;
    GLint available = 0;
    glGetQueryObjectiv(queries_[i].id(), GL_QUERY_RESULT_AVAILABLE, &available);
    if (!available) continue;
    GLuint64 ns = 0;
    glGetQueryObjectui64v(queries_[i].id(), GL_QUERY_RESULT, &ns);
    ms = double(ns) * 1e-6;
    pending_[i] = false;
  }
  return ms;
}

}  // namespace npr::gl
