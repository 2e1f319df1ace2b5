// The automatic tone range (see tone_fit.h).
#include "renderer/frame/tone_fit.h"

#include <algorithm>
#include <chrono>

#include "renderer/core/elapsed.h"

namespace npr {

void ToneFit::update(Scene& scene, const LightingState& lighting, const CameraMatrices& camera, const RenderSettings& s, FrameStats& stats) {
  const bool perObject = s.toneRange == ToneRange::PerObject && s.bands.empty();
  if (!perObject)
    scene.forEachIncludingHidden([](Model& m) {
      m.toneTracker().reset();
      m.toneTarget.reset();
      m.toneSlot = 0;
    });
  if (s.toneRange == ToneRange::Fixed || !s.bands.empty()) {
    tracker_.reset();
    target_.reset();
    return;
  }
  const auto t0 = std::chrono::steady_clock::now();
  // About 1024 triangles over the whole scene for one range: enough for stable percentiles
  // (the spider orbiting moves it at most 2 quanta a frame, as 4096 did), a tenth of a
  // millisecond on the CPU. Each object's own range needs more, about 4096 over the scene
  // (with 1024 the dark object of test_gl_tone_range moved 8 quanta a frame), at least 64 each
  // (a scene of many parts keeps about the same total).
  std::size_t models = 0;
  scene.forEach([&](const Model&) { ++models; });
  const std::size_t budget = perObject ? std::max<std::size_t>(64, 4096 / std::max<std::size_t>(models, 1))
                                       : std::max<std::size_t>(256, 1024 / std::max<std::size_t>(models, 1));
  samples_.clear();
  int slot = 0;
  scene.forEach([&](Model& m) {
    const std::size_t first = samples_.size();
    m.poseToneSamples(toneSampleStride(m.mesh().triangleCount(), budget));  // a pose only the GPU made
    sampleTones(m.mesh(), lighting, camera.view * m.transform(), camera.projection, s.materials, s.match, budget, samples_);
    if (!perObject) return;
    // Its own tones, fitted and smoothed as the scene's are (slots from 1, in scene order).
    std::vector<ToneSample> own(samples_.begin() + std::ptrdiff_t(first), samples_.end());
    m.toneTarget = m.toneTracker().update(percentileRange(own, 2.0f, 98.0f, 0.15f), 0.25f);
    m.toneSlot = ++slot;
  });
  // A quarter of the way to each new estimate per frame: settles in about ten frames and
  // follows an orbit without pumping.
  target_ = tracker_.update(percentileRange(samples_, 2.0f, 98.0f, 0.15f), 0.25f);
  stats.cpuToneMs = msSince(t0);
}

}  // namespace npr
