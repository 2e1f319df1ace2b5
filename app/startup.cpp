// First-scene set-up from the command line (see startup.h).
#include "app/startup.h"

#include <algorithm>

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
  if (o.path) state.settings.path = *o.path;
  if (o.match) state.settings.match = *o.match;
  if (o.rangeScale) state.settings.rangeScale = *o.rangeScale;
  state.settings.referenceGouraud = o.gouraud;
  if (o.naiveStencil) state.settings.stencilScissor = state.settings.stencilSkipEmpty = false;
  if (o.light) state.light = *o.light;
  if (o.camera) state.camera.setYawPitchDistance(o.camera->x, o.camera->y, o.camera->z * state.camera.modelRadius());
  return okStatus();
}

}  // namespace npr
