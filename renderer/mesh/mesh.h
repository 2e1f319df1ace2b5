// The mesh as the renderer sees it: flat arrays ready for the GPU and for per-triangle
// lighting, and the load report. OpenMesh's halfedge structure is built while loading (it
// decides which faces must be drawn on copied vertices, mesh_builder.h) and by the feature
// lines on a welded copy, but not kept: nothing draws from it, it held a third of a large
// mesh's memory, and without it a Mesh is plain arrays that move cheaply and cache to disk.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <glm/glm.hpp>
#include <glm/gtc/type_precision.hpp>

#include "renderer/core/image.h"

namespace npr {

using TriMesh = OpenMesh::TriMesh_ArrayKernelT<>;

struct LoadReport {
  std::string file;
  std::size_t vertices = 0;
  std::size_t triangles = 0;              // every triangle that will be drawn
  std::size_t polygons_triangulated = 0;  // faces with more than 3 corners
  std::size_t skipped_faces = 0;          // faces that could not be drawn at all
  std::size_t repeated_corner_faces = 0;  // faces that named a vertex twice in a row; drawn without the repeat
  std::size_t degenerate_triangles = 0;   // triangles (of faces or their triangulation) naming one vertex twice: not drawn
  std::size_t non_manifold_faces = 0;     // refused by the halfedge structure, drawn on copied vertices
  std::vector<std::string> warnings;
  // Materials (OBJ's .mtl): the libraries read, the materials defined and used, and texture
  // maps found and missing (each names the file and line).
  std::vector<std::string> material_libraries;
  std::size_t materials = 0;
  std::vector<std::string> textures_loaded;
  std::vector<std::string> textures_missing;
  bool vertex_colours = false;
  bool texture_coordinates = false;
  double load_ms = 0.0;
  bool from_cache = false;          // read from the mesh cache (mesh_cache.h), not parsed
  glm::dvec3 original_centre{0.0};  // the model was translated by -centre ...
  double original_scale = 1.0;      // ... then scaled by this to fit a unit sphere
  std::string toJson() const;
};

// A surface material as a .mtl file describes it, mapped to OpenGL's material (Materialfv):
// Ka, Kd, Ks, Ke become the four colours, Ns (Phong exponent, 0..1000) the shininess clamped
// to GL's 0..128, and illum 0 and 1 turn the specular term off (illum 0 also the lighting:
// the diffuse colour is emitted), as does an Ns below 1 (GL would light the whole side white).
struct MeshMaterial {
  std::string name;
  glm::vec3 ambient{0.2f}, diffuse{0.8f}, specular{0.0f}, emission{0.0f};
  float shininess = 0.0f;
  float opacity = 1.0f;  // d (or 1 - Tr), glTF's base colour alpha: see `alpha`
  int illum = 2;
  // glTF's alpha mode. The surface's alpha is opacity times the diffuse map's alpha. Mask:
  // drawn only where it reaches alphaCutoff (a cut-out). Blend: screen-door transparency,
  // drawn at that share of each 4x4 block of pixels, in no order (gpu_materials.h says why).
  enum class Alpha : std::uint8_t { Opaque, Mask, Blend } alpha = Alpha::Opaque;
  float alphaCutoff = 0.5f;
  int diffuseMap = -1;   // into Mesh::textures; modulates ambient and diffuse (map_Kd)
  int opacityMap = -1;   // map_d, until the OBJ reader folds it into diffuseMap's alpha (opacity_map.h)
  bool fromLightingState = false;  // the default material: taken from the lighting state at draw time
};

// A model's texture budget, whatever its files declare (OBJ/MTL and glTF alike): distinct maps,
// each reduced while it is read to at most this a side (the GPU array holds them at up to 1024
// anyway): 64 x 4 MB at most.
inline constexpr std::size_t kMaxModelTextures = 64;
inline constexpr int kMaxModelTextureSide = 1024;

struct MeshTexture {
  std::string path;
  ImageRGBA8 image;  // as stored (no colour conversion, as fixed-function GL sampled)
};

// How a mesh deforms (glTF skins and morph targets), per vertex of the mesh; empty when it does
// not. The deformed copy is made by animation/deformation.h.
struct MeshDeformation {
  std::vector<glm::u16vec4> joints;  // into the object's skin's joints (SceneSkin)
  std::vector<glm::vec4> weights;    // non-negative, summing to 1; all zero: the vertex stays at rest
  // Per morph target: position deltas (in the mesh's centred and scaled space) and normal deltas.
  std::vector<std::vector<glm::vec3>> targetPositions, targetNormals;
  bool skinned() const { return !joints.empty(); }
  std::size_t targets() const { return targetPositions.size(); }
  bool empty() const { return !skinned() && targetPositions.empty(); }
};

struct Mesh {
  // Structure of arrays, for upload and for cache-friendly per-triangle work.
  std::vector<glm::vec3> positions;       // per vertex, centred and scaled
  std::vector<glm::vec3> normals;         // per vertex, unit length (never NaN)
  std::vector<std::uint32_t> indices;     // 3 per triangle, counter-clockwise
  std::vector<glm::vec3> faceCentroids;   // per triangle
  std::vector<glm::vec3> faceNormals;     // per triangle; zero for zero-area triangles
  float radius = 1.0f;                    // bounding sphere radius about the origin
  // Every edge joins exactly two triangles wound in opposite directions, and they enclose a
  // positive volume: seen from outside, every back face lies behind a front face
  // (closedSurface below; finalizeMesh fills it).
  bool closed = false;
  // Appearance from the file, all optional (empty when the file has none). Vertices are split
  // where a file vertex has two texture coordinates or borders two materials, so every
  // attribute is per vertex; split vertices share their normal (sourceVertex).
  std::vector<MeshMaterial> materials;
  std::vector<MeshTexture> textures;
  std::vector<std::uint16_t> faceMaterials;  // per triangle, into materials
  std::vector<glm::vec3> colours;            // per vertex, as `v x y z r g b` gives them
  std::vector<glm::vec2> texcoords;          // per vertex
  std::vector<std::uint32_t> sourceVertex;   // per vertex: the vertex it was split from (normals are shared)
  // Per triangle: its diffuse map averaged over the triangle (white without one), what the
  // per-triangle paths modulate ambient and diffuse by, and averaged around each vertex the
  // per-vertex paths (finalizeMesh fills it; empty when no material has a map).
  std::vector<glm::vec3> faceTints;
  // Whether some material leaves part of the surface undrawn (its alpha mode, opacity and map's
  // alpha: cut-outs and screen-door transparency, mesh.frag's ALPHA_COVERAGE); finalizeMesh
  // fills it. Such a mesh is never treated as closed when culling.
  bool seeThrough = false;
  MeshDeformation deformation;
  // What the file draws besides faces (glTF POINTS and LINES primitives), in the mesh's space:
  // dots, and segments (two ends each) drawn as strokes of the line style (lines/line_pass.h).
  std::vector<glm::vec3> dots, segments;
  LoadReport report;

  std::size_t triangleCount() const { return indices.size() / 3; }
  // Whether the file gave anything beyond the shape (what `--materials on` draws).
  bool hasAppearance() const { return !materials.empty() || !colours.empty(); }
  bool hasMarks() const { return !dots.empty() || !segments.empty(); }

};

// Fills the radius, centroids and normals from `positions` and `indices` (used by the loader
// and by meshes built in code, e.g. the benchmark's generated icosphere).
void finalizeMesh(Mesh& m);
// Whether the triangles `indices` (vertex `slot`s: split vertices welded) form a closed,
// consistently wound surface enclosing positive volume (Mesh::closed).
bool closedSurface(const std::vector<glm::vec3>& positions, const std::vector<std::uint32_t>& indices,
                   const std::vector<std::uint32_t>& sourceVertex);
// faceCentroids and faceNormals from the positions again (a deformed mesh), in parallel;
// zero-area faces get a zero normal, as finalizeMesh gives them.
void updateFaceGeometry(Mesh& m);
// faceTints from the texture maps (part of finalizeMesh; empty when no material has a map).
void computeFaceTints(Mesh& m);
// Mesh::seeThrough from the materials and their maps' alpha (part of finalizeMesh).
bool seeThrough(const Mesh& m);

}  // namespace npr
