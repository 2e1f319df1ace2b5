// GPU frame time from timer queries, read without stalling: a ring of queries, each read once
// its result is available, the newest finished one kept. (llvmpipe's timer queries time
// submission, not rasterisation: there they read microseconds for milliseconds of work.)
#pragma once

#include <optional>

#include "renderer/gl/gl_handle.h"

namespace npr::gl {

class GpuTimer {
 public:
  GpuTimer();
  // Starts timing this frame unless every query is still in flight (then the frame is not timed).
  void begin();
  void end();
  // Reads finished queries; the newest finished frame's milliseconds, if any finished.
  std::optional<double> collect();

 private:
  static constexpr int kSlots = 4;
  Query queries_[kSlots];
  bool pending_[kSlots] = {false, false, false, false};
  int next_ = 0;
  bool running_ = false;
};

}  // namespace npr::gl
