// A mesh as one pass draws it: its GPU copy and the camera placed by its model's transform
// (the scene's view times the model's). Passes that see the whole scene (screen-space
// occlusion, image-space edges) take a list of these.
#pragma once

#include "renderer/core/camera.h"
#include "renderer/mesh/gpu_mesh.h"

namespace npr {

class GpuMaterials;

struct PlacedMesh {
  const GpuMesh* mesh;
  CameraMatrices camera;
  const GpuMaterials* materials = nullptr;  // for a see-through mesh's coverage (GpuMaterials::coverage)
};

}  // namespace npr
