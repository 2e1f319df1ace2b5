// The automatic tone range (see tone_fit.h).
#include "renderer/frame/tone_fit.h"

#include <algorithm>
#include <chrono>

#include "renderer/core/elapsed.h"

namespace npr {

// The tones fitted onto the palette: the 2nd to the 95th percentile. The top stops short of a
// glossy object's highlight (a few percent of a near-black surface, four times its diffuse
// tone), which would otherwise stretch the range and leave the rest in the darkest levels: the
// dark bunny of test_gl_style_legibility in the crosshatch style reads at 0.35 of the paper's
// lightness, 0.32 with the 98th. The highlight still takes the lightest level.
constexpr float kLowPercentile = 2.0f, kHighPercentile = 95.0f;
// At most this many triangles sampled over the scene, and this many surfaces fitted each to its
// own range (the rest take the scene's): each slot is a matcher and its lookup tables.
constexpr std::size_t kMaxSamples = 65536;
constexpr int kMaxToneSlots = 1024;

// The ground set apart from the objects (figure and ground): its own lit tones fitted onto the
// palette's lightest levels, so it reads lighter and sparser than the objects on it whatever
// their tones, while its shading and the shadows on it (darker than its lit tones) still show.
void ToneFit::fitGround(Model& ground, const LightingState& lighting, const CameraMatrices& camera, const RenderSettings& s, int slot) {
  constexpr float kLightShare = 0.4f;  // the share of the palette's range, from its light end, the lit ground takes
  std::vector<ToneSample> own;
  sampleTones(ground.mesh(), lighting, camera.view * ground.transform(), camera.projection, false, s.match, 256, own);
  const std::optional<glm::vec2> range = percentileRange(own, kLowPercentile, kHighPercentile, 0.15f);
  if (!range) {
    ground.toneTarget.reset();
    return;
  }
  const glm::vec2 target(range->y - (range->y - range->x) / kLightShare, range->y);
  ground.toneTarget = ground.toneTracker().update(target, 1.0f);
  ground.toneSlot = slot;
}

void ToneFit::update(Scene& scene, const LightingState& lighting, const CameraMatrices& camera, const RenderSettings& s, FrameStats& stats) {
  const bool perObject = s.toneRange == ToneRange::PerObject && s.bands.empty();
  if (!perObject) {
    const auto reset = [](Model& m) {
      m.toneTracker().reset();
      m.toneTarget.reset();
      m.toneSlot = 0;
    };
    scene.forEachIncludingHidden(reset);
    scene.forEachSurface(reset);  // the batches too
  }
  Model* ground = s.ground ? scene.ground() : nullptr;
  if (ground) ground->toneSlot = 0;
  if (s.toneRange == ToneRange::Fixed || !s.bands.empty()) {
    tracker_.reset();
    target_.reset();
    return;
  }
  const auto t0 = std::chrono::steady_clock::now();
  // About 1024 triangles over the whole scene for one range: enough for stable percentiles
  // (the spider orbiting 3 degrees a frame moves it 3 quanta a frame), a tenth of a millisecond
  // on the CPU. Each object's own range needs more: unsmoothed, the glossy dark sphere of
  // test_gl_tone_range jittered 8 quanta a frame with 2048 samples of its 5120 triangles and 4
  // with 2560 or all of them (its highlight falls on few faces). So about 8192 over the scene,
  // at least 64 each: the bunny's frame costs what the fixed range's does within the noise; the
  // 67-part engine orbiting pays 1.12x with 4096 and 1.16x with 16384 (docs/lines-and-tone.md).
  // The surfaces as drawn: a batch of small objects (scene/scene_batches.h, each batch of one
  // material) is fitted as one. Past kMaxSamples over the scene the share of each shrinks, so a
  // scene of thousands of parts costs what one of a few hundred does.
  std::size_t models = 0;
  scene.forEachSurface([&](const Model&) { ++models; });
  models = std::max<std::size_t>(models, 1);
  const std::size_t budget = std::max<std::size_t>(1, std::min(perObject ? std::max<std::size_t>(64, 8192 / models) : std::max<std::size_t>(256, 1024 / models),
                                                               kMaxSamples / models));
  samples_.clear();
  int slot = 0;
  scene.forEachSurface([&](Model& m) {
    const std::size_t first = samples_.size();
    m.poseToneSamples(toneSampleStride(m.mesh().triangleCount(), budget));  // a pose only the GPU made
    sampleTones(m.mesh(), lighting, camera.view * m.transform(), camera.projection, s.materials, s.match, budget, samples_);
    if (!perObject) return;
    if (slot >= kMaxToneSlots) {  // past the slots, the scene's range
      m.toneSlot = 0;
      return;
    }
    // Its own tones, fitted and smoothed as the scene's are (slots from 1, in scene order).
    std::vector<ToneSample> own(samples_.begin() + std::ptrdiff_t(first), samples_.end());
    m.toneTarget = m.toneTracker().update(percentileRange(own, kLowPercentile, kHighPercentile, 0.15f), 1.0f);
    m.toneSlot = ++slot;
  });
  // Not smoothed over frames: the fit is a function of the frame's view and pose alone, so a
  // still equals the same frame of a sequence, the window's frame the headless one, and frames
  // rendered apart (a farm's frame ranges) the whole run's. Orbiting the spider 3 degrees a
  // frame moves it 0.023 on the 0..3 axis (3 quanta; smoothed a quarter a frame, it was 0.016).
  target_ = tracker_.update(percentileRange(samples_, kLowPercentile, kHighPercentile, 0.15f), 1.0f);
  if (ground) fitGround(*ground, lighting, camera, s, ++slot);
  stats.cpuToneMs = msSince(t0);
}

}  // namespace npr
