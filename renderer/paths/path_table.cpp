// The path table (see path_table.h).
#include "renderer/paths/path_table.h"

#include "renderer/paths/render_pass.h"
#include "renderer/paths/shaded_path.h"
#include "renderer/paths/stencil_path.h"
#include "renderer/paths/triangle_path.h"

namespace npr {
namespace {

template <class Pass, auto... Args>
std::unique_ptr<RenderPass> make() {
  return std::make_unique<Pass>(Args...);
}

}  // namespace

const std::vector<PathInfo>& renderPaths() {
  // clang-format off
  static const std::vector<PathInfo> table = {
    // id                     name            label                                user   palette per-triangle
    {RenderPath::Stencil,     "stencil",      "stencil (original, per triangle)",  true,  true,  true,  make<StencilPath>},
    {RenderPath::Triangle,    "triangle",     "triangle (one pass, per triangle)", true,  true,  true,  make<TrianglePath>},
    {RenderPath::Vertex,      "vertex",       "vertex (lit per vertex)",           true,  true,  false, make<ShadedPath, ShadedPath::Kind::Vertex>},
    {RenderPath::Pixel,       "pixel",        "pixel (lit per pixel)",             true,  true,  false, make<ShadedPath, ShadedPath::Kind::Pixel>},
    {RenderPath::Smooth,      "smooth",       "smooth (blended entries)",          true,  true,  false, make<ShadedPath, ShadedPath::Kind::Smooth>},
    {RenderPath::Reference,   "reference",    "reference (lit, no palette)",       true,  false, false, make<ShadedPath, ShadedPath::Kind::Reference>},
    {RenderPath::LitTextured, "lit-textured", "lit-textured (benchmark floor)",    false, true,  false, make<ShadedPath, ShadedPath::Kind::LitTextured>},
  };
  // clang-format on
  return table;
}

std::size_t pathIndex(RenderPath p) {
  const auto& table = renderPaths();
  for (std::size_t i = 0; i < table.size(); ++i)
    if (table[i].id == p) return i;
  return 0;  // unreachable: every enumerator has a row (tested)
}

const PathInfo& pathInfo(RenderPath p) { return renderPaths()[pathIndex(p)]; }

const char* renderPathName(RenderPath p) { return pathInfo(p).name; }

std::optional<RenderPath> parseRenderPath(const std::string& name) {
  for (const PathInfo& info : renderPaths())
    if (name == info.name) return info.id;
  return std::nullopt;
}

const std::vector<RenderPath>& userRenderPaths() {
  static const std::vector<RenderPath> paths = [] {
    std::vector<RenderPath> v;
    for (const PathInfo& info : renderPaths())
      if (info.userSelectable) v.push_back(info.id);
    return v;
  }();
  return paths;
}

std::string userRenderPathNames(const std::string& separator) {
  std::string s;
  for (RenderPath p : userRenderPaths()) s += (s.empty() ? "" : separator) + renderPathName(p);
  return s;
}

}  // namespace npr
