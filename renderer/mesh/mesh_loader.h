// Loading meshes from files: OBJ through our own parser (obj_parser.h: double precision,
// ear-clipped polygons, every face it cannot use reported), PLY/OFF/STL through our own readers
// and OM through OpenMesh's in a child process (mesh_formats.h). Nothing is dropped without a
// warning in the report, and OpenMesh's halfedge structure only sees faces it accepts.
#pragma once

#include <string>

#include "renderer/core/result.h"
#include "renderer/mesh/mesh.h"

namespace npr {

[[nodiscard]] Result<Mesh> loadMesh(const std::string& path);
// What the command line and the viewer accept as a model: a generated mesh's name
// ("generated:torus-871k", see mesh_generators.h) or a file for loadMesh.
[[nodiscard]] Result<Mesh> loadModel(const std::string& nameOrPath);

}  // namespace npr
