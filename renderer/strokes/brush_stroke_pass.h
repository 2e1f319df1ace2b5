// Painterly brush strokes, part two: drawing them (the games chapter's strokes as particles).
// The particles (stroke_seeding.h) are uploaded once per mesh and density as one instance
// buffer; every frame is one instanced draw of textured, alpha-blended quads in the particles'
// fixed order (so overlaps never flicker), over the path's image and depth-tested against it.
// Culling (back-facing, thinned with distance) happens in the vertex stage, with fades.
#pragma once

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/core/camera.h"
#include "renderer/core/frame_stats.h"
#include "renderer/core/result.h"
#include "renderer/gl/gl_handle.h"
#include "renderer/gl/program_cache.h"
#include "renderer/lighting/lighting_state.h"
#include "renderer/mesh/mesh.h"
#include "renderer/palette/gpu_palette.h"
#include "renderer/settings/render_settings.h"
#include "renderer/strokes/stroke_seeding.h"

namespace npr {

class BrushStrokePass {
 public:
  // Forgets the previous mesh's strokes (seeded again on the next draw). `rest`: the mesh's
  // rest pose where `mesh` deforms (else null): strokes are seeded there and carried to the
  // pose, so which strokes there are does not depend on the pose the first draw found (a frame
  // range's frames equal the whole sequence's).
  void setMesh(const Mesh* mesh, const Mesh* rest = nullptr);
  // The mesh deformed in place: the strokes are put back on it where they were seeded (their
  // triangle and barycentric place), not seeded again.
  void geometryChanged() { moved_ = true; }
  // `directions`: the mesh's direction field (one per vertex) or empty. `sceneScale`: scene
  // units per mesh unit (the model's transform's largest axis scale), so the density is per
  // unit area of the scene, as --stroke-density says: each part of a scene of many is fitted
  // to its own unit sphere, and seeded at the whole scene's density every small part took as
  // many strokes as a whole model. Seeds first when the mesh, density or budget changed since
  // the last seeding (the scale then in force is kept: an animation that scales a model does
  // not seed it again every frame).
  [[nodiscard]] Status draw(const CameraMatrices& camera, float sceneScale, const StrokeSettings& strokes, const LightingState& lighting,
                            const GpuPalette& palette, MatchMode match, const std::vector<glm::vec3>& directions, bool fade,
                            const glm::ivec4& viewport, gl::ProgramCache& programs, FrameStats& stats);
  std::size_t strokes() const { return count_; }
  double seedMs() const { return seedMs_; }

 private:
  const Mesh* mesh_ = nullptr;
  const Mesh* rest_ = nullptr;  // where strokes are seeded when the mesh deforms
  std::vector<StrokeParticle> particles_;  // as uploaded, with where each sits
  std::vector<StrokeAnchor> anchors_;
  bool moved_ = false;  // the mesh deformed since the particles were placed
  float seededDensity_ = -1.0f;
  int seededBudget_ = -1;
  bool seededWithField_ = false;
  std::size_t count_ = 0;
  double seedMs_ = 0.0;
  gl::VertexArray vao_;
  gl::Buffer instances_;
  gl::Texture brush_;
};

}  // namespace npr
