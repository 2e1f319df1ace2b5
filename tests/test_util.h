// Helpers shared by the tests: temporary files, and meshes generated in code.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

#include "renderer/mesh.h"

namespace npr::test {

// A fresh folder under the system temp dir, removed when the object dies.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  const std::filesystem::path& path() const { return path_; }
  std::string write(const std::string& name, const std::string& content) const;

 private:
  std::filesystem::path path_;
};

// A subdivided icosahedron of radius 1 (20 * 4^level triangles).
Mesh icosphere(int level);
// A torus (radii 1 and 0.35) of nu x nv quads, 2 nu nv triangles: large meshes on demand.
Mesh torus(int nu, int nv);
// Writes a mesh as OBJ (what the loader benchmark and large-mesh tests read).
void writeObj(const Mesh& m, const std::string& path);

}  // namespace npr::test
