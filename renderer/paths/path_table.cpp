// Render path names (see render_path.h).
#include "renderer/paths/path_table.h"

namespace npr {

const char* renderPathName(RenderPath p) {
  switch (p) {
    case RenderPath::Stencil: return "stencil";
    case RenderPath::Triangle: return "triangle";
    case RenderPath::Vertex: return "vertex";
    case RenderPath::Pixel: return "pixel";
    case RenderPath::Smooth: return "smooth";
    case RenderPath::Reference: return "reference";
    case RenderPath::LitTextured: return "lit-textured";
  }
  return "?";
}

std::optional<RenderPath> parseRenderPath(const std::string& s) {
  for (RenderPath p : {RenderPath::Stencil, RenderPath::Triangle, RenderPath::Vertex, RenderPath::Pixel, RenderPath::Smooth,
                       RenderPath::Reference, RenderPath::LitTextured})
    if (s == renderPathName(p)) return p;
  return std::nullopt;
}

const std::vector<RenderPath>& userRenderPaths() {
  static const std::vector<RenderPath> paths = {RenderPath::Stencil, RenderPath::Triangle, RenderPath::Vertex,
                                                RenderPath::Pixel, RenderPath::Smooth, RenderPath::Reference};
  return paths;
}

}  // namespace npr
