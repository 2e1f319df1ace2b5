// The OBJ reader. Our own parser because OpenMesh's reader loses data we must keep: it reads
// floats (a model offset by 1e7 loses its shape), fans concave polygons, and drops faces its
// halfedge structure refuses. Every line it cannot use becomes a warning naming the line.
#pragma once

#include <string>

#include "renderer/core/result.h"
#include "renderer/mesh/mesh.h"

namespace npr {

// Parses the file and builds the mesh (not yet finalised: see loadMesh).
[[nodiscard]] Result<Mesh> loadObj(const std::string& path);
// The same on text already in memory (`path` names it in messages): what the fuzz harness calls.
[[nodiscard]] Result<Mesh> parseObj(const std::string& path, const std::string& text);

}  // namespace npr
