// Painterly brush strokes (`--strokes`) as a feature: each model's strokes, seeded on its
// surface once and oriented by its direction field, drawn over the surfaces
// (strokes/brush_stroke_pass.h).
#include <memory>

#include "renderer/features/feature.h"

namespace npr {
namespace {

class StrokesFeature final : public Feature {
 public:
  const char* name() const override { return "strokes"; }
  bool active(const FrameView& f) const override { return f.settings.strokes.on && f.palette; }
  Status drawOver(FrameView& f) override {
    Status result = okStatus();
    f.scene.forEach([&](Model& m) {
      if (!result) return;
      result = m.strokes().draw(m.placed(f.camera), m.scale(), f.settings.strokes, f.lighting, *f.palette, f.settings.match,
                                  m.surfaceDirections(f.stats), f.settings.tuning.strokeFade, f.viewport, f.programs, f.stats);
    });
    return result;
  }
};

}  // namespace

void addStrokesFeatures(std::vector<std::unique_ptr<Feature>>& features) { features.push_back(std::make_unique<StrokesFeature>()); }
// Strokes are seeded on the CPU's pose.
void StrokesNeeds(const RenderSettings& s, FrameNeeds& needs) { needs.cpuPose = needs.cpuPose || s.strokes.on; }

}  // namespace npr
