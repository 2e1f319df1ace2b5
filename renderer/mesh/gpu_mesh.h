// A mesh on the GPU: positions and normals (attributes 0 and 1 of mesh.vert; with an
// appearance also colours, texture coordinates, material indices and map averages, 2-5; the hatching
// direction field, 6; baked ambient occlusion, 7; a deforming mesh's rest pose, 8-9), its index
// buffer, and the vertex array that binds them. Draws the whole mesh or a range of triangles
// of another index buffer over the same vertices (the per-triangle paths' buckets).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "renderer/core/camera.h"
#include "renderer/gl/gl_handle.h"
#include "renderer/gl/shader_program.h"
#include "renderer/mesh/mesh.h"

namespace npr {

// Triangles `first` to `first + count` of a mesh's own index buffer, all of `material`.
struct MaterialRun {
  std::uint16_t material = 0;
  std::uint32_t first = 0, count = 0;
};

class GpuMesh {
 public:
  // Uploads `mesh` (replacing what was there); an empty mesh leaves nothing to draw.
  void upload(const Mesh& mesh);
  // A part of `base` (a per-material palette's faces): `part` holds some of base's mesh's faces
  // over the same vertices (mesh_subset.h). Only its index buffer is its own; it draws through
  // base's vertex buffers, which must outlive it. Call shareStreamsOf again after base uploads
  // its direction field or occlusion.
  void uploadPart(const GpuMesh& base, const Mesh& part);
  void shareStreamsOf(const GpuMesh& base);
  void clear();
  // `mesh` (the one uploaded, deformed since) has new positions and normals: they alone are
  // sent again, into the same buffers.
  void updateGeometry(const Mesh& mesh);
  // Whether the mesh deforms: its rest pose is kept beside the drawn one (attributes 8 and 9 of
  // mesh.vert's PATTERN_REST variant), uploaded once.
  bool deforms() const { return restPositions_.id() != 0 || (shared_ && shared_->deforms()); }
  // The buffers a pose on the GPU reads and writes (animation/gpu_deformation.h); ids 0 where
  // there are none (a mesh that does not deform has no rest streams; directions before the field).
  struct PoseStreams {
    GLuint restPositions = 0, restNormals = 0, positions = 0, normals = 0, directions = 0;
    std::size_t vertices = 0;
  };
  PoseStreams poseStreams() const { return {restPositions_.id(), restNormals_.id(), positions_.id(), normals_.id(), directions_.id(), vertexCount_}; }
  // The hatching direction field, one vector per vertex (attribute 6; orientation/
  // direction_field.h). Without it the attribute reads zero: no direction.
  void uploadDirections(const std::vector<glm::vec3>& directions);
  // Baked ambient occlusion, one value per vertex (attribute 7; shadows/occlusion_bake.h).
  void uploadOcclusion(const std::vector<float>& occlusion);
  bool hasOcclusion() const { return occlusion_.id() != 0 || (shared_ && shared_->hasOcclusion()); }
  // Every vertex as a point (the occlusion bake addresses vertices by gl_VertexID).
  void drawPoints() const;

  // Binds the vertex array with the mesh's own indices and draws every triangle.
  void drawAll() const;
  // With an appearance, the mesh's triangles are uploaded grouped by material (in their order
  // within each), so the GPU-lit paths can draw each material with its own uniforms and
  // program: these are the groups (one, of material 0, for vertex colours alone); else none.
  const std::vector<MaterialRun>& materialRuns() const { return runs_; }
  // Binds the vertex array with the mesh's own indices and draws one run.
  void drawRun(const MaterialRun& run) const;
  // Binds the vertex array with `indices` (3 per triangle, over this mesh's vertices).
  void bindIndices(const gl::Buffer& indices) const;
  // Draws `count` triangles from triangle `first` of the bound index buffer.
  void drawTriangles(std::uint32_t first, std::uint32_t count) const;

 private:
  gl::VertexArray vao_;
  void uploadAppearance(const Mesh& mesh);  // the appearance's streams (attributes 2-5)
  void uploadIndices(const Mesh& mesh);     // the index buffer, grouped by material with an appearance
  // Points the vertex array at `source`'s streams (this mesh's own, or a part's model's).
  void bindStreams(const GpuMesh& source);
  gl::Buffer positions_, normals_, indices_, colours_, texcoords_, materials_, mapAverages_, directions_, occlusion_;
  gl::Buffer restPositions_, restNormals_;
  std::vector<MaterialRun> runs_;
  const GpuMesh* shared_ = nullptr;  // a part's: whose vertex streams it draws through
  std::size_t vertexCount_ = 0;
  std::size_t triangleCount_ = 0;
};

// mesh.vert's transform uniforms. The mesh is already centred and scaled, so the modelview is
// the camera's view.
void setMeshTransform(gl::ShaderProgram& program, const CameraMatrices& camera);

}  // namespace npr
