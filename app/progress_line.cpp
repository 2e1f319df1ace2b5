// Progress lines (see progress_line.h).
#include "app/progress_line.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace npr {

ProgressLine::ProgressLine(std::string what)
    : what_(std::move(what)), start_(std::chrono::steady_clock::now()), terminal_(::isatty(STDERR_FILENO) == 1) {}

ProgressLine::~ProgressLine() {
  if (open_) std::fprintf(stderr, "\n");
}

void ProgressLine::update(double fraction) {
  fraction = std::clamp(fraction, 0.0, 1.0);
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double remaining = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
  if (terminal_) {
    std::fprintf(stderr, "\r%s: %3.0f%%, %.1f s elapsed, about %.1f s to go   ", what_.c_str(), 100.0 * fraction, elapsed, remaining);
    open_ = fraction < 1.0;
    if (!open_) std::fprintf(stderr, "\n");
  } else {
    const int tenth = int(fraction * 10.0 + 1e-9);
    if (tenth == lastTenth_) return;
    lastTenth_ = tenth;
    std::fprintf(stderr, "%s: %.0f%%, %.1f s elapsed, about %.1f s to go\n", what_.c_str(), 100.0 * fraction, elapsed, remaining);
  }
  std::fflush(stderr);
}

}  // namespace npr
