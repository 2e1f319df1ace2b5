// First-scene set-up from the command line (see startup.h).
#include "app/startup.h"

#include <algorithm>

#include "app/style_file.h"

namespace npr {

Status startScene(const Options& o, ViewerState& state, Renderer& renderer) {
  applyDefaultMaterial(renderer.lighting());
  const std::string model = o.models.empty() ? defaultModelPath() : o.models.front();
  if (Status s = state.loadModel(model, renderer); !s) return s;
  state.palettes = discoverPalettes();
  const std::string first = o.palettes.empty() ? defaultPalettePath() : o.palettes.front();
  for (const auto& p : o.palettes)
    if (std::find(state.palettes.begin(), state.palettes.end(), p) == state.palettes.end()) state.palettes.push_back(p);
  if (Status s = state.loadPalette(first, renderer); !s) return s;
  // A style sets the look; what the command line names beside it wins.
  if (!o.style.empty()) {
    Result<Style> style = loadStyle(resolveStyle(o.style));
    if (!style) return Error{style.error()};
    if (!o.palettes.empty()) style->palette.reset();
    if (Status s = applyStyle(*style, state, renderer); !s) return s;
  }
  for (const auto& [material, file] : o.materialPalettes)
    if (Status s = state.setMaterialPalette(material, file, renderer); !s) return s;
  if (!o.shadowPalette.empty())
    if (Status s = state.setControlPalette(ControlParameter::Shadow, o.shadowPalette, renderer); !s) return s;
  if (!o.occlusionPalette.empty())
    if (Status s = state.setControlPalette(ControlParameter::Occlusion, o.occlusionPalette, renderer); !s) return s;
  if (o.path) state.settings.path = *o.path;
  if (o.match) state.settings.match = *o.match;
  if (o.rangeScale) state.settings.rangeScale = *o.rangeScale;
  state.settings.referenceGouraud = o.gouraud;
  state.settings.materials = o.materials;
  if (o.pattern) state.settings.pattern = *o.pattern;
  state.settings.patternFollowsRotation = !o.patternNoRotation;
  if (o.patternScale) state.settings.patternScale = *o.patternScale;
  if (o.patternLinear) state.settings.patternLinearFilter = true;
  if (o.orient) state.settings.orient = *o.orient;
  if (o.orientBins) state.settings.orient.bins = *o.orientBins;
  if (o.ground) state.settings.ground = true;
  if (o.shadows) state.settings.shadows = true;
  if (o.occlusion) state.settings.occlusion = true;
  if (o.occlusionStrength) state.settings.occlusionStrength = *o.occlusionStrength;
  if (o.occlusionMethod) state.settings.occlusionMethod = *o.occlusionMethod;
  state.settings.triangleLighting = o.triangleLighting;
  if (o.naiveStencil) state.settings.stencilScissor = state.settings.stencilSkipEmpty = state.settings.stencilMasksFirst = false;
  if (!o.bands.empty()) state.settings.bands = o.bands;
  StrokeSettings& strokes = state.settings.strokes;
  if (o.strokes) strokes.on = true;
  if (o.strokeDensity) strokes.density = *o.strokeDensity;
  if (o.strokeBudget) strokes.budget = *o.strokeBudget;
  if (o.strokeSize) strokes.length = o.strokeSize->x, strokes.width = o.strokeSize->y;
  LineSettings& lines = state.settings.lines;
  if (o.lineKinds) {
    lines.silhouettes = o.lineKinds->silhouettes;
    lines.creases = o.lineKinds->creases;
    lines.boundaries = o.lineKinds->boundaries;
    lines.imageSpace = o.lineKinds->imageSpace;
    lines.hardware = o.lineKinds->hardware;
    lines.rim = o.lineKinds->rim;
  }
  if (o.outlineMethod) lines.outline = *o.outlineMethod;
  if (o.outlineOffset) lines.outlineOffset = *o.outlineOffset;
  if (o.sketchy) lines.sketchy = true;
  if (o.lineFalloff) lines.depthFalloff = true;
  if (o.creaseAngle) lines.creaseAngle = *o.creaseAngle;
  if (o.lineWidth) lines.width = *o.lineWidth;
  if (o.tone)
    if (Status s = renderer.lighting().setToneModel(*o.tone, renderer.lighting().toneParameters()); !s) return s;
  if (o.light) state.light = *o.light;
  if (o.camera) state.camera.setYawPitchDistance(o.camera->x, o.camera->y, o.camera->z * state.camera.modelRadius());
  state.noteIdleControlPalettes();
  return okStatus();
}

}  // namespace npr
