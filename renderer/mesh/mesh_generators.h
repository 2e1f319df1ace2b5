// Meshes built in code: test shapes and the large meshes the benchmarks need (the project
// generates its big meshes rather than downloading them).
#pragma once

#include <optional>
#include <string>

#include "renderer/mesh/mesh.h"

namespace npr {

// A subdivided icosahedron of radius 1 (20 * 4^level triangles).
Mesh icosphere(int level);
// A torus fitted to the unit sphere, nu x nv quads: 2 nu nv triangles (660 x 660: 871,200).
Mesh torus(int nu, int nv);
// "generated:torus-871k", "generated:torus-500k", "generated:icosphere-N": what the benchmark
// accepts in place of a file name. Nothing for other names.
std::optional<Mesh> generatedMesh(const std::string& name);

}  // namespace npr
