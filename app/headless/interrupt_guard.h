// Ctrl+C (SIGINT) and a farm cancelling a job (SIGTERM) while a headless sequence renders: the
// signal is noted and the run stops between frames, so its partial video and GIF are removed
// rather than left behind. The handlers before it are back when it goes.
#pragma once

#include <csignal>

namespace npr {

class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;
  bool raised() const;

 private:
  struct sigaction previousInt_ {}, previousTerm_{};
};

}  // namespace npr
