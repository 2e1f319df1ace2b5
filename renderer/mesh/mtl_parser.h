// The OBJ material library (.mtl) reader: newmtl, Ka, Kd, Ks, Ke, Ns, d/Tr, illum and the
// map_Kd / map_Ka / map_d texture statements, mapped to OpenGL's material (see MeshMaterial).
// Unknown statements are ignored; a malformed one is a warning naming the file and line and
// leaves that value at its default. Texture paths are resolved against the library's folder
// (backslashes read as separators, spaces kept), not loaded here.
#pragma once

#include <string>
#include <vector>

#include "renderer/mesh/mesh.h"

namespace npr {

class Warnings;

struct MtlMaterial {
  MeshMaterial material;  // diffuseMap / opacityMap not yet set
  std::string diffuseMapPath, ambientMapPath, opacityMapPath;  // resolved; empty: none
  std::string where;      // "file.mtl line 3", for messages about its textures
};

// Parses the text of the library at `path`, appending its materials to `out`.
void parseMtl(const std::string& path, const std::string& text, std::vector<MtlMaterial>& out, Warnings& warnings);

// A texture file name as an .mtl gives it ("..\tex\wood 1.jpg") resolved against `folder`: the
// path as written if it exists, else the file name alone in `folder` (exporters often write
// absolute paths from the artist's machine). Returns the first candidate when neither exists.
std::string resolveMaterialFile(const std::string& folder, const std::string& name);

}  // namespace npr
