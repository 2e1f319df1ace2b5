// How the frame lays the palettes' textures on the surface it draws: the pattern's mapping
// (screen space, a fixed scale, the anchored pattern's frame, object space), where the frame's
// pixels sit (a poster's tile, the viewport), and where the hatching's stroke angle comes from.
// It belongs to the frame, not to a palette: every palette a model is drawn with (its own, the
// material palettes, the control palettes) reads the same one, set once per model drawn
// (Renderer::preparePattern) and handed to the passes with the frame (FrameContext::pattern).
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "renderer/core/camera.h"
#include "renderer/core/frame_stats.h"
#include "renderer/programs/program_variants.h"
#include "renderer/patterns/pattern_tracker.h"
#include "renderer/settings/render_settings.h"

namespace npr {

// The anchored pattern's octave split: fract(log2 scale) and how far the dissolve from the
// coarse octave to the fine one has gone (gpu_palette.cpp's bindPattern reads both).
struct OctaveSplit {
  float octave = 0.0f, fade = 0.0f;
};

struct PatternPlacement {
  // The anchored pattern's frame (nullopt: screen space), the pattern scale (texel size in
  // pixels, > 0), and whether mapped lookups filter bilinearly.
  std::optional<PatternFrame> frame;
  float scale = 1.0f;
  bool linearFilter = false;
  // The object-space pattern (--pattern object): `pixelSize` is the object units one pixel spans
  // at eye depth 1 (2 / (projection[1][1] x height)), `eyeToObject` the view's inverse.
  bool object = false;
  float pixelSize = 1.0f;
  glm::mat4 eyeToObject{1.0f};
  // Where this viewport's pixels sit in the whole frame (a poster's tile), so patterns continue
  // across tiles; the viewport drawn in (x, y, width, height), so vertex stages can place the
  // pattern from clip positions; and whether mesh passes do (pattern_vertex.glsl: where
  // triangles span a few pixels or more) or each pixel does.
  glm::vec2 frameOffset{0.0f};
  glm::ivec4 viewport{0, 0, 1, 1};
  bool perVertex = false;
  // Hatching orientation: where the stroke angle comes from (bins clamped to the settings'
  // range), and the first enabled light (eye space) for OrientSource::Light.
  OrientSettings orient;
  glm::vec4 light{0.0f, 0.0f, 1.0f, 0.0f};

  gl::PatternMapping mapping() const;
  OctaveSplit octaves() const;
};

// Places the pattern for one model seen through `placed` (its camera) in `viewport`: its frame
// (anchored: `tracker` follows the model, which it must then hold; else none), the scale and
// filter, where the viewport sits in the whole frame (`frameOffset`, a poster's tile), and
// whether mapped patterns are placed per vertex (by `pixelsPerFrontTriangle`, the model's
// density on screen; infinite for no model). The orientation fields are left as they are.
void placePattern(PatternPlacement& into, PatternTracker* tracker, float pixelsPerFrontTriangle, const CameraMatrices& placed,
                  const RenderSettings& settings, const glm::ivec4& viewport, glm::vec2 frameOffset, FrameStats& stats);

}  // namespace npr
