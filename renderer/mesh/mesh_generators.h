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
// An open cylinder about the y axis, radius 0.5 and height 1.5, nu around x nv along: its seam
// has duplicated vertices (as a file split for texture coordinates would), its ends are
// boundaries. The hatching direction tests' surface with one direction of curvature.
Mesh cylinder(int nu, int nv);
// An ellipsoid with semi-axes `radii` as a latitude-longitude grid (nu around y, nv from pole to
// pole; one vertex per pole).
Mesh ellipsoid(int nu, int nv, const glm::vec3& radii);
// "generated:torus-871k", "generated:torus-500k", "generated:icosphere-N", "generated:cylinder",
// "generated:ellipsoid": what the benchmark
// accepts in place of a file name. Nothing for other names.
std::optional<Mesh> generatedMesh(const std::string& name);

}  // namespace npr
