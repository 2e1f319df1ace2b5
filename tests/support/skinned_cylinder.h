// The animation tests' deforming surface: mesh_generators' cylinder (y from -0.75 to 0.75)
// skinned to two joints, the lower one holding its foot and the upper one its head, their
// weights blended linearly over the middle fifth; bent by turning the upper joint about z
// around the origin. And a linear blend skinning reference written apart from deformMesh.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "renderer/mesh/mesh.h"

namespace npr::test {

Mesh skinnedCylinder(int around, int along);
// The two joints' matrices (mesh space to mesh space) with the upper one turned `degrees`.
std::vector<glm::mat4> bendJoints(float degrees);
// Vertex `i` of `m` bent by `degrees`: w0 p + w1 Rz(degrees) p, in double precision.
glm::dvec3 referenceBend(const Mesh& m, std::size_t i, double degrees);

}  // namespace npr::test
