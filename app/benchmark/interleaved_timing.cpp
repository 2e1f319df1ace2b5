// Interleaved frame timing (see interleaved_timing.h).
#include "app/benchmark/interleaved_timing.h"

#include <algorithm>
#include <chrono>

#include "renderer/core/elapsed.h"

namespace npr {

double median(std::vector<double> v) {
  if (v.empty()) return -1.0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

double percentile95(std::vector<double> v) {
  if (v.empty()) return -1.0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<size_t>(0.95 * double(v.size())))];
}

std::vector<FrameTiming> timeInterleaved(Renderer& renderer, const OffscreenTarget& target, std::size_t configurations, int frames,
                                         int warmup, const std::function<TimedFrame(std::size_t, int)>& prepare, int& failures) {
  std::vector<std::vector<double>> wall(configurations), cpu(configurations), shading(configurations), gpu(configurations);
  for (int round = -warmup; round < frames; ++round) {
    for (std::size_t c = 0; c < configurations; ++c) {
      const TimedFrame frame = prepare(c, round);
      Renderer& r = frame.renderer ? *frame.renderer : renderer;
      target.bind();
      const auto t0 = std::chrono::steady_clock::now();
      const Status st = r.render(frame.camera, frame.settings, {0, 0, target.width(), target.height()});
      finishGpuWork();
      const double ms = msSince(t0);
      r.collectGpuTime();
      if (!st) ++failures;
      if (round < 0) continue;
      wall[c].push_back(ms);
      cpu[c].push_back(r.stats().cpuFrameMs);
      shading[c].push_back(r.stats().cpuShadingMs);
      if (r.stats().gpuMs >= 0) gpu[c].push_back(r.stats().gpuMs);
    }
  }
  std::vector<FrameTiming> out(configurations);
  for (std::size_t c = 0; c < configurations; ++c)
    out[c] = {median(wall[c]), percentile95(wall[c]), median(cpu[c]), median(shading[c]), median(gpu[c])};
  return out;
}

}  // namespace npr
