// Painterly brush strokes, part one: where they sit. Stroke particles are seeded once per mesh
// (and density) on its surface, so they stay put as the camera moves (the games chapter's
// "strokes as particles"). Blue noise over the surface area: dart throwing in three passes of
// shrinking radius over area-weighted candidates; a stroke's rank is its place in the order
// taken (coarse passes first), so any prefix of the ranks is itself spread evenly, which is what
// lets the stroke pass thin them out smoothly with distance (brush_stroke_pass.h).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/mesh/mesh.h"

namespace npr {

struct StrokeParticle {
  glm::vec3 position;
  glm::vec3 normal;     // the surface's, interpolated (unit)
  glm::vec3 direction;  // the direction field's there, in the tangent plane (unit), or zero
  float rank;           // in [0, 1): strokes below the kept fraction are drawn
  float seed;           // in [0, 1): size and angle jitter
};

// Where a particle sits on the surface: its triangle and barycentric (u, v) of its second and
// third corners, so a deforming mesh carries it (placeStrokes).
struct StrokeAnchor {
  std::uint32_t face = 0;
  float u = 0.0f, v = 0.0f;
};

struct StrokeSeeding {
  std::vector<StrokeParticle> particles;
  std::vector<StrokeAnchor> anchors;  // one per particle
  float area = 0;  // the mesh's surface area
  double ms = 0;
};

// `density` strokes per unit of surface area (the mesh fitted to the unit sphere), at most
// `budget`. `directions`: one per vertex (orientation/direction_field.h) or empty. Never NaN;
// zero-area and degenerate triangles get no strokes. Deterministic for a given mesh.
StrokeSeeding seedStrokes(const Mesh& mesh, float density, int budget, const std::vector<glm::vec3>& directions);
// Each particle put back on `mesh` (the seeded mesh, deformed since) at its anchor: position,
// normal and direction as seeding makes them; rank and seed kept.
void placeStrokes(const Mesh& mesh, const std::vector<glm::vec3>& directions, const std::vector<StrokeAnchor>& anchors,
                  std::vector<StrokeParticle>& particles);

}  // namespace npr
