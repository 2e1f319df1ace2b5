// Our readers for the mesh formats beside OBJ: PLY (ascii and binary, either byte order), OFF
// (ascii), STL (ascii and binary) and glTF 2.0 (through tinygltf, every accessor checked here). OpenMesh's own readers crash, hang or exhaust memory on
// small hostile files (a PLY property before its element, an OFF header alone, absurd element
// counts), so every header is validated against the file's size before anything is allocated,
// and OpenMesh only ever sees the triangles FaceBuilder accepted. Coordinates are read in
// double precision where the file has them. OM, OpenMesh's own format, is read by OpenMesh in
// an isolated child process (om_reader.cpp).
#pragma once

#include <string>

#include "renderer/core/result.h"
#include "renderer/mesh/mesh.h"
#include "renderer/mesh/scene_description.h"

namespace npr {

// Each parses a whole file already in memory (`name` stands for it in messages) and builds the
// mesh (not yet finalised: see loadMesh, which reads the file). The bytes are taken so they
// are freed before the mesh is built.
[[nodiscard]] Result<Mesh> parsePly(const std::string& name, std::string bytes);
[[nodiscard]] Result<Mesh> parseOff(const std::string& name, std::string bytes);
[[nodiscard]] Result<Mesh> parseStl(const std::string& name, std::string bytes);
// glTF 2.0 (.gltf, .glb): the default scene flattened into one mesh (gltf_reader.cpp).
[[nodiscard]] Result<Mesh> parseGltf(const std::string& name, std::string bytes);
// glTF 2.0 as a scene: one object per node with a mesh (meshes finalised, shared by the nodes
// that instance them), the cameras and the lights, all in the file's space.
[[nodiscard]] Result<LoadedScene> parseGltfScene(const std::string& name, std::string bytes);
// OM is read from the file by OpenMesh in a child process; `seconds` bounds that process.
[[nodiscard]] Result<Mesh> loadOm(const std::string& path, int seconds = 30);

}  // namespace npr
