// Frame-time statistics (see frame_timer.h).
#include "app/window/frame_timer.h"

#include <algorithm>
#include <cmath>

namespace npr {

void FrameTimer::add(double now, double ms) {
  window_.push_back({now, ms});
  while (!window_.empty() && window_.front().t < now - 1.0) window_.pop_front();
  history_.push_back(static_cast<float>(ms));
  if (history_.size() > 240) history_.erase(history_.begin());
}

double FrameTimer::meanMs() const {
  if (window_.empty()) return 0.0;
  double s = 0.0;
  for (const auto& x : window_) s += x.ms;
  return s / double(window_.size());
}

double FrameTimer::worst1PercentMs() const {
  if (window_.empty()) return 0.0;
  std::vector<double> v;
  for (const auto& x : window_) v.push_back(x.ms);
  std::sort(v.begin(), v.end());
  const size_t i = static_cast<size_t>(std::floor(0.99 * double(v.size() - 1)));
  return v[std::min(v.size() - 1, i + (v.size() > 1 ? 1 : 0))];
}

double FrameTimer::fps() const {
  const double m = meanMs();
  return m > 0.0 ? 1000.0 / m : 0.0;
}

}  // namespace npr
