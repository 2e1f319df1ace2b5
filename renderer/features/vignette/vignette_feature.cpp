// The vignette (`--vignette`): the picture fades into the paper toward the frame's edges, as
// book illustrations were printed. One full-screen pass after everything else (the depth cue
// included), blending the palette's paper (its first entry's average) over the viewport, so it
// suits every path and style. A poster's tiles each fade at their own edges (the pass sees one
// viewport).
#include <algorithm>
#include <memory>
#include <vector>

#include "renderer/features/feature.h"
#include "renderer/gl/pass_state.h"
#include "renderer/programs/program_variants.h"

namespace npr {
namespace {

// Over the viewport only (the split view draws two), blended, no depth.
constexpr gl::PassState kVignette = [] {
  gl::PassState s;
  s.blend = s.scissor = true;
  return s;
}();

class VignetteFeature final : public Feature {
 public:
  const char* name() const override { return "vignette"; }
  bool active(const FrameView& f) const override { return f.settings.vignette.on && f.settings.vignette.strength > 0.0f && f.palette; }
  Status drawOver(FrameView& f) override {
    Result<gl::ShaderProgram*> prog = f.programs.get(gl::FeatureProgram{"fullscreen.vert", "vignette.frag", {}}, f.stats.shaderBuilds);
    if (!prog) return Error{prog.error()};
    const VignetteSettings& v = f.settings.vignette;
    gl::ShaderProgram& p = **prog;
    gl::apply(kVignette);
    p.use();
    p.set("uViewport", glm::vec4(f.viewport));
    p.set("uRadius", std::clamp(v.radius, 0.0f, 1.0f));
    p.set("uSoftness", std::clamp(v.softness, 0.0f, 1.0f));
    p.set("uStrength", std::clamp(v.strength, 0.0f, 1.0f));
    p.set("uPaper", f.palette->averages().empty() ? glm::vec3(1.0f) : f.palette->averages().front());
    glBindVertexArray(f.emptyVao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    ++f.stats.drawCalls;
    return okStatus();
  }
};

}  // namespace

void addVignetteFeatures(std::vector<std::unique_ptr<Feature>>& features) { features.push_back(std::make_unique<VignetteFeature>()); }
void VignetteNeeds(const RenderSettings&, FrameNeeds&) {}

}  // namespace npr
