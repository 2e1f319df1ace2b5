// The choices that settings make and that folders below the settings read too (the palette
// matcher reads the match mode; the path table lists the paths): kept here, at the bottom,
// so that render_settings.h includes nothing above it.
#pragma once

namespace npr {

// How a lit colour is matched against the palette's entries (palette/palette_matcher.h).
enum class MatchMode { Colors, Intensity, Order };

// The lighting model the palette matches against (lighting/lighting_state.h has what each does).
enum class ToneModel { OpenGL, Gooch, Splashback, Charcoal };

// The render paths (paths/path_table.h has their table), from fastest and coarsest to slowest
// and finest.
enum class RenderPath {
  Stencil,      // the original: per-triangle CPU lighting, stencil buckets, two quads per bucket
  Triangle,     // the same per-triangle choice in one pass, one draw per bucket
  Vertex,       // lit per vertex, matched per pixel
  Pixel,        // lit and matched per pixel
  Smooth,       // lit per pixel, two bracketing entries blended
  Reference,    // plain lit render (Phong or Gouraud), no palette
  LitTextured,  // benchmark floor: lighting times one screen-space texture fetch
};

}  // namespace npr
