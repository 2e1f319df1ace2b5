// Helpers shared by the tests: temporary files, failure images, and meshes generated in code.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

#include "renderer/mesh/mesh.h"
#include "renderer/mesh/mesh_generators.h"

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

// NAME inside the build's test-output folder (created on demand): where a failing test leaves
// images to look at, so they never land in the source tree.
std::string outputPath(const std::string& name);

using npr::icosphere;
using npr::torus;
// Writes a mesh as OBJ (what the loader benchmark and large-mesh tests read).
void writeObj(const Mesh& m, const std::string& path);
// A 2 x 2 square in the z = 0 plane facing +z, of n x n cells (two triangles each).
Mesh square(int n = 1);
// An icosphere of `level` whose every face is of one material, `name`, ambient and diffuse
// `colour` (scenes of many objects in a few materials).
Mesh sphereInMaterial(int level, const std::string& name, const glm::vec3& colour);

}  // namespace npr::test
