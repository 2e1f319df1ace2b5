// Frame timing for benchmarks, shared by the viewer's --benchmark and tests/bench/bench_frames:
// several configurations timed interleaved, one frame of each in turn (the machine's load
// drifts over seconds, and timing each configuration in its own block made their ratios
// swing by 30%), each frame finished on the GPU before the clock stops, and one definition
// of the median and the 95th percentile.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "renderer/core/camera.h"
#include "renderer/gl/offscreen_target.h"
#include "renderer/settings/render_settings.h"
#include "renderer/renderer.h"

namespace npr {

// -1 for no samples.
double median(std::vector<double> samples);
double percentile95(std::vector<double> samples);

struct FrameTiming {
  double medianMs = -1, p95Ms = -1;  // wall clock, GPU work included
  double cpuMs = -1;                 // render()'s CPU time
  double shadingMs = -1;             // per-triangle CPU work
  double gpuMs = -1;                 // timer queries (where they finished)
};

// What one configuration draws in one round; set the light and anything else on the renderer
// before returning.
struct TimedFrame {
  CameraMatrices camera;
  RenderSettings settings;
  Renderer* renderer = nullptr;  // draws this frame; null: the one timeInterleaved was given (styles each keep their own)
};

// `frames` rounds after `warmup` rounds (shader builds, uploads), each rendering every
// configuration once into `target`. `prepare(config, round)` is called before each frame;
// warm-up rounds are numbered from -warmup. Failed renders are counted in `failures`.
std::vector<FrameTiming> timeInterleaved(Renderer& renderer, const OffscreenTarget& target, std::size_t configurations,
                                         int frames, int warmup,
                                         const std::function<TimedFrame(std::size_t config, int round)>& prepare,
                                         int& failures);

}  // namespace npr
