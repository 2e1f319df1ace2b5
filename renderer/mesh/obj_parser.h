// The OBJ reader. Our own parser because OpenMesh's reader loses data we must keep: it reads
// floats (a model offset by 1e7 loses its shape), fans concave polygons, and drops faces its
// halfedge structure refuses. Every line it cannot use becomes a warning naming the line.
#pragma once

#include <string>

#include "renderer/core/result.h"
#include "renderer/mesh/mesh.h"

namespace npr {

// Parses the file's text (`path` names it in messages) and builds the mesh (not yet
// finalised: see loadMesh, which reads the file). The text is taken so it is freed before the
// mesh is built.
[[nodiscard]] Result<Mesh> parseObj(const std::string& path, std::string text);

// The file's `o` and `g` groups as meshes of their own (--split-objects), each centred and
// scaled by the loader as any mesh (its report says how, so it can be placed back). A group
// named again continues its object; faces before any group form "(no group)".
struct ObjObject {
  std::string name;
  Mesh mesh;
};
[[nodiscard]] Result<std::vector<ObjObject>> parseObjObjects(const std::string& path, std::string text);

}  // namespace npr
