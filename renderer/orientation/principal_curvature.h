// Principal curvatures and directions per vertex of a triangle mesh, after Rusinkiewicz 2004
// ("Estimating Curvatures and Their Derivatives on Triangle Meshes"): each face fits its
// second fundamental form to the change of the vertex normals along its three edges; each
// vertex averages the forms of its faces, turned into its own tangent plane and weighted by
// area, and takes the eigenvectors. What the hatching direction field starts from
// (direction_field.h).
//
// Works on a welded copy (mesh/weld.h): seams split for texture coordinates or materials
// would otherwise cut the surface, and a polygon soup would have no neighbours at all.
// Degenerate and zero-area faces are left out; a vertex no face reaches keeps a zero normal
// and zero curvature. Nothing is NaN.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/mesh/mesh.h"
#include "renderer/mesh/weld.h"

namespace npr {

struct PrincipalCurvatures {
  WeldedPositions weld;
  std::vector<std::array<std::uint32_t, 3>> triangles;  // welded, with area
  std::vector<glm::vec3> normals;                        // per welded vertex, area-weighted; zero if isolated
  // Edge neighbours per welded vertex (compressed rows): neighbours[start[v] .. start[v + 1]).
  std::vector<std::uint32_t> neighbourStart, neighbours;
  // Per welded vertex: the unit tangent along which |k| is largest, and the curvatures along
  // it and across it (signed; positive where the surface bends away from its normal).
  std::vector<glm::vec3> maxDirection;
  std::vector<float> kMax, kMin;
};

PrincipalCurvatures estimatePrincipalCurvatures(const Mesh& mesh);

// An orthonormal tangent basis (t1, t2) of the plane with unit normal `n`, continuous except
// where n crosses between the two helper axes.
void tangentBasis(const glm::vec3& n, glm::vec3& t1, glm::vec3& t2);

}  // namespace npr
