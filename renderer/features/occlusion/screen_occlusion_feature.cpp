// Ambient occlusion per pixel (`--occlusion --occlusion-method screen`) as a feature: estimated
// every frame from what the frame shows of every model and the ground, after the clear, and
// read by the per-pixel shadings (shadows/screen_occlusion_pass.h).
#include <algorithm>
#include <memory>

#include "renderer/features/feature.h"
#include "renderer/paths/lit_mesh_program.h"
#include "renderer/frame/frame_context.h"
#include "renderer/features/occlusion/screen_occlusion_pass.h"
#include "renderer/lighting/occlusion_factor.h"

namespace npr {
namespace {

class ScreenOcclusionFeature final : public Feature, SurfaceInput {
 public:
  const char* name() const override { return "occlusion (screen)"; }
  bool active(const FrameView& f) const override {
    return f.settings.occlusion && f.settings.occlusionMethod == OcclusionMethod::Screen && !f.scene.empty();
  }
  Status afterClear(FrameView& f) override {
    ready_ = false;
    std::vector<PlacedMesh> meshes = f.scene.placed(f.camera);
    if (f.settings.ground)
      if (Model* g = f.scene.ground()) meshes.push_back({&g->gpu(), f.camera});
    const float sceneRadius = f.scene.bounds().w;
    const float radius = std::clamp(f.settings.screenOcclusionRadius, 0.01f, 10.0f) * (sceneRadius > 0.0f ? sceneRadius : 1.0f);
    if (Status st = pass_.draw(meshes, f.camera, radius, f.viewport, f.programs, f.emptyVao, f.stats); !st) return st;
    ready_ = true;
    return okStatus();
  }
  void shade(const FrameView&, const Model*, FrameContext& frame) override {
    if (ready_) frame.addInput(this);
  }
  // The per-pixel shadings read this frame's estimate (occlusion.glsl) instead of the bake;
  // the others draw no occlusion while it is on.
  void addTo(gl::MeshProgram& variant, const FrameContext&) const override {
    variant.screenOcclusion = shadesPerPixel(variant.shading);
    variant.occlusion = false;
  }
  void bind(gl::ShaderProgram& program, const gl::MeshProgram& variant, const FrameContext& frame) const override {
    if (!variant.screenOcclusion) return;
    pass_.bind(program, frame.viewport);
    program.set("uOcclusionStrength", occlusionStrength(frame.settings.occlusionStrength));
  }

 private:
  ScreenOcclusionPass pass_;
  bool ready_ = false;
};

}  // namespace

std::unique_ptr<Feature> makeScreenOcclusionFeature() { return std::make_unique<ScreenOcclusionFeature>(); }

}  // namespace npr
