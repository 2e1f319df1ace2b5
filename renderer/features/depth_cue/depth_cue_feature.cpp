// The depth cue (`--depth-cue`): tone and lines fade toward the paper with distance through
// the scene, as illustrators draw the foreground heavy and the distance light (seed 001). One
// pass over the surfaces after the lines: each model (and the ground) drawn again at the
// depth its path left, blending the palette's lightest entry over it by its eye distance, so
// every path gets it, the stencil path's quads included.
#include <algorithm>
#include <memory>

#include "renderer/features/feature.h"
#include "renderer/gl/pass_state.h"

namespace npr {
namespace {

// Over the surface at its own depth, blended, writing no depth.
constexpr gl::PassState kFade = [] {
  gl::PassState s;
  s.depthTest = s.blend = true;
  s.depthFunc = GL_LEQUAL;
  return s;
}();

class DepthCueFeature final : public Feature {
 public:
  const char* name() const override { return "depth cue"; }
  bool active(const FrameView& f) const override {
    return f.settings.depthCue.on && f.settings.depthCue.strength > 0.0f && f.palette && !f.scene.empty();
  }
  Status drawOver(FrameView& f) override {
    Result<gl::ShaderProgram*> prog = f.programs.get(gl::FeatureProgram{"depth_cue.vert", "depth_cue.frag", {}}, f.stats.shaderBuilds);
    if (!prog) return Error{prog.error()};
    // The scene's depth range as the eye sees it: its bounding sphere's front and back.
    const glm::vec4 bounds = f.scene.bounds();
    const float centre = glm::length(glm::vec3(f.camera.view * glm::vec4(glm::vec3(bounds), 1.0f)));
    const DepthCueSettings& d = f.settings.depthCue;
    gl::ShaderProgram& p = **prog;
    gl::apply(kFade);
    p.use();
    p.set("uProjection", f.camera.projection);
    p.set("uRange", glm::vec2(std::max(centre - bounds.w, 0.0f), centre + bounds.w));
    p.set("uFade", glm::vec2(d.start, d.end));
    p.set("uStrength", std::clamp(d.strength, 0.0f, 1.0f));
    p.set("uPaper", f.palette->averages().empty() ? glm::vec3(1.0f) : f.palette->averages().front());
    auto draw = [&](const GpuMesh& mesh, const glm::mat4& modelView) {
      p.set("uModelView", modelView);
      mesh.drawAll();
      ++f.stats.drawCalls;
    };
    f.scene.forEachSurface([&](Model& m) { draw(m.gpu(), f.camera.view * m.transform()); });
    if (f.settings.ground)
      if (Model* g = f.scene.ground()) draw(g->gpu(), f.camera.view);
    return okStatus();
  }
};

}  // namespace

void addDepthCueFeatures(std::vector<std::unique_ptr<Feature>>& features) { features.push_back(std::make_unique<DepthCueFeature>()); }
void DepthCueNeeds(const RenderSettings&, FrameNeeds&) {}

}  // namespace npr
