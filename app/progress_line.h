// Progress of long work on stderr: on a terminal one line redrawn in place (percentage,
// elapsed, expected remaining); otherwise a plain line at every tenth, so logs stay readable.
#pragma once

#include <chrono>
#include <string>

namespace npr {

class ProgressLine {
 public:
  explicit ProgressLine(std::string what);
  ~ProgressLine();
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;
  // `fraction` of the work done, 0..1.
  void update(double fraction);

 private:
  std::string what_;
  std::chrono::steady_clock::time_point start_;
  bool terminal_;
  int lastTenth_ = -1;
  bool open_ = false;
};

}  // namespace npr
