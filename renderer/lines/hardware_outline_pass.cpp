// Hardware outlines and the charcoal rim (see hardware_outline_pass.h).
#include "renderer/lines/hardware_outline_pass.h"

#include <algorithm>

#include "renderer/gl/pass_state.h"

namespace npr {

Status drawHardwareOutlines(const GpuMesh& mesh, const CameraMatrices& camera, const LineSettings& ls, const GpuPalette* palette,
                            const PatternPlacement& pattern, MatchMode match, const glm::ivec4& viewport, gl::ProgramCache& programs, FrameStats& stats) {
  struct Draw {
    gl::OutlineProgram variant;
    bool on;
  };
  gl::OutlineProgram rim;
  if (palette) {
    rim.palette = palette->variant(match, pattern);
    rim.palette->orientBins = 0;  // the rim is a smudge along the outline: not turned
    // The rim's faces are fattened past the surface: no object-space position to map, so the
    // object-space pattern is read in screen space there, through the scaled mapping (the
    // pattern scale and, with a linear filter, the sRGB view the palette binds then).
    if (rim.palette->pattern == gl::PatternMapping::Object) rim.palette->pattern = gl::PatternMapping::Scaled;
  }
  const Draw draws[] = {{gl::OutlineProgram{ls.outline, std::nullopt}, ls.hardware}, {rim, ls.rim && palette != nullptr}};
  for (const Draw& d : draws) {
    if (!d.on) continue;
    Result<gl::ShaderProgram*> prog = programs.get(d.variant, stats.shaderBuilds);
    if (!prog) return Error{prog.error()};
    gl::ShaderProgram& p = **prog;
    gl::apply(!d.variant.rim() && d.variant.method == OutlineMethod::Offset ? gl::pass::kOutlineBackFaces : gl::pass::kOutline);
    p.use();
    p.set("uModelView", camera.view);
    p.set("uProjection", camera.projection);
    if (!d.variant.rim() && d.variant.method == OutlineMethod::Offset) {
      p.set("uOffset", std::clamp(ls.outlineOffset, LineSettings::kMinOutlineOffset, LineSettings::kMaxOutlineOffset));
    } else {
      p.set("uViewport", glm::vec2(viewport.z, viewport.w));
      p.set("uWidth", std::max(ls.width, 0.5f));
    }
    if (d.variant.rim()) {
      p.set("uRimLimit", std::clamp(ls.rimLimit, 0.0f, 1.0f));
      palette->bind(p, pattern, false);
    } else {
      p.set("uColour", ls.silhouetteColour);
    }
    mesh.drawAll();
    ++stats.drawCalls;
  }
  return okStatus();
}

}  // namespace npr
