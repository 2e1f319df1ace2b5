// The render paths, from fastest-and-coarsest to slowest-and-finest, in one table that the
// command line (help, validation), the overlay, the benchmark and the tests read. Adding a
// path is a file in paths/ and a row here (plus its PATH_* block in shaders/mesh.frag if it
// is a mesh shading).
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "renderer/settings/choices.h"

namespace npr {


class RenderPass;

struct PathInfo {
  RenderPath id;
  const char* name;          // on the command line, in files and reports
  const char* label;         // in the overlay
  bool userSelectable;       // offered by --path, the overlay and P; else internal (benchmark)
  bool usesPalette;
  bool perTriangle;          // lit and matched per triangle on the CPU
  std::unique_ptr<RenderPass> (*create)();
};

// Every path, in the order P cycles through the user-selectable ones.
const std::vector<PathInfo>& renderPaths();
const PathInfo& pathInfo(RenderPath p);
// The row of `p` in renderPaths().
std::size_t pathIndex(RenderPath p);
const char* renderPathName(RenderPath p);
// Any path by name, internal ones included.
std::optional<RenderPath> parseRenderPath(const std::string& name);
// The user-selectable paths, in order.
const std::vector<RenderPath>& userRenderPaths();
// "stencil, triangle, ..., reference": the user-selectable names joined by `separator`.
std::string userRenderPathNames(const std::string& separator = ", ");

}  // namespace npr
