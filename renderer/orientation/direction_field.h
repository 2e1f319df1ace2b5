// The hatching direction field: one tangent direction per vertex that strokes follow.
// Principal curvature directions (principal_curvature.h) are kept where the surface is clearly
// curved one way; elsewhere (flat, spherical or saddle-symmetric regions, where they are noise)
// the direction is smoothed in from around as a 4-way cross field (Hertzmann and Zorin 2000,
// "Illustrating Smooth Surfaces"): a direction and its quarter turns are one value, so the two
// principal directions never fight. The cross field is then combed into one direction per vertex,
// spreading from the most clearly curved vertices, so that neighbours pick the same one of the
// four and the direction can be interpolated across triangles.
//
// Computed once per mesh (seconds at most, in parallel) and kept by the renderer while the mesh
// stays; never NaN: a vertex with no surface around it gets a zero direction, which the shaders
// read as "leave the palette unrotated".
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/mesh/mesh.h"

namespace npr {

struct DirectionFieldOptions {
  int smoothingIterations = 24;
  // A vertex is "clearly curved one way" from |k1| > 2 |k2| (anisotropy 1/3) on, fully at 0.6,
  // and only where |k1| - |k2| is above `flatCurvature` (the mesh is fitted to the unit sphere).
  float flatCurvature = 0.05f;
  // How hard a vertex's own curvature direction holds it during smoothing, against its
  // neighbours' mean (times its confidence and its neighbour count). At 2 the bunny's field
  // kept 84 singular triangles (a star of strokes at the hip); at 0.25, 30, while the fields on
  // the cylinder, torus and ellipsoids stay within 3 degrees of the principal directions
  // (test_orientation). A closed surface keeps some (a sphere's field turns twice in all).
  float curvatureWeight = 0.25f;
};

struct DirectionField {
  std::vector<glm::vec3> directions;  // per mesh vertex: unit tangent, or zero
  std::vector<float> confidence;      // per mesh vertex, in [0, 1]: how much curvature decided it
  std::size_t weldedVertices = 0;
  double ms = 0.0;
};

DirectionField computeDirectionField(const Mesh& mesh, const DirectionFieldOptions& options = {});

}  // namespace npr
