// The viewer's look where it differs from the renderer's defaults: what a user meets first on
// a model no one tuned for. The renderer keeps the original's semantics (the palette's own
// range) for its API and tests; the viewer, its style files and the settings table start here.
#pragma once

#include "renderer/settings/render_settings.h"

namespace npr {

inline RenderSettings viewerDefaultSettings() {
  RenderSettings s;
  // Each object's tones fitted onto the palette's levels: a near-black or near-white material
  // reads as the palette's dark or light end with its light and form, not as a blob (issue 57).
  s.toneRange = ToneRange::PerObject;
  // Silhouettes outlined: a dark object keeps its shape against dark hatching or a ground.
  s.lines.silhouettes = true;
  // Tone edges anti-aliased in the shader: about 1.1x the bunny's frame on llvmpipe (issue 57;
  // docs/lines-and-tone.md), for the window and stills alike. Supersampling stays a choice.
  s.aa = AntiAliasing::Edges;
  return s;
}

}  // namespace npr
