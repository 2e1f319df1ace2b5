// Frame-time statistics for the overlay: the mean and the 1%-worst frame over the last
// second, frames per second, and a short history for the graph.
#pragma once

#include <deque>
#include <vector>

namespace npr {

class FrameTimer {
 public:
  void add(double nowSeconds, double frameMs);
  double meanMs() const;
  double worst1PercentMs() const;  // the frame time that 1% of last second's frames exceed or equal
  double fps() const;
  const std::vector<float>& history() const { return history_; }

 private:
  struct Sample { double t, ms; };
  std::deque<Sample> window_;
  std::vector<float> history_;
};

}  // namespace npr
