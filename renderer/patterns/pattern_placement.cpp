// The frame's pattern placement (see pattern_placement.h).
#include "renderer/patterns/pattern_placement.h"

#include <algorithm>
#include <cmath>

namespace npr {
namespace {
// The dissolve runs over the middle half of the octave only: in the outer quarters one octave
// shows alone (marks within 2^0.25 of the pattern scale), which costs a scaled pattern's single
// lookup and no hash, so an orbiting or panning camera, whose scale stays near 1, never pays for
// it; zooms pay while they cross the middle.
constexpr float kFadeBegin = 0.25f, kFadeEnd = 0.75f;
}  // namespace

OctaveSplit PatternPlacement::octaves() const {
  if (!frame) return {};
  const float l = std::log2(frame->scale);
  const float octave = l - std::floor(l);
  return {octave, std::clamp((octave - kFadeBegin) / (kFadeEnd - kFadeBegin), 0.0f, 1.0f)};
}

gl::PatternMapping PatternPlacement::mapping() const {
  if (object) return gl::PatternMapping::Object;
  if (frame) {
    const float fade = octaves().fade;
    // One octave alone is a fixed scale through the frame (GpuPalette::bindPattern folds it in).
    return fade > 0.0f && fade < 1.0f ? gl::PatternMapping::Anchored : gl::PatternMapping::Scaled;
  }
  return scale != 1.0f ? gl::PatternMapping::Scaled : gl::PatternMapping::Screen;
}

namespace {
// Screen pixels per front-facing triangle (the model's bounding disc over half its triangles)
// from which mapped patterns are placed per vertex. Framed at 1280x720, triangle path, anchored,
// orbiting, per vertex against per pixel: icosphere-7 (2.0 pixels) 4-9% faster, torus-500k (1.3)
// 0-5% slower; in bench_frames the 871K torus (0.75) 5-10% slower, the bunny (178) 7-9% faster.
constexpr float kPatternPerVertexPixels = 1.5f;
}  // namespace

void placePattern(PatternPlacement& into, PatternTracker* tracker, float pixelsPerFrontTriangle, const CameraMatrices& placed,
                  const RenderSettings& s, const glm::ivec4& viewport, glm::vec2 frameOffset, FrameStats& stats) {
  std::optional<PatternFrame> frame;
  if (s.pattern == PatternSpace::Anchored && tracker) {
    // The reference path draws no pattern: following its frame too would fit the split view's
    // two viewports as motion, back and forth every frame, and the fits' float error would make
    // the pattern creep over a still model.
    if (s.path != RenderPath::Reference) {
      const PatternFit& fit = tracker->update(placed, viewport, s.patternFollowsRotation);
      stats.cpuPatternMs = fit.ms;
      stats.patternSamples = fit.samplesUsed;
    }
    frame = tracker->frame();
  }
  into.frame = frame;
  into.scale = std::clamp(s.patternScale, RenderSettings::kMinPatternScale, RenderSettings::kMaxPatternScale);
  into.linearFilter = s.patternLinearFilter;
  into.object = s.pattern == PatternSpace::Object;
  // Object units one pixel spans at eye depth 1 (the model's units are the eye's).
  into.pixelSize = 2.0f / (std::max(std::abs(placed.projection[1][1]), 1e-6f) * float(std::max(viewport.w, 1)));
  into.eyeToObject = glm::inverse(placed.view);
  into.frameOffset = frameOffset;
  into.viewport = viewport;
  // Mapped patterns are placed per vertex where the model's triangles span a few pixels each:
  // there interpolation is cheaper than mapping every pixel; on denser meshes llvmpipe shades a
  // block of pixels per triangle anyway and a varying costs each triangle's set-up more than the
  // arithmetic it saves (pattern_vertex.glsl has the figures).
  into.perVertex = pixelsPerFrontTriangle >= kPatternPerVertexPixels;
}

}  // namespace npr
