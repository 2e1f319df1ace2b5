// Cast shadows (`--shadows`) as a feature: the shadow maps of every enabled light over the
// scene's models, redrawn when a light or the scene moves (shadows/shadow_maps.h), and the
// ground's shadow texture (shadows/ground_shadow_pass.h).
#include <memory>

#include "renderer/features/feature.h"
#include "renderer/paths/lit_mesh_program.h"
#include "renderer/frame/frame_context.h"
#include "renderer/shadows/ground_shadow_pass.h"
#include "renderer/shadows/shadow_maps.h"

namespace npr {
namespace {

class ShadowsFeature final : public Feature, SurfaceInput {
 public:
  const char* name() const override { return "shadows"; }
  bool active(const FrameView& f) const override { return f.settings.shadows && !f.scene.empty(); }
  Status prepare(FrameView& f) override {
    ready_ = false;
    const Model* ground = f.settings.ground ? f.scene.ground() : nullptr;
    ShadowScene scene;
    f.scene.forEachSurface(
        [&](Model& m) { scene.casters.push_back({&m.gpu(), m.transform(), m.materials().coverage() ? &m.materials() : nullptr}); });
    const glm::vec4 bounds = f.scene.bounds();
    scene.centre = glm::vec3(bounds);
    scene.casterRadius = bounds.w;
    scene.sceneRadius = ground ? ground->mesh().radius : bounds.w;
    scene.version = f.scene.version() * 2 + (ground ? 1 : 0);
    if (Status st = maps_.update(f.lighting, f.camera.view, scene, f.programs, f.stats); !st) return st;
    ready_ = maps_.layers() > 0;
    f.stats.shadowLayers = maps_.layers();
    if (ready_ && ground && f.settings.tuning.groundShadowTexture)
      if (Status st = groundShadows_.update(maps_, ground->mesh(), f.scene.version(), f.programs, f.emptyVao, f.stats); !st) return st;
    return okStatus();
  }
  void shade(const FrameView& f, const Model* model, FrameContext& frame) override {
    if (!ready_) return;
    frame.shadows = &maps_;  // the per-triangle paths light with them on the GPU
    frame.addInput(this);
    if (!model && f.settings.tuning.groundShadowTexture && groundShadows_.ready()) frame.addInput(&groundInput_);
  }
  // The GPU-lit passes look the maps up (shadows.glsl), with the scene's view.
  void addTo(gl::MeshProgram& variant, const FrameContext&) const override { variant.shadowLayers = maps_.layers(); }
  void bind(gl::ShaderProgram& program, const gl::MeshProgram& variant, const FrameContext& frame) const override {
    if (variant.shadowLayers > 0) maps_.bind(program, frame.sceneView);
  }

 private:
  // The ground's per-pixel shadings read its shadow texture instead of the maps (added after
  // the maps' input, whose layers it needs).
  struct GroundInput final : SurfaceInput {
    const GroundShadowPass& pass;
    explicit GroundInput(const GroundShadowPass& p) : pass(p) {}
    void addTo(gl::MeshProgram& variant, const FrameContext&) const override {
      variant.groundShadowMap = shadesPerPixel(variant.shading) && variant.shadowLayers > 0;
    }
    void bind(gl::ShaderProgram& program, const gl::MeshProgram& variant, const FrameContext&) const override {
      if (variant.groundShadowMap) pass.bind(program);
    }
  };
  ShadowMaps maps_;
  GroundShadowPass groundShadows_;
  GroundInput groundInput_{groundShadows_};
  bool ready_ = false;
};

}  // namespace

void addShadowsFeatures(std::vector<std::unique_ptr<Feature>>& features) { features.push_back(std::make_unique<ShadowsFeature>()); }
void ShadowsNeeds(const RenderSettings&, FrameNeeds&) {}

}  // namespace npr
