// Features as modules: what a frame may be drawn with beyond the path itself (shadows,
// occlusion, painterly strokes, lines, the depth cue, ...). Each feature is one folder under
// features/ and one row of the feature table (feature_table.cpp); the frame (renderer.cpp)
// is a loop over the active ones. A feature says whether this frame needs it, prepares what
// the surfaces read (maps, bakes, screen buffers), hands each surface pass its share, and
// draws its passes over the surfaces.
#pragma once

#include <memory>
#include <vector>

#include "renderer/core/result.h"
#include "renderer/frame/frame_context.h"
#include "renderer/frame/frame_needs.h"
#include "renderer/frame/frame_view.h"
#include "renderer/settings/render_settings.h"

namespace npr {

class Feature {
 public:
  virtual ~Feature() = default;
  virtual const char* name() const = 0;
  // Whether this frame needs the feature; inactive features are never called.
  virtual bool active(const FrameView& frame) const = 0;
  // Before the frame's clear (shadow maps, bakes).
  [[nodiscard]] virtual Status prepare(FrameView&) { return okStatus(); }
  // After the clear, before the surfaces (buffers of what the frame shows).
  [[nodiscard]] virtual Status afterClear(FrameView&) { return okStatus(); }
  // Its share of a surface pass of `model` (null: the ground): what the pass reads.
  virtual void shade(const FrameView&, const Model*, FrameContext&) {}
  // Passes over the surfaces (lines, strokes, fades), in the table's order; colour frames only.
  [[nodiscard]] virtual Status drawOver(FrameView&) { return okStatus(); }
  // What a colour frame hands the next (strokes' parameters continued from the last frame's),
  // carried through a frame that is not drawn: Renderer::follow, a frame range's frames before
  // its first. A feature that keeps nothing from frame to frame has nothing to do here.
  [[nodiscard]] virtual Status follow(FrameView&) { return okStatus(); }
};

// A row of the feature table: a feature's folder adds its features (several where they share
// resources, as the line kinds share stroke textures) and says, from the settings alone, what a
// frame drawn with them needs before it draws.
struct FeatureRow {
  void (*add)(std::vector<std::unique_ptr<Feature>>& features);
  void (*needs)(const RenderSettings& settings, FrameNeeds& needs);
};
// The feature table (feature_table.cpp), in the order the frame calls them.
const std::vector<FeatureRow>& featureTable();
// Every feature of the table, made anew (each renderer keeps its own).
std::vector<std::unique_ptr<Feature>> makeFeatures();
// What the table's features declare for `settings`.
void featureNeeds(const RenderSettings& settings, FrameNeeds& needs);

}  // namespace npr
