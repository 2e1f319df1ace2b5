// Whether triangles form an oriented 2-manifold, checked in linear time: every directed edge
// used once, and the triangles around every vertex one fan (a disk or a half-disk). Such
// triangles are what the halfedge structure takes in any order with none refused, so the mesh
// builder can skip building it (mesh_builder.cpp): on a glTF scene of 16 meshes it was half the
// load. Anything else (a duplicate or flipped face, three faces on an edge, two fans touching at
// a vertex, a vertex on more than kMaxFanDegree triangles) answers false, and the builder lets
// OpenMesh decide which faces are refused, as before.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace npr {

inline constexpr std::size_t kMaxFanDegree = 64;

// `triangles` name vertices in [0, vertexCount), three distinct each.
bool formsManifoldFans(const std::vector<std::array<int, 3>>& triangles, std::size_t vertexCount);

}  // namespace npr
