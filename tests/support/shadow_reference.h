// The shadows' reference: which pixels a directional light cannot reach, by casting a ray
// from each covered pixel's surface point toward the light through the mesh's triangles on the
// CPU, against what the renderer drew (the frame with shadows darker than without). The shadow
// tests' and the benchmark's agreement measure.
#pragma once

#include <cstddef>

#include "renderer/core/camera.h"
#include "renderer/core/image.h"
#include "renderer/mesh/mesh.h"

namespace npr::test {

struct ShadowAgreement {
  double agreement = 0.0;      // share of compared pixels where reference and render agree
  std::size_t compared = 0;    // covered, lit side (N.L > 0.3), outside the edge band
  std::size_t shadowed = 0;    // of those, shadowed in the reference
};

// `eyePositions`/`eyeNormals`: the model's geometry outputs for `camera` (rows top first);
// `lit`/`shadowed`: the same frame without and with shadows; `toLight`: model space, unit.
// Pixels within `band` pixels of a change in the reference's classification are left out.
ShadowAgreement compareShadows(const Mesh& mesh, const glm::vec3& toLight, const CameraMatrices& camera, const ImageRGBA32F& eyePositions,
                               const ImageRGBA32F& eyeNormals, const ImageRGBA8& lit, const ImageRGBA8& shadowed, int band = 2);

}  // namespace npr::test
