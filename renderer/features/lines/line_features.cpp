// The line kinds as features, drawn over the surfaces in this order: hardware outlines and the
// charcoal rim from back faces (lines/hardware_outline_pass.h), image-space edges from the
// frame's depth and normals (lines/image_edges_pass.h), and each model's object-space feature
// lines (lines/line_pass.h).
#include <memory>

#include "renderer/features/feature.h"
#include "renderer/lines/hardware_outline_pass.h"
#include "renderer/lines/image_edges_pass.h"

namespace npr {
namespace {

class OutlinesFeature final : public Feature {
 public:
  const char* name() const override { return "outlines"; }
  bool active(const FrameView& f) const override { return f.settings.lines.hardware || f.settings.lines.rim; }
  Status drawOver(FrameView& f) override {
    Status result = okStatus();
    f.scene.forEach([&](Model& m) {
      if (result)
        result = drawHardwareOutlines(m.gpu(), m.placed(f.camera), f.settings.lines, f.palette, f.settings.match, f.viewport, f.programs, f.stats);
    });
    return result;
  }
};

class ImageEdgesFeature final : public Feature {
 public:
  const char* name() const override { return "image edges"; }
  bool active(const FrameView& f) const override { return f.settings.lines.imageSpace && !f.scene.empty(); }
  Status drawOver(FrameView& f) override {
    return pass_.draw(f.scene.placed(f.camera), f.camera, f.settings.lines, f.viewport, f.programs, f.emptyVao, f.stats);
  }

 private:
  ImageEdgesPass pass_;
};

class FeatureLinesFeature final : public Feature {
 public:
  const char* name() const override { return "feature lines"; }
  bool active(const FrameView& f) const override { return f.settings.lines.objectSpace(); }
  Status drawOver(FrameView& f) override {
    Status result = okStatus();
    f.scene.forEach([&](Model& m) {
      if (result) result = m.lines().draw(m.placed(f.camera), f.settings.lines, f.viewport, f.programs, f.stats);
    });
    return result;
  }
};

}  // namespace

std::unique_ptr<Feature> makeOutlinesFeature() { return std::make_unique<OutlinesFeature>(); }
std::unique_ptr<Feature> makeImageEdgesFeature() { return std::make_unique<ImageEdgesFeature>(); }
std::unique_ptr<Feature> makeFeatureLinesFeature() { return std::make_unique<FeatureLinesFeature>(); }

}  // namespace npr
