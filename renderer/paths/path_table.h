// The render paths users choose between, from fastest-and-coarsest to slowest-and-finest,
// with the names the command line and the viewer show.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace npr {

enum class RenderPath {
  Stencil,      // the original: per-triangle CPU lighting, stencil buckets, two quads per bucket
  Triangle,     // the same per-triangle choice in one pass (texture array, gl_PrimitiveID)
  Vertex,       // lit per vertex, matched per pixel
  Pixel,        // lit and matched per pixel
  Smooth,       // lit per pixel, two bracketing entries blended
  Reference,    // plain lit render (Phong or Gouraud), no palette
  LitTextured,  // benchmark floor: lighting plus one screen-space texture fetch
};

const char* renderPathName(RenderPath p);
std::optional<RenderPath> parseRenderPath(const std::string& s);
// The paths a user can pick, in the order P cycles through them.
const std::vector<RenderPath>& userRenderPaths();

}  // namespace npr
