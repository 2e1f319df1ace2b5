// Turning parsed positions and triangles into a Mesh, shared by every reader: positions
// centred and scaled into the unit sphere in double precision before they become float, and
// triangles added to OpenMesh's halfedge structure with the faces it refuses kept on copied
// vertices (never dropped, never handed to OpenMesh in a form it asserts on).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/mesh/mesh.h"

namespace npr {

// `valid` (optional) marks the positions to fit; the others are transformed but not counted.
std::vector<glm::vec3> normalizePositions(const std::vector<glm::dvec3>& positions, const std::vector<char>* valid,
                                          LoadReport& report);
// Fills mesh.positions and mesh.indices. Takes its inputs so they are freed once the halfedge
// structure holds them (an 871K-triangle load peaks here).
// When `vertexOrigin` / `faceOrigin` are given, they receive for every mesh vertex the input
// vertex it is (or was copied from, for a refused face) and for every mesh triangle its input
// triangle, so per-vertex and per-face attributes can follow.
void buildTriMesh(std::vector<glm::vec3> positions, std::vector<std::array<int, 3>> triangles, Mesh& mesh,
                  std::vector<std::uint32_t>* vertexOrigin = nullptr, std::vector<std::uint32_t>* faceOrigin = nullptr);

}  // namespace npr
