// Ambient occlusion baked per vertex (`--occlusion`, method baked) as a feature: each model's
// bake runs the first frames that ask for it, within the frame's work budget, and the surface
// passes of that model read its values (shadows/occlusion_bake.h).
#include <algorithm>
#include <memory>

#include "renderer/features/feature.h"
#include "renderer/frame/frame_context.h"
#include "renderer/lighting/occlusion_factor.h"

namespace npr {
namespace {

class BakedOcclusionFeature final : public Feature, SurfaceInput {
 public:
  const char* name() const override { return "occlusion (baked)"; }
  bool active(const FrameView& f) const override { return f.settings.occlusion && f.settings.occlusionMethod == OcclusionMethod::Baked; }
  Status prepare(FrameView& f) override {
    Status status = okStatus();
    f.scene.forEach([&](Model& m) {
      if (!status || m.mesh().triangleCount() == 0) return;  // a file's points and lines alone: nothing to shade
      if (status = m.startOcclusionBake(); !status) return;
      OcclusionBake& bake = *m.occlusionBake();
      if (bake.done()) return;
      if (f.workBudgetMs <= 0.0 && f.progress) {
        // To the end now, in slices, saying how far it got.
        while (status && !bake.done()) {
          status = bake.step(250.0, f.programs, f.stats);
          f.progress("baking ambient occlusion", double(bake.directionsDone()) / bake.directions());
        }
      } else {
        status = bake.step(f.workBudgetMs, f.programs, f.stats);
      }
      if (status && bake.done()) m.occlusionBaked(f.stats);
    });
    return status;
  }
  // Baked on the pose of the first frame that asks, drawn or not: a frame range bakes at its
  // sequence's first frame, as the whole sequence does.
  Status follow(FrameView& f) override { return prepare(f); }
  void shade(const FrameView&, const Model* model, FrameContext& frame) override {
    if (!model) return;
    frame.occlusion = model->occlusionValues();  // the per-triangle paths light with it on the CPU
    frame.addInput(this);
  }
  // The GPU-lit passes read the bake from the mesh's occlusion stream once it is uploaded: per
  // vertex (mesh.vert) or interpolated per pixel (occlusion.glsl).
  void addTo(gl::MeshProgram& variant, const FrameContext& frame) const override {
    variant.occlusion = variant.shading != gl::MeshShading::LitTextured && frame.gpuMesh.hasOcclusion();
  }
  void bind(gl::ShaderProgram& program, const gl::MeshProgram& variant, const FrameContext& frame) const override {
    if (variant.occlusion) program.set("uOcclusionStrength", occlusionStrength(frame.settings.occlusionStrength));
  }
};

}  // namespace

std::unique_ptr<Feature> makeBakedOcclusionFeature() { return std::make_unique<BakedOcclusionFeature>(); }

}  // namespace npr
