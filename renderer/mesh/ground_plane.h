// The ground plane (`--ground`): a square grid just under a model's lowest point, facing up,
// drawn with the same palette and path as the model and receiving its shadows (as polyscope's
// ground plane does). A grid, not one quad, so the per-vertex and per-triangle paths have
// something to vary over.
#pragma once

#include "renderer/mesh/mesh.h"

namespace npr {

// Centred under the model's bounding sphere, `extent` model radii to each side, `cells` x
// `cells` quads, at the model's lowest y less a hair (so it never z-fights the model's base).
Mesh groundPlane(const Mesh& model, float extent = 2.5f, int cells = 48);
// The same under a scene: its lowest y and the radius of a sphere about the origin holding it.
Mesh groundPlane(float lowest, float radius, float extent = 2.5f, int cells = 48);

}  // namespace npr
