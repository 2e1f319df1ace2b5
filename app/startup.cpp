// First-scene set-up from the command line (see startup.h).
#include "app/startup.h"

#include <algorithm>

#include "app/settings/style_file.h"

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
  if (Status s = applySettings(o.settings, false, state, renderer); !s) return s;
  if (o.camera) state.camera.setYawPitchDistance(o.camera->x, o.camera->y, o.camera->z * state.camera.modelRadius());
  state.noteIdleControlPalettes();
  if (!o.saveStyle.empty())
    if (Status s = saveStyle(state, renderer, o.style.empty() ? "Saved style" : o.style, o.saveStyle); !s) return s;
  return okStatus();
}

}  // namespace npr
