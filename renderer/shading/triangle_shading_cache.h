// The per-triangle paths' CPU work, done only when its inputs changed: the entries and
// buckets of shadeTriangles (recomputed when the lighting as seen from the object, the
// matcher or the mesh changed), the bucketed index buffer on the GPU (uploaded when the
// buckets changed), and the stencil path's scissor rectangles (vertices projected when the
// view changed, bounds rebuilt when the view or the buckets changed).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/core/frame_stats.h"
#include "renderer/gl/gl_handle.h"
#include "renderer/lighting/lighting_model.h"
#include "renderer/lighting/lighting_state.h"
#include "renderer/palette/palette.h"
#include "renderer/mesh/mesh.h"
#include "renderer/palette/palette_matcher.h"
#include "renderer/shading/gpu_triangle_lighting.h"
#include "renderer/shading/triangle_shading.h"

namespace npr {

class TriangleShadingCache {
 public:
  // Forgets everything computed for the previous mesh. `vertices`: the mesh `mesh`'s indices
  // point into when it holds only triangles (a part of a model, mesh_subset.h), whose vertex
  // positions, colours and materials are read; null: `mesh` itself.
  void setMesh(const Mesh* mesh, const Mesh* vertices = nullptr);
  // The mesh was deformed in place (a posed mesh): lighting, buckets and bounds are worked out
  // again; what depends only on its materials is kept.
  void geometryChanged();
  // Entries and buckets for this frame, and the bucketed index buffer.
  // `materials`: light each face with the mesh's own material (when it has any).
  // `occlusion`: baked ambient occlusion per vertex (shadows/occlusion_bake.h), scaling each
  // face's ambient and diffuse by mix(1, its vertices' mean, strength); null: none.
  void update(const LightingState& lighting, const glm::mat4& modelView, const PaletteMatcher& matcher, unsigned matcherId,
              FrameStats& stats, bool materials = false, const std::vector<float>* occlusion = nullptr, float occlusionStrength = 1.0f);
  // update()'s lighting alone, without GL (no upload): safe on another thread, one per cache.
  // An update() with the same arguments afterwards finds it done and only uploads.
  void prepare(const LightingState& lighting, const glm::mat4& modelView, const PaletteMatcher& matcher, unsigned matcherId,
               FrameStats& stats, bool materials = false, const std::vector<float>* occlusion = nullptr, float occlusionStrength = 1.0f);
  // Entries lit and matched on the GPU instead (gpu()): buckets built from them and uploaded;
  // the next CPU update recomputes whatever its key says.
  void setEntries(std::vector<std::uint8_t>&& entries, int paletteSize, FrameStats& stats);
  // A palette with rows (palette.h): each triangle's entry becomes its layer, the row the
  // axis gives at its centroid with its face normal (the nearest row) as seen through
  // `modelView`. Redone when the entries or the view changed; the lighting is not.
  void applyRows(const PaletteAxis& axis, const glm::vec2& axisMap, int columns, const glm::mat4& modelView, FrameStats& stats,
                 float detail = 0.0f);
  // Set before update() or setEntries() when applyRows follows: they then leave the buckets
  // (and their upload) to it.
  void expectRows(bool rows) { rowsNext_ = rows; }
  GpuTriangleLighting& gpu() { return gpu_; }
  // The screen rectangle of each bucket (after update), for `modelViewProjection` and a
  // viewport of `size` pixels.
  void updateBounds(const glm::mat4& modelViewProjection, const glm::ivec2& size, FrameStats& stats);

  const TriangleShading& shading() const { return shading_; }
  // Buckets: one per palette entry matched, or per layer once rows are applied (applyRows).
  int buckets() const { return static_cast<int>(shading_.bucketStart.size()) - 1; }
  // Vertex indices grouped by bucket; bucket k is bucketCount(k) triangles from bucketFirst(k).
  const gl::Buffer& bucketIndices() const { return bucketIndices_; }
  std::uint32_t bucketFirst(int k) const { return shading_.bucketStart[static_cast<size_t>(k)]; }
  std::uint32_t bucketCount(int k) const {
    return shading_.bucketStart[static_cast<size_t>(k) + 1] - shading_.bucketStart[static_cast<size_t>(k)];
  }

 private:
  const Mesh* mesh_ = nullptr;
  const Mesh* vertices_ = nullptr;  // mesh_ or the whole it is part of
  unsigned meshId_ = 0;  // bumped per setMesh
  TriangleShading shading_;
  gl::Buffer bucketIndices_;
  struct Key {
    unsigned mesh = 0, matcher = 0;
    PreparedLighting<float> lighting, probe;
    bool materials = false;
    const float* occlusion = nullptr;
    float occlusionStrength = 0.0f;
    bool valid = false;
  } key_;
  // The face scale with occlusion folded in, rebuilt when its inputs change.
  std::vector<glm::u8vec4> occludedScale_;
  const float* occludedWith_ = nullptr;
  float occludedStrength_ = -1.0f;
  bool occludedMaterials_ = false;
  std::vector<glm::u8vec4> faceScale_;  // faceColourScale, packed once per mesh when materials are drawn
  int singleMaterial_ = -1;  // the material of every face, when they all have one
  bool faceScaleValid_ = false;
  bool bucketsUploaded_ = false;
  // applyRows: the matched columns (shading_.entry holds layers once rows are applied), and
  // what the layers were worked out for.
  std::vector<std::uint8_t> columns_;
  bool columnsFresh_ = false;  // shading_.entry was just matched (columns, not layers)
  bool layered_ = false;       // shading_.entry holds layers
  bool rowsNext_ = false;
  int rowsCount_ = 0;
  float rowsDetail_ = -1.0f;
  glm::mat4 rowsView_{0.0f};
  glm::vec2 rowsMap_{0.0f};
  GpuTriangleLighting gpu_;
  // Scissor bounds: vertices projected once per view, bounds once per change of the buckets
  // or the view.
  std::vector<glm::vec2> screenVertices_;
  glm::mat4 projectedWith_{0.0f};
  glm::ivec2 projectedSize_{0};
  unsigned projectedMesh_ = 0;
  bool boundsValid_ = false;
};

}  // namespace npr
